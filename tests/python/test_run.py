"""catena.run / run_case / report against the built program: identical JSON for every example
case and every documented example; values as on the command line; every problem listed."""

import json
import math

import numpy as np
import pytest

import catena
from conftest import SOURCE, cli_json, run_cli
from doc_examples import documented_examples

EXAMPLES = sorted((SOURCE / "examples").glob("*.toml"))


def without_timing(value):
    """The record without what a run measures of itself (dynamics' summary.wall_time and the
    real_time_factor it implies), which no two runs share."""
    if isinstance(value, dict):
        return {k: without_timing(v) for k, v in value.items()
                if not (k in ("wall_time", "real_time_factor") and "energy_drift" in value)}
    if isinstance(value, list):
        return [without_timing(v) for v in value]
    return value


def key_of(analysis, flag):
    """The parameter key of a command-line flag (or of one of its aliases)."""
    name = flag[2:].replace("-", "_")
    for p in analysis["parameters"]:
        if p["name"] == name or name in p["aliases"]:
            return p["name"]
    raise KeyError(flag)


def documented():
    analyses = catena.analyses()
    cases = list(documented_examples(analyses))
    by_name = {a["name"]: a for a in analyses}
    # "catena hinge sweep <the same flags>": the hinge's documented flags
    # but the plate radius, which the sweep varies
    hinge = next(flags for a, flags in cases if a["name"] == "hinge")
    cases.append((by_name["hinge_sweep"], [(f, v) for f, v in hinge if f != "--plate-radius"]))
    # "catena loop FILE": the example case holds a [loop] table
    cases.append((by_name["loop"], [("FILE", str(SOURCE / "examples" / "000_loop.toml"))]))
    # "catena dynamics FILE": the example case holds a [dynamics] table
    cases.append((by_name["dynamics"],
                  [("FILE", str(SOURCE / "examples" / "dynamics_12B.toml"))]))
    return cases


DOCUMENTED = documented()


def test_every_analysis_has_a_documented_example():
    assert {a["name"] for a, _ in DOCUMENTED} == {a["name"] for a in catena.analyses()}


@pytest.mark.parametrize("path", EXAMPLES, ids=[p.stem for p in EXAMPLES])
def test_example_case_equals_cli(cli, path):
    expected = cli_json(cli, "run", str(path))
    assert without_timing(catena.run_case(str(path)).to_dict()) == without_timing(expected)


@pytest.mark.parametrize("analysis,flags", DOCUMENTED,
                         ids=[f"{a['name']}-{i}" for i, (a, _) in enumerate(DOCUMENTED)])
def test_documented_example_equals_cli(cli, analysis, flags):
    args = list(analysis["command"])
    values = {}
    for flag, value in flags:
        if flag == "FILE":
            args.append(value)
            values[next(p["name"] for p in analysis["parameters"] if p["type"] == "table")] = value
            continue
        args += [flag] if value is None else [flag, value]
        values[key_of(analysis, flag)] = True if value is None else value
    expected = cli_json(cli, *args, "--format", "json")
    result = catena.run(analysis["name"], **values)
    assert without_timing(result.to_dict()) == without_timing(expected)
    if analysis["name"] == "dynamics":
        return  # its wall time differs from run to run: no byte-for-byte comparison
    # byte for byte, too
    assert result.to_json() == run_cli(cli, *args, "--format", "json")[1]


def test_bare_numbers_take_the_parameters_bare_unit():
    with_units = catena.run("hinge", pin_diameter="40 mm", half_thickness="8mm",
                            plate_radius="0.034 m", teeth=8, strokes=1, tension="29.4kN")
    bare = catena.run("hinge", pin_diameter=40, half_thickness=8.0, plate_radius=34,
                      teeth=np.int64(8), strokes=1, tension=29400)
    assert bare.to_dict() == with_units.to_dict()
    units = {p["name"]: p["unit"] for p in
             next(a for a in catena.analyses() if a["name"] == "hinge")["parameters"]}
    assert units["pin_diameter"] == "mm" and units["tension"] == "N"


