#!/usr/bin/env bash
# The city from streets (examples/graph/city/city.graph.json) at growing sizes: GRID x GRID street
# vertices give (GRID-1)^2 blocks of 8 lots, each lot a mass whose four walls are derived by CGA
# rules (issue 14 target: 10,000 lots with CGA buildings in at most 10 s on the 2-core machine).
# Times whole runs writing a GLB with farm-bench (medians), then prints the lot count, the run
# and scene stages and the slowest nodes of one run (from --report).
# Usage: [INSULA=path/to/insula] [RUNS=3] bench/graph_city.sh [GRID...]   (default: 12 36)
set -euo pipefail
cd "$(dirname "$0")/.."
insula=$(realpath "${INSULA:-./build/src/apps/cli/insula}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
grids=("$@")
[ ${#grids[@]} -gt 0 ] || grids=(12 36)
for g in "${grids[@]}"; do
    echo "== grid $g: insula build examples/graph/city/city.graph.json --set columns=$g --set rows=$g -o city.glb"
    farm-bench -n "${RUNS:-3}" --timeout 900 -- "$insula" build examples/graph/city/city.graph.json \
      --set columns="$g" --set rows="$g" -q -o "$tmp/city.glb" --report "$tmp/r.json"
    node -e 'const r = require(process.argv[1]);
             const runs = Object.entries(r.graph.node_runs).sort((a, b) => b[1].seconds - a[1].seconds);
             console.log(r.graph.leaves["tiles.out"].count + " lots, " + r.entities + " entities; run " +
                         r.seconds.run.toFixed(2) + " s, scene " + r.seconds.scene.toFixed(2) +
                         " s, total " + r.seconds.total.toFixed(2) + " s (one run)");
             console.log("slowest nodes: " + runs.slice(0, 4).map(([k, v]) => k + " " +
                         v.seconds.toFixed(2) + " s").join(", "));' "$tmp/r.json"
done
