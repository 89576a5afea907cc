"""catena.sweep: the same frame, bit for bit, on 1, 2 and 8 threads, on a LocalCluster of two
worker processes, and when a worker is killed mid-sweep (Dask retries its chunk)."""

import functools
import os

import pandas as pd
import pytest

import catena
import chunk_runners

GRID = {"teeth": [6, 8, 10, 12], "pin_diameter": ["30mm", "40mm", "50mm"],
        "half_thickness": [6, 8, "10 mm"]}
BASE = {"plate_radius": "34mm", "strokes": 1, "tension": "29.4kN", "pitch": "125mm"}
POINTS = 4 * 3 * 3
CLUSTER_TIMEOUT = 60  # [s] the whole Dask sweep, start to gather


def same(a, b):
    pd.testing.assert_frame_equal(a, b, check_exact=True)


@pytest.fixture(scope="module")
def one_thread():
    return catena.sweep("hinge", grid=GRID, base=BASE, threads=1)


def test_one_row_per_point_in_grid_order(one_thread):
    assert len(one_thread) == POINTS
    points = catena.sweep_points(GRID, BASE)
    assert [p["teeth"] for p in points[:4]] == [6, 6, 6, 6]  # the first key varies slowest
    assert points[1]["half_thickness"] == 8 and points[0]["plate_radius"] == "34mm"
    single = catena.run("hinge", **points[5]).to_dict()
    row = one_thread.iloc[5]
    scalars = [k for k, v in single.items() if isinstance(v, (int, float)) and
               not isinstance(v, bool) and k in one_thread.columns]
    assert scalars, "the frame has the scalar results"
    for key in scalars:
        assert row[key] == single[key], key


@pytest.mark.parametrize("threads", [2, 8])
def test_threads_do_not_change_the_frame(one_thread, threads):
    same(catena.sweep("hinge", grid=GRID, base=BASE, threads=threads), one_thread)


def test_explicit_points_equal_the_grid(one_thread):
    points = catena.sweep_points(GRID)
    same(catena.sweep("hinge", points=points, base=BASE, threads=2), one_thread)


def test_a_bad_point_is_an_input_error():
    with pytest.raises(catena.InputError) as error:
        catena.sweep("hinge", grid={"teeth": [8, [9, 10]]}, base=BASE)
    assert "teeth" in str(error.value)


def cluster():
    from dask.distributed import LocalCluster
    return LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                        dashboard_address=None, silence_logs=40)


def test_local_cluster_of_two_processes(one_thread):
    from dask.distributed import Client
    with cluster() as c, Client(c, timeout=CLUSTER_TIMEOUT) as client:
        frame = catena.sweep("hinge", grid=GRID, base=BASE, threads=1, client=client,
                             chunk_size=5)
        pids = set(client.run(os.getpid).values())
    assert len(pids) == 2 and os.getpid() not in pids
    same(frame, one_thread)


def test_a_worker_killed_mid_sweep_still_yields_the_frame(one_thread, tmp_path):
    from dask.distributed import Client
    marker = tmp_path / "killed"
    runner = functools.partial(chunk_runners.kill_worker_on_first_attempt, str(marker))
    with cluster() as c, Client(c, timeout=CLUSTER_TIMEOUT) as client:
        before = set(client.run(os.getpid).values())
        frame = catena.sweep("hinge", grid=GRID, base=BASE, threads=2, client=client,
                             chunk_size=4, runner=runner)
        after = set(client.run(os.getpid).values())
    killed = int(marker.read_text())
    assert killed in before and killed not in after, "a worker process died and was replaced"
    same(frame, one_thread)


def test_the_hinge_study_example_draws_its_figure(tmp_path):
    import subprocess
    import sys
    from conftest import SOURCE
    out = tmp_path / "hinge_study.png"
    p = subprocess.run([sys.executable, str(SOURCE / "examples" / "python" / "hinge_study.py"),
                        str(out)], capture_output=True, text=True, timeout=120)
    assert p.returncode == 0, p.stderr
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
