"""What a call through Python costs on top of the C++ call: catena.run("hinge", ...) against
BM_AnalysisHingeByName (bench/analysis_bench.cpp, the same inputs through catena::run).

    PYTHONPATH=build/release/python /usr/bin/python3 bench/python_overhead.py
    build/release/bench/analysis_bench --benchmark_filter=BM_AnalysisHingeByName

Prints the best of five repeats of each measurement in microseconds per call. Results are in
docs/performance.md. Not a test: nothing here passes or fails.
"""

import sys
import timeit

import catena

HINGE = dict(pin_diameter="40 mm", half_thickness="8 mm", teeth="8", plate_radius="34 mm",
             pitch="125 mm")
HINGE_NUMBERS = dict(pin_diameter=40, half_thickness=8, teeth=8, plate_radius=34, pitch=125)
TEXTS = list(HINGE.items())


def best(stmt, number):
    return min(timeit.repeat(stmt, number=number, repeat=5)) / number * 1e6


def main():
    number = int(sys.argv[1]) if len(sys.argv) > 1 else 2000
    rows = [
        ("_core.run (binding only: text pairs in, Record held)",
         best(lambda: catena._core.run("hinge", TEXTS), number)),
        ("catena.run, strings with units",
         best(lambda: catena.run("hinge", **HINGE), number)),
        ("catena.run, bare numbers",
         best(lambda: catena.run("hinge", **HINGE_NUMBERS), number)),
        ("catena.run(...).to_dict()",
         best(lambda: catena.run("hinge", **HINGE).to_dict(), number)),
        ("catena.analyses()", best(catena.analyses, number)),
    ]
    for name, us in rows:
        print(f"{us:9.2f} us  {name}")


if __name__ == "__main__":
    main()
