"""Sweeps: one analysis over a grid (Cartesian product of lists) or an explicit list of parameter
sets, run by the library's thread pool; with a ``dask.distributed.Client``, the points are split
into chunks, each chunk runs on a worker through that worker's thread pool, and the chunks'
frames are gathered in input order. Dask schedules, moves the data and retries a chunk whose
worker was lost; nothing here does any of that itself. See docs/python.md.
"""

from __future__ import annotations

import itertools
from typing import Any, Callable, Mapping, Sequence

from . import _core


def sweep_points(grid: Mapping[str, Sequence[Any]] | None = None,
                 base: Mapping[str, Any] | None = None,
                 points: Sequence[Mapping[str, Any]] | None = None) -> list[dict]:
    """The parameter sets of a sweep, in its order: ``points`` as given, or the Cartesian product
    of ``grid``'s lists with the first key varying slowest (the last fastest); each over
    ``base``."""
    base = dict(base or {})
    if points is not None and grid:
        raise ValueError("sweep: give grid or points, not both")
    if points is not None:
        return [{**base, **dict(p)} for p in points]
    grid = dict(grid or {})
    keys = list(grid)
    for key in keys:
        if isinstance(grid[key], (str, bytes)) or not hasattr(grid[key], "__iter__"):
            raise ValueError(f"sweep: grid[{key!r}] must be a list of values")
    return [{**base, **dict(zip(keys, combo))}
            for combo in itertools.product(*(list(grid[k]) for k in keys))]


def _frame(points: Sequence[Mapping[str, Any]], columns: Sequence[str], units: Sequence[str],
           rows: Sequence[Sequence[Any]]):
    """The chunk's frame: the points' inputs as given (every key any point has, in order of first
    appearance), then the C++ table's columns. A result named like an input gets the prefix
    ``result.``; ``frame.attrs["units"]`` maps each result column to its SI unit."""
    import pandas as pd
    keys: list[str] = []
    for point in points:
        keys += [k for k in point if k not in keys]
    names = [f"result.{c}" if c in keys else c for c in columns]
    frame = pd.DataFrame(list(rows), columns=names)
    for i, key in enumerate(keys):
        frame.insert(i, key, pd.Series([p.get(key) for p in points], dtype=object))
    frame.attrs["units"] = {n: u for n, u in zip(names, units) if u}
    return frame


def sweep_chunk(name: str, points: Sequence[Mapping[str, Any]], threads: int = 0):
    """Runs ``points`` (parameter sets, values as for catena.run) of analysis ``name`` on the
    library's thread pool (``threads`` = 0: all cores) and returns their rows as a DataFrame, in
    the order of ``points``. This is what each Dask task runs."""
    from . import InputError, _issues_from
    sets = _point_texts(name, points)
    try:
        columns, units, rows = _core.sweep(name, sets, int(threads))
    except _core._InputError as error:
        raise InputError(_issues_from(error.issues), str(error)) from None
    return _frame(points, columns, units, rows)


def _point_texts(name: str, points: Sequence[Mapping[str, Any]]) -> list:
    """Each point's (key, text) pairs for the library; raises InputError with every problem only
    Python can see (a list where one value is required), named by point."""
    from . import InputError, _analysis, _texts
    analysis = _analysis(name)
    sets = []
    issues = []
    known: dict = {}  # (key, type, value) → _texts of that one value: grids repeat their values
    for i, point in enumerate(points):
        texts = []
        for key, value in point.items():
            try:
                memo = (key, type(value), value)
                converted = known.get(memo)
            except TypeError:  # unhashable (a list): converted every time
                memo, converted = None, None
            if converted is None:
                converted = _texts(analysis, {key: value})
                if memo is not None:
                    known[memo] = converted
            texts += converted[0]
            for issue in converted[1]:
                issue = dict(issue)
                issue["field"] = f"point {i}: {issue['field']}"
                issues.append(issue)
        sets.append(texts)
    if issues:
        raise InputError(issues)
    return sets


def sweep(name: str, grid: Mapping[str, Sequence[Any]] | None = None,
          base: Mapping[str, Any] | None = None,
          points: Sequence[Mapping[str, Any]] | None = None, threads: int = 0,
          client: Any = None, chunk_size: int | None = None,
          runner: Callable[..., Any] | None = None):
    """Runs analysis ``name`` over a grid or a list of points; returns a pandas DataFrame with one
    row per point, in input order: the inputs, then the scalar results, then the worst
    diagnostic (the columns of ``catena sweep``).

    ``threads``: the thread pool's size on this machine, or on each Dask worker (0: all cores).
    ``client``: a ``dask.distributed.Client``; the points go out in chunks of ``chunk_size``
    (default: about four chunks per worker), one Dask task each, gathered in order.
    ``runner``: the function each task calls, ``runner(name, points, threads)`` → DataFrame;
    default ``sweep_chunk`` (a wrapper can log or inspect a chunk).
    """
    sets = sweep_points(grid, base, points)
    run_chunk = runner or sweep_chunk
    if client is None:
        return run_chunk(name, sets, threads)
    import pandas as pd
    # the whole sweep's problems (keys, a table's file, the total work of a dynamics sweep) before
    # any chunk goes out: each chunk checks only its own points
    from . import InputError, _issues_from
    try:
        _core.check_sweep(name, _point_texts(name, sets))
    except _core._InputError as error:
        raise InputError(_issues_from(error.issues), str(error)) from None
    if chunk_size is None:
        workers = max(1, len(client.scheduler_info().get("workers", {})))
        chunk_size = max(1, -(-len(sets) // (4 * workers)))
    chunks = [sets[i:i + chunk_size] for i in range(0, len(sets), chunk_size)] or [[]]
    # pure=False: every chunk is its own task even when two chunks are equal
    futures = [client.submit(run_chunk, name, chunk, threads, pure=False) for chunk in chunks]
    frames = client.gather(futures)
    return pd.concat(frames, ignore_index=True)
