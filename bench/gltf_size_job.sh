#!/usr/bin/env bash
# The GLB a user opens (issue 21): CGA building.cga on COUNT generated lots (bench/make_footprints.mjs),
# Insula's GLB (and with --compress when the CLI has it) against gltfpack's output of the same
# scene (tools/node_modules: `gltfpack` and `gltfpack -cc`, given the scene as plain float
# geometry with a node per part, `--gltf-nodes element --gltf-float`, so it starts from what
# Insula wrote before issue 21), and how long Blender 3.4 headless takes to import each (stopped
# after BLENDER_TIMEOUT seconds, default 60; "not imported" when Blender refuses the file).
# Also gltfpack given the node-per-building scene the issue asks for (`--gltf-float`, float
# geometry with a node per building and feature ids) and told to keep those nodes (`-kn`): the
# same structure and content, so the comparison of the layouts' bytes only (docs/PERFORMANCE.md).
# Prints one line per figure; the targets: default at most 1.5x gltfpack, --compress at most
# 1.2x gltfpack -cc, Blender under 10 s.
# Usage: [INSULA=path/to/insula] [BLENDER_TIMEOUT=60] bench/gltf_size_job.sh [COUNT]  (default 1000)
set -euo pipefail
cd "$(dirname "$0")/.."
insula=$(realpath "${INSULA:-./build/src/apps/cli/insula}")
count=${1:-1000}
timeout_s=${BLENDER_TIMEOUT:-60}
gltfpack=tools/node_modules/.bin/gltfpack
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

node bench/make_footprints.mjs "$count" "$tmp/lots.geojson" >/dev/null
start=$(date +%s.%N)
"$insula" build examples/cga/building.cga --lot "$tmp/lots.geojson" -o "$tmp/insula.glb" -q \
  >/dev/null
echo "insula build: $(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.2f", b - a }') s wall"
if "$insula" build --help 2>/dev/null | grep -- --compress >/dev/null; then
  "$insula" build examples/cga/building.cga --lot "$tmp/lots.geojson" -o "$tmp/compressed.glb" \
    --compress -q >/dev/null
fi
"$insula" build examples/cga/building.cga --lot "$tmp/lots.geojson" -o "$tmp/plain.glb" \
  --gltf-nodes element --gltf-float -q >/dev/null
"$gltfpack" -i "$tmp/plain.glb" -o "$tmp/gltfpack.glb" >/dev/null
"$gltfpack" -cc -i "$tmp/plain.glb" -o "$tmp/gltfpack_cc.glb" >/dev/null
"$insula" build examples/cga/building.cga --lot "$tmp/lots.geojson" -o "$tmp/buildings.glb" \
  --gltf-float -q >/dev/null
"$gltfpack" -kn -i "$tmp/buildings.glb" -o "$tmp/gltfpack_kn.glb" >/dev/null
"$gltfpack" -kn -cc -i "$tmp/buildings.glb" -o "$tmp/gltfpack_kn_cc.glb" >/dev/null

bytes() { stat -c %s "$1"; }
structure() {  # nodes, meshes, accessors of a GLB
  node -e 'const b = require("fs").readFileSync(process.argv[1]);
           const j = JSON.parse(b.subarray(20, 20 + b.readUInt32LE(12)));
           console.log(`${j.nodes.length} nodes, ${j.meshes.length} meshes, ` +
                       `${j.accessors.length} accessors`);' "$1"
}
blender_seconds() {  # GLB: import time in seconds, "not imported", or "over N s"
  local t0 t1 status=0
  t0=$(date +%s.%N)
  timeout "$timeout_s" blender -b --factory-startup --python-exit-code 1 \
    --python tools/blender_import.py -- "$1" >"$tmp/blender.txt" 2>&1 || status=$?
  t1=$(date +%s.%N)
  if [ "$status" = 124 ]; then
    echo "over $timeout_s s"
  elif ! grep -q '^IMPORTED ' "$tmp/blender.txt"; then
    echo "not imported ($(grep -m1 -o 'Error: .*' "$tmp/blender.txt" | cut -c1-80))"
  else
    awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.1f s (Blender start and import)\n", b - a }'
  fi
}
for f in insula compressed gltfpack gltfpack_cc gltfpack_kn gltfpack_kn_cc; do
  [ -f "$tmp/$f.glb" ] || continue
  printf '%-12s %12d bytes  %s  Blender %s\n' "$f" "$(bytes "$tmp/$f.glb")" \
    "$(structure "$tmp/$f.glb")" "$(blender_seconds "$tmp/$f.glb")"
done
ratio() { awk -v a="$(bytes "$1")" -v b="$(bytes "$2")" 'BEGIN { printf "%.2f", a / b }'; }
echo "ratio insula / gltfpack: $(ratio "$tmp/insula.glb" "$tmp/gltfpack.glb") (target 1.5)"
if [ -f "$tmp/compressed.glb" ]; then
  echo "ratio compressed / gltfpack -cc: $(ratio "$tmp/compressed.glb" "$tmp/gltfpack_cc.glb") (target 1.2)"
  echo "ratio compressed / gltfpack -kn -cc (same structure): $(ratio "$tmp/compressed.glb" \
    "$tmp/gltfpack_kn_cc.glb") (target 1.2)"
fi
echo "ratio insula / gltfpack -kn (same structure): $(ratio "$tmp/insula.glb" "$tmp/gltfpack_kn.glb") (target 1.5)"
