"""Chunk functions for the Dask tests, importable on the workers (ctest puts tests/python on
PYTHONPATH)."""

import os
import signal

import catena


def kill_worker_on_first_attempt(marker, name, points, threads):
    """Runs the chunk (catena.sweep_chunk), except that the first chunk any worker starts kills
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
    return catena.sweep_chunk(name, points, threads)
