#!/usr/bin/env python3
"""Writes the fuzz harnesses' seed corpus (tests/fuzz/corpus/<harness>/) from the example case
files and the commands the documentation shows. Run from the repository root after changing
either; the corpus is committed. Formats: tests/fuzz/*_fuzz.cpp."""
import pathlib
import tomllib

root = pathlib.Path(__file__).resolve().parents[2]
corpus = root / "tests/fuzz/corpus"
shared_tables = ("chain", "sprocket", "loads", "material")
renamed = {"designation": "chain"}  # chain.designation is contact's --chain


def write(harness, name, data):
    folder = corpus / harness
    folder.mkdir(parents=True, exist_ok=True)
    (folder / name).write_bytes(data if isinstance(data, bytes) else data.encode())


def text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    return str(value)


def flat(table, prefix=""):
    for key, value in table.items():
        if isinstance(value, dict):
            yield from flat(value, prefix + key + ".")
        else:
            yield prefix + key, value


# The case-file reader: every example as it is.
examples = sorted((root / "examples").glob("*.toml"))
for path in examples:
    write("case", path.name, path.read_bytes())

# Each analysis: every [analyses.<name>] table of the examples with the shared tables it takes.
for path in examples:
    case = tomllib.loads(path.read_text())
    shared = []
    for table in shared_tables:
        for key, value in case.get(table, {}).items():
            if key not in ("type", "name"):
                shared.append((renamed.get(key, key), text(value)))
    for table, values in case.get("analyses", {}).items():
        name = table.split("-")[0]
        lines = [name] + [f"{k}={v}" for k, v in shared]
        lines += [f"{k}={text(v)}" for k, v in values.items()]
        write("analysis", f"{path.stem}.{table}", "\n".join(lines) + "\n")
    if "loop" in case:  # the table parameter takes the rest of the input as its TOML file
        body = path.read_text()
        write("analysis", f"{path.stem}.loop", "loop\nloop=\n" + body[body.index("[loop]"):])