def test_a_python_list_is_the_comma_list(cli):
    args = dict(heights="0,10mm,50mm,60mm", stiffness="2e8", widths="8mm", pin_diameter="24mm",
                load_height="30mm")
    comma = catena.run("warp", force="30kN,35kN,40kN", **args)
    listed = catena.run("warp", force=["30kN", "35kN", 40000.0], **args)
    assert listed.to_dict() == comma.to_dict()


def test_a_list_where_one_value_is_required_is_refused():
    with pytest.raises(catena.InputError) as error:
        catena.run("hinge", pin_diameter=[40, 50], half_thickness=8, plate_radius=34, teeth=8,
                   strokes=1)
    assert [i["field"] for i in error.value.issues] == ["pin_diameter"]
    assert "pin_diameter" in str(error.value)
    assert isinstance(error.value, ValueError)


def test_bad_input_lists_every_problem_as_the_cli_does(cli):
    status, _, err = run_cli(cli, "hinge", "--pin-diameter", "40kg", "--half-thickness", "8mm",
                             "--teeth", "2", "--strokes", "1", "--format", "json")
    assert status == 2
    cli_lines = [line.strip() for line in err.splitlines()[1:]]
    with pytest.raises(catena.InputError) as error:
        catena.run("hinge", pin_diameter="40kg", half_thickness="8mm", teeth=2, strokes=1)
    fields = [i["field"] for i in error.value.issues]
    assert {"pin_diameter", "plate_radius", "teeth"} <= set(fields)
    # the same problems in the same order, named by key instead of by flag
    assert len(fields) == len(cli_lines)
    for issue, line in zip(error.value.issues, cli_lines):
        flag = "--" + issue["field"].replace("_", "-")
        assert line == f"{flag} = {issue['value']}: expected {issue['expected']}"
    assert str(error.value).count("\n") == len(fields)


def test_a_mixed_list_problem_and_binding_problems_come_together():
    with pytest.raises(catena.InputError) as error:
        catena.run("hinge", pin_diameter="40 kg", teeth=[8, 9], half_thickness=8, strokes=1)
    fields = [i["field"] for i in error.value.issues]
    assert fields.count("teeth") == 1 and "pin_diameter" in fields and "plate_radius" in fields


def test_unknown_analysis_and_key_are_input_errors():
    with pytest.raises(catena.InputError):
        catena.run("hinje", teeth=8)
    with pytest.raises(catena.InputError) as error:
        catena.run("hinge", pin_diameter=40, half_thickness=8, plate_radius=34, teeth=8, strokes=1,
                   teeht=8)
    assert "teeht" in str(error.value)


def test_series_are_numpy_arrays_of_the_tree():
    r = catena.run("pocketwheel", example=True, guide="tangential")
    vx = r.series("series.vx")
    assert isinstance(vx, np.ndarray) and vx.dtype == np.float64
    assert vx.tolist() == r.to_dict()["series"]["vx"]
    assert r.units and all(isinstance(u, str) for u in r.units.values())
    with pytest.raises(KeyError):
        r.series("series.nothing")


def test_diagnostics_are_listed():
    case = catena.run_case(SOURCE / "examples" / "000_thesis_rolling_hinge.toml")
    r = case.results["hinge"]
    assert r.diagnostics, "the thesis hinge's contact leaves the face: a finding"
    d = r.diagnostics[0]
    assert set(d) == {"severity", "code", "message", "value", "limit"}
    assert [x["code"] for x in r.diagnostics] == [x["code"] for x in r["diagnostics"]]
    assert d["code"] in json.dumps(case.to_dict()["analyses"]["hinge"])


