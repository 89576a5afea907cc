"""Catena from Python: the library's analyses, case files, reports and sweeps.

Values are given as on the command line: a string with a unit ("40 mm", "29.4kN"), or a number in
the parameter's bare unit (``catena.analyses()`` lists it). See docs/python.md.
"""

from __future__ import annotations

import functools
import numbers
import os
from typing import Any, Iterable, Mapping, Sequence

from . import _core

__version__ = _core.__version__

__all__ = [
    "InputError",
    "Result",
    "Case",
    "analyses",
    "run",
    "run_case",
    "report",
    "sweep",
    "sweep_chunk",
    "sweep_points",
]


class InputError(ValueError):
    """Invalid input. ``str(error)`` lists every problem, one a line; ``error.issues`` holds them
    as dicts with ``field`` (the parameter key, or the case file's path), ``value`` and
    ``expected``."""

    def __init__(self, issues: Sequence[Mapping[str, str]], message: str | None = None):
        self.issues = [dict(i) for i in issues]
        for i in self.issues:
            i.setdefault("text", f"{i['field']} = {i['value']}: expected {i['expected']}")
        if message is None:
            message = _listing(self.issues)
        super().__init__(message)


def _listing(issues: Sequence[Mapping[str, str]]) -> str:
    lines = [i["text"] for i in issues]
    head = "invalid input:" if len(lines) == 1 else f"invalid input ({len(lines)} problems):"
    return head + "\n  " + "\n  ".join(lines)


def _issues_from(raw) -> list[dict]:
    return [{"field": f, "value": v, "expected": e, "text": t} for (f, v, e, t) in raw]


def _reraise(error: Exception) -> None:
    issues = getattr(error, "issues", None)
    if issues is None:
        raise error
    raise InputError(_issues_from(issues), str(error)) from None


def analyses() -> list[dict]:
    """Every analysis with its parameter table, in registry order.

    Each is a dict: name, command, title, help, seed, docs, chain_types, example (the doc of its
    ``example`` flag, or None) and parameters; each parameter: name, type (quantity, number,
    integer, choice, flag, text, table), kind (what a quantity measures), unit (of a bare number),
    required, default, list (a comma list or Python list allowed), choices, example, doc, fields
    (of a table parameter).
    """
    return _core.analyses()


@functools.lru_cache(maxsize=None)
def _tables() -> dict:
    """name → analysis, read once (the registry does not change while the process runs)."""
    return {a["name"]: a for a in _core.analyses()}


def _analysis(name: str) -> dict:
    a = _tables().get(name)
    if a is not None:
        return a
    names = ", ".join(_tables())
    raise InputError([{"field": "analysis", "value": str(name),
                       "expected": f"an analysis Catena has: {names}"}])


def _text(value: Any) -> str:
    """One value as the command line would take it."""
    if isinstance(value, str):
        return value
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, numbers.Integral):
        return str(int(value))
    if isinstance(value, numbers.Real):
        return repr(float(value))  # the shortest text that reads back exactly
    if isinstance(value, os.PathLike):
        return os.fspath(value)
    return str(value)


def _is_list(value: Any) -> bool:
    if isinstance(value, (str, bytes, os.PathLike)):
        return False
    if hasattr(value, "tolist") and getattr(value, "ndim", 1) == 0:
        return False  # a NumPy scalar
    return isinstance(value, Iterable)


def _texts(analysis: dict, values: Mapping[str, Any]) -> tuple[list[tuple[str, str]], list[dict]]:
    """(key, text) pairs for the library, and the problems only Python can see (a list where a
    single value is required)."""
    params = analysis.setdefault("_by_key", {p["name"]: p for p in analysis["parameters"]})
    texts: list[tuple[str, str]] = []
    issues: list[dict] = []
    for key, value in values.items():
        p = params.get(key)
        if value is None:
            continue  # absent, as an omitted flag
        if _is_list(value):
            parts = [_text(v) for v in value]
            if p is not None and not p["list"]:
                issues.append({"field": key, "value": "[" + ", ".join(parts) + "]",
                               "expected": "one value (" + key + " takes no list)"})
                continue
            texts.append((key, ",".join(parts)))
            continue
        if p is not None and p["type"] == "flag":
            if value is False or (isinstance(value, str) and value.lower() == "false"):
                continue
        texts.append((key, _text(value)))
    return texts, issues


