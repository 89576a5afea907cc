"""A 10⁵-point hinge sweep from Python: on the library's thread pool (catena.sweep, threads 1
and 2), and through Dask with a LocalCluster of 2 worker processes of one thread each (each
chunk on its worker's pool with threads=1). Points per second, wall time from the call to the
frame; the cluster's start-up is not counted.

    PYTHONPATH=build/ci/python /usr/bin/python3 bench/python_sweep.py [points]

Results are in docs/performance.md. Not a test: nothing here passes or fails.
"""

import os
import sys
import time

import catena
import pandas  # noqa: F401  (imported before the clock starts)

BASE = {"pin_diameter": "40mm", "half_thickness": "8mm", "tension": "29.4kN",
        "allowable_shear": "120MPa", "allowable_contact": "1600MPa", "friction": 0.15}


def grid(points):
    teeth = list(range(6, 106))
    radii = [f"{8 + 0.01 * i:.2f}mm" for i in range(max(1, points // len(teeth)))]
    return {"teeth": teeth, "plate_radius": radii}


def timed(label, points, fn):
    start = time.perf_counter()
    frame = fn()
    wall = time.perf_counter() - start
    assert len(frame) == points and not frame["error"].any(), label
    print(f"{label:44s} {wall:7.2f} s  {points / wall / 1e3:7.1f} k points/s", flush=True)
    return frame


def main():
    points = int(sys.argv[1]) if len(sys.argv) > 1 else 100_000
    g = grid(points)
    points = len(g["teeth"]) * len(g["plate_radius"])
    print(f"{points} hinge points; load average {os.getloadavg()[0]:.2f}")
    one = timed("catena.sweep, pool of 1 thread", points,
                lambda: catena.sweep("hinge", grid=g, base=BASE, threads=1))
    two = timed("catena.sweep, pool of 2 threads", points,
                lambda: catena.sweep("hinge", grid=g, base=BASE, threads=2))
    from dask.distributed import Client, LocalCluster
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None, silence_logs=40) as cluster, Client(cluster) as client:
        # a long-lived cluster's workers have imported catena and pandas already: so do these
        client.run(lambda: (__import__("pandas"), __import__("catena").analyses()))
        dask = timed("catena.sweep, Dask: 2 workers x 1 thread", points,
                     lambda: catena.sweep("hinge", grid=g, base=BASE, threads=1, client=client))
    for frame in (two, dask):
        assert frame.equals(one), "the frames differ"
    print("frames identical (1 thread, 2 threads, Dask)")


if __name__ == "__main__":
    main()
