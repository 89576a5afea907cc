"""A hinge design study: the rolling-friction hinge of seed 000 swept over the number of sprocket
teeth and the pin diameter; the pitch change over the engagement and the pin's shear stress
drawn against the teeth, one curve per pin diameter.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/python/hinge_study.py [out.png]

Add `--dask tcp://host:8786` to run the sweep on a Dask cluster (docs/python.md).
"""

import argparse

import matplotlib

matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt  # noqa: E402

import catena  # noqa: E402

GRID = {"pin_diameter": ["30mm", "40mm", "50mm"], "teeth": list(range(6, 21))}
BASE = {"half_thickness": "8mm", "plate_radius": "34mm", "strokes": 1, "pitch": "125mm",
        "tension": "29.4kN", "allowable_shear": "100MPa"}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("output", nargs="?", default="hinge_study.png")
    parser.add_argument("--dask", help="a Dask scheduler's address (tcp://host:8786)")
    args = parser.parse_args()

    client = None
    if args.dask:
        from dask.distributed import Client
        client = Client(args.dask)
    frame = catena.sweep("hinge", grid=GRID, base=BASE, client=client)

    fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4), constrained_layout=True)
    for pin, rows in frame.groupby("pin_diameter", sort=False):
        left.plot(rows["teeth"], rows["max_pitch_change"] * 1e3, marker="o", label=f"pin {pin}")
        right.plot(rows["teeth"], rows["shear_stress"] / 1e6, marker="o", label=f"pin {pin}")
    left.set(xlabel="teeth z", ylabel="largest pitch change Δt [mm]",
             title="Pitch change over the engagement")
    right.set(xlabel="teeth z", ylabel="pin shear stress τ [MPa]",
              title="Pin shear at 29.4 kN")
    right.axhline(100, color="grey", linestyle="--", linewidth=1, label="allowable")
    for ax in (left, right):
        ax.grid(True, alpha=0.3)
        ax.legend()
    fig.suptitle(f"Rolling-friction hinge, {len(frame)} designs (catena.sweep)")
    fig.savefig(args.output, dpi=120)
    print(f"wrote {args.output} ({len(frame)} designs)")


if __name__ == "__main__":
    main()
