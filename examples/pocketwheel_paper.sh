#!/usr/bin/env bash
# Seed 003's example: chain Ø18×64 on an 8-tooth pocket wheel at ω = 5 1/s, guide end 256 mm.
# Free, chordal and tangential run-on side by side, then the tangential run in JSON with the
# inertial force of a 40 kg strand. Run from the repository root after building (README).
set -euo pipefail
catena=${CATENA:-build/release/apps/catena/catena}
"$catena" pocketwheel --example --csv pocketwheel_paper.csv
"$catena" pocketwheel --pitch 64mm --wire 18mm --teeth 8 --omega '5 1/s' --guide tangential \
  --guide-end 256mm --strand-mass 40kg --format json --output pocketwheel_tangential.json
echo "wrote pocketwheel_paper.csv and pocketwheel_tangential.json" >&2
