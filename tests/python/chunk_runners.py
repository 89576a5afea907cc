"""Chunk functions for the Dask tests, importable on the workers (ctest puts tests/python on
PYTHONPATH)."""

import os
import signal

import pandas as pd

import catena


def per_point_rows(name, points, threads):
    """A chunk run point by point through catena.run (one row of the tree's scalars each): the
    Dask tests' runner that does not need the C++ sweep, so that chunking, ordered gathering and
    retries are tested on their own."""
    rows = []
    for point in points:
        tree = catena.run(name, **point).to_dict()
        rows.append({**{k: str(v) for k, v in point.items()},
                     **{k: v for k, v in tree.items()
                        if isinstance(v, (int, float)) and not isinstance(v, bool)}})
    return pd.DataFrame(rows)


def kill_worker_on_first_attempt(marker, runner, name, points, threads):
    """Runs the chunk with `runner`, except that the first chunk any worker starts kills
    its own worker process (SIGKILL: no cleanup, as a lost machine) while the other chunks are
    queued or running; `marker` is created first, so that Dask's retry runs the chunk normally."""
    if points:
        try:
            fd = os.open(marker, os.O_CREAT | os.O_EXCL | os.O_WRONLY)
        except FileExistsError:
            pass
        else:
            os.write(fd, str(os.getpid()).encode())
            os.close(fd)
            os.kill(os.getpid(), signal.SIGKILL)
    return runner(name, points, threads)