def test_analyses_list_the_parameter_tables():
    names = [a["name"] for a in catena.analyses()]
    assert names[:3] == ["pocketwheel", "hinge", "hinge_sweep"]
    hinge = next(a for a in catena.analyses() if a["name"] == "hinge")
    teeth = next(p for p in hinge["parameters"] if p["name"] == "teeth")
    assert teeth["type"] == "integer" and teeth["required"] and not teeth["list"]
    assert hinge["docs"] == "docs/models/hinge.md" and hinge["seed"]


def test_reports(tmp_path):
    case = SOURCE / "examples" / "003_pocket_wheel.toml"
    out = catena.report(str(case), tmp_path / "case.html")
    html = (tmp_path / "case.html").read_text()
    assert out.endswith("case.html") and "pocketwheel-chordal" in html and "Plotly" in html
    catena.report(catena.run_case(case), tmp_path / "again.html")
    assert "pocketwheel-chordal" in (tmp_path / "again.html").read_text()
    r = catena.run("pocketwheel", example=True, guide="chordal")
    catena.report([r], tmp_path / "results.html", title="Study")
    text = (tmp_path / "results.html").read_text()
    assert "Study" in text and "pocketwheel.guide" in text


def test_a_bad_case_file_lists_every_problem(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text('[chain]\ntype = "rolling-hinge"\n[analyses.hinge]\npin_diameter = "40 kg"\n'
                   'teeht = 8\n')
    with pytest.raises(catena.InputError) as error:
        catena.run_case(bad)
    fields = " ".join(i["field"] for i in error.value.issues)
    assert "analyses.hinge.pin_diameter" in fields and "analyses.hinge.teeht" in fields


def test_non_finite_values_are_none_as_json_null():
    d = catena.run("pocketwheel", example=True, guide="none").to_dict()
    assert d["guide_end"] is None
    assert not any(isinstance(x, float) and not math.isfinite(x) for x in d["series"]["vx"])


def test_concurrent_runs_from_python_threads_give_the_serial_results():
    # the GIL is released while a model runs: calls from several threads run in the library
    # at once and must not disturb each other
    from concurrent.futures import ThreadPoolExecutor
    kw = [dict(pin_diameter=d, half_thickness=8, plate_radius=34, teeth=z, strokes=1)
          for d in (30, 40, 50) for z in (6, 8, 10, 12)]
    serial = [catena.run("hinge", **k).to_dict() for k in kw]
    with ThreadPoolExecutor(4) as pool:
        threaded = list(pool.map(lambda k: catena.run("hinge", **k).to_dict(), kw * 4))
    assert threaded == serial * 4


# The thesis ring of issue 18 by the finite-difference sweep with 10x its node cap: 25 s of work.
LONG_RING = dict(inner_radius=4.72, outer_radius=10, thickness=1, E_r="10GPa", E_phi="40GPa",
                 G="4GPa", nu_phi_r=0.28, gap=0.02, method="sweep", nodes=200000,
                 allow_large=True)


@pytest.mark.parametrize("call", [
    lambda: catena.run("ring", **LONG_RING),
    lambda: catena.sweep("ring", grid={"gap": [0.02, 0.021, 0.022]}, base=LONG_RING, threads=2),
], ids=["run", "sweep"])
def test_ctrl_c_stops_a_long_run_with_keyboard_interrupt(call):
    """Ctrl-C (simulated: _thread.interrupt_main raises SIGINT's handler in the main thread)
    stops the C++ run at its next poll: KeyboardInterrupt soon, no result."""
    import _thread
    import threading
    import time

    sent = []

    def interrupt():
        sent.append(time.monotonic())
        _thread.interrupt_main()

    timer = threading.Timer(0.3, interrupt)
    timer.start()
    result = None
    with pytest.raises(KeyboardInterrupt):
        result = call()
    stopped = time.monotonic()
    timer.join()
    assert result is None
    # stopped at a poll soon after the Ctrl-C, not after the 25 s of work
    assert len(sent) == 1 and stopped - sent[0] < 1.5
    # the module still runs afterwards
    assert catena.run("ring", **{**LONG_RING, "nodes": 2000}).to_dict()["load"] > 0