# The commands of docs/cli.md and the README (flag → key), and issue 18's shortest reproducers
# of unbounded and non-finite results (size parameters are clamped by the harness).
commands = {
    "pocketwheel.tangential": "pocketwheel --pitch 64mm --wire 18mm --teeth 8 --omega 47.75rpm "
    "--guide tangential --guide-end 256mm --span-model pivot --strand-mass 40kg",
    "pocketwheel.height": "pocketwheel --pitch 64mm --wire 18mm --teeth 8 --omega 5 --guide height "
    "--guide-height 30mm",
    "pocketwheel.omega_overflow": "pocketwheel --pitch 64 --wire 18 --teeth 8 --omega 1e200",
    "hinge.flat": "hinge --pin-diameter 40mm --half-thickness 8mm --plate-radius 34mm --teeth 8 "
    "--strokes 1 --flat --face-half-length 10mm --loaded-length 20mm --tension 29.4kN "
    "--allowable-shear 100MPa --contact-length 24mm --modulus 210GPa --poisson 0.3 "
    "--allowable-contact 1200MPa --pitch 125mm --friction 0.15",
    "hinge_sweep.count": "hinge_sweep --pin-diameter 40 --half-thickness 8 --teeth 8 --count 1000000",
    "contact.chain": "contact --chain 12B --tooth-radius 15.56 --load 1kN --skew 0.7 --gamma 1e300",
    "contact.full": "contact --roller-diameter 11.91mm --roller-length 12.7mm --tooth-radius 15.56mm "
    "--profile convex --modulus 210GPa --poisson 0.3 --load 1kN --pitch 19.05mm --skew 0.7deg "
    "--skew-factor 0.65 --tooth-modulus 210GPa --tooth-poisson 0.3 --skew-sweep 0deg:4deg:0.1deg "
    "--slices 201",
    "contact.bracket": "contact --chain 12B --roller-diameter 1e150m --tooth-radius 15.56 "
    "--profile convex --load 1kN --skew 0.5",
    "fretting.docs": "fretting --roughness 0.8um --amplitude 5um --load 2kN --frequency 20Hz "
    "--k1 1e9 --k2 -1e-6",
    "warp.docs": "warp --heights 0,10mm,50mm,60mm --stiffness 2e8 --widths 8mm --pin-diameter 24mm "
    "--force 30kN,35kN,40kN --load-height 30mm,33mm,36mm --clearances 0,20um,0,0 --exponent 2",
    "warp.force_overflow": "warp --heights 0,10,50,60 --stiffness 2e8 --widths 8 --pin-diameter 24 "
    "--force 1e300 --load-height 30",
    "engagement.sliding": "engagement --hinge sliding --pitch 125mm --teeth 8 --strokes 2 "
    "--tension 29.4kN --friction 0.15 --journal-diameter 40mm --tooth-diameter 40mm --flank-angle 0deg",
    "engagement.rolling": "engagement --hinge rolling --pitch 125mm --teeth 8 --strokes 2 "
    "--tension 29.4kN --pin-diameter 40mm --half-thickness 8mm --plate-radius 15mm "
    "--rolling-coefficient 0.001 --tooth-arm 0mm --flank-angle 0deg",
    "engagement.friction_overflow": "engagement --hinge sliding --pitch 125 --teeth 8 "
    "--tension 29.4kN --friction 1e300",
    "ring.sweep": "ring --inner-radius 4.72mm --outer-radius 10mm --thickness 1mm --E-r 10GPa "
    "--E-phi 40GPa --G 4GPa --nu-phi-r 0.28 --gap 0.02mm --method sweep --nodes 2000000",
    "ring.extreme_moduli": "ring --inner-radius 4.72 --outer-radius 10 --thickness 1 --E-r 1e-300 "
    "--E-phi 1e300 --G 1e-300 --nu-phi-r 0.28 --gap 0.02",
    "ring_capacity.docs": "ring_capacity --alpha 0.42 --sum-sigma-r 0.2662 --k-max 4.173 "
    "--fibre-strength 2500MPa --fibre-area 22.7mm^2 --steel-mass 0.337kg --link-mass 0.035kg",
    "ring_design.docs": "ring_design --load 32900N --fibre-modulus 72.4GPa --fibre-poisson 0.22 "
    "--fibre-strength 2500MPa --fibre-density 2.56g/cm^3 --matrix-modulus 3.5GPa "
    "--matrix-poisson 0.35 --matrix-density 1.2g/cm^3 --fibre-fraction 0.7 --thickness 6mm "
    "--pitch 200mm --steel-strength 600MPa --steel-thickness 6mm",
    "strength.docs": "strength --heights 0,8mm,48mm,56mm --widths 8mm --pin-diameter 40mm "
    "--plate-width 80mm --end-distance 40mm --tension 29.4kN --roller-yield 600MPa "
    "--plate-yield 355MPa --allowable-pressure 60MPa --layout both",
    "strength.heights_overflow": "strength --heights 1e13 --widths 8 --pin-diameter 40 "
    "--plate-width 80 --end-distance 40 --tension 29.4kN --roller-yield 600 --plate-yield 355 "
    "--allowable-pressure 60",
}
chain_type = {
    "pocketwheel": "round-link", "hinge": "rolling-hinge", "hinge_sweep": "rolling-hinge",
    "contact": "roller-iso606", "fretting": "roller-iso606", "warp": "sliding-hinge",
    "engagement.sliding": "sliding-hinge", "engagement": "rolling-hinge",
    "ring": "composite-link", "ring_capacity": "composite-link", "ring_design": "composite-link",
    "strength": "sliding-hinge",
}
for name, command in commands.items():
    words = command.split()
    lines = [words[0]]
    for i, word in enumerate(words[1:], 1):
        if not word.startswith("--"):
            continue
        key = word[2:].replace("-", "_")
        has_value = i + 1 < len(words) and not words[i + 1].startswith("--")
        lines.append(f"{key}={words[i + 1]}" if has_value else key)
    write("analysis", name, "\n".join(lines) + "\n")
    # the same as a small case file: one analysis table, so that the case harness has cheap
    # starting points besides the examples (each of which runs several analyses)
    chain = chain_type.get(name, chain_type.get(words[0]))
    toml = [f'[chain]\ntype = "{chain}"', f"[analyses.{words[0]}]"]
    for line in lines[1:]:
        key, _, value = line.partition("=")
        toml.append(f'{key} = "{value}"' if value else f"{key} = true")
    write("case", f"small.{name}.toml", "\n".join(toml) + "\n")

# The quantity parser: first byte the kind (order of quantity_fuzz.cpp), then the text.
kinds = ["length", "angle", "angular_speed", "force", "stress", "mass", "time", "frequency",
         "speed", "force_per_length", "area", "density"]
quantities = {
    "length": ["64mm", "64 mm", "0.064m", "2.5in", "0.8um", "1e150m", "20"],
    "angle": ["20deg", "20 degree", "20°", "0°42'", "1°30'15\"", "42 arcmin", "0.35 rad", "3"],
    "angular_speed": ["5 1/s", "5 rad/s", "47.75 rpm", "20 Hz", "5 s^-1", "1/min"],
    "force": ["29.4kN", "1200 N", "1e300", "-0"],
    "stress": ["350MPa", "210 GPa", "1e-300 Pa"],
    "mass": ["40kg", "500 g", "0.337kg"],
    "time": ["2 s", "5 min"],
    "frequency": ["20 Hz", "1200 1/min", "5 rad/s"],
    "speed": ["0.5 m/s", "30 m/min"],
    "force_per_length": ["150 N/m", "0.15 kN/m", "15 kgf/m", "15 kg/m"],
    "area": ["22.7mm^2", "22.7 mm2", "0.227 cm^2"],
    "density": ["2.56g/cm^3", "1200 kg/m^3", "1130"],
}
for kind, texts in quantities.items():
    for i, q in enumerate(texts):
        write("quantity", f"{kind}.{i}", bytes([kinds.index(kind)]) + q.encode())
