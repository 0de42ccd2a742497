#!/usr/bin/env bash
# Set-up, build, and the main job on the bundled example: six footprints (L, T, U, H, a courtyard
# house and an irregular concave house) in UTM coordinates become roofed LOD2 buildings.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh insula
mkdir -p out
./build/insula mass examples/town.geojson \
  -o out/town.glb -o out/town.obj -o out/town.city.json -o out/town.svg -o out/town.png \
  --report out/town.report.json
echo "outputs are in $(pwd)/out/ (report: out/town.report.json)"