class Result:
    """One analysis run.

    ``to_dict()`` is the JSON tree that ``catena <analysis> --format json`` prints (same names,
    same values, SI with its ``units`` object; a non-finite number is None as it is null there).
    ``series(path)`` gives an array of numbers of the tree as a NumPy array
    (``result.series("series.angle")``; ``None`` entries become NaN). ``units`` is the tree's
    units object, ``diagnostics`` its findings (dicts with severity, code, message, value, limit).
    """

    def __init__(self, core: Any):
        self._core = core
        self._dict: dict | None = None

    @property
    def name(self) -> str:
        return self._core.name

    @property
    def inputs(self) -> dict:
        """The values as given to the library (text)."""
        return dict(self._core.inputs)

    def to_dict(self) -> Any:
        if self._dict is None:
            self._dict = self._core.to_dict()
        return self._dict

    def to_json(self) -> str:
        """The JSON text, byte for byte what the command line prints."""
        return self._core.to_json()

    def __getitem__(self, key: str) -> Any:
        return self.to_dict()[key]

    @property
    def units(self) -> dict:
        d = self.to_dict()
        return dict(d.get("units", {})) if isinstance(d, dict) else {}

    @property
    def diagnostics(self) -> list[dict]:
        return self._core.diagnostics()

    @property
    def table(self) -> str:
        """The text table of ``--format table``."""
        return self._core.table()

    def series(self, path: str):
        """The list of numbers at the dotted ``path`` of the tree as a float64 NumPy array."""
        return self._core.series(path)

    def __repr__(self) -> str:
        return f"<catena.Result {self.name}>"


class Case:
    """A case file run. ``to_dict()`` is the tree ``catena run CASE`` prints; ``results`` maps
    each [analyses.<name>] table's name to its Result."""

    def __init__(self, core: Any):
        self._core = core
        self.results = {name: Result(r) for name, r in core.results()}

    @property
    def name(self) -> str:
        return self._core.name

    def to_dict(self) -> dict:
        return self._core.to_dict()

    def __repr__(self) -> str:
        return f"<catena.Case {self.name}: {', '.join(self.results)}>"


def run(name: str, **values: Any) -> Result:
    """Runs analysis ``name`` with ``values`` given as on the command line: strings with units or
    numbers in the bare unit; a list for a parameter that takes a comma list; True for a flag; a
    table parameter (``loop``) is the path of a TOML file holding it. Raises InputError listing
    every problem."""
    analysis = _analysis(name)
    texts, issues = _texts(analysis, values)
    if issues:
        refused = {i["field"] for i in issues}
        bound = [i for i in _issues_from(_core.bind_issues(name, texts))
                 if i["field"] not in refused]
        raise InputError(issues + bound)
    try:
        return Result(_core.run(name, texts))
    except _core._InputError as error:
        _reraise(error)
        raise  # not reached


def run_case(path: str | os.PathLike) -> Case:
    """Runs every analysis of a TOML case file (docs/case_files.md), as ``catena run`` does."""
    try:
        return Case(_core.run_case(os.fspath(path)))
    except _core._InputError as error:
        _reraise(error)
        raise


def report(case_or_results: Any, path: str | os.PathLike = "report.html",
           title: str = "Catena results") -> str:
    """Writes the self-contained HTML report: of a case file (a path, or a Case from run_case), as
    ``catena report`` does, or of Results (one or a list), one section each. Returns the path."""
    out = os.fspath(path)
    try:
        if isinstance(case_or_results, (str, os.PathLike)):
            _core.report_case(_core.run_case(os.fspath(case_or_results)), out)
        elif isinstance(case_or_results, Case):
            _core.report_case(case_or_results._core, out)
        else:
            results = [case_or_results] if isinstance(case_or_results, Result) \
                else list(case_or_results)
            if not results or not all(isinstance(r, Result) for r in results):
                raise TypeError("report() takes a case file's path, a Case, or Results")
            _core.report_results([r._core for r in results], out, title)
    except _core._InputError as error:
        _reraise(error)
    return out


from .sweep import sweep, sweep_chunk, sweep_points  # noqa: E402
