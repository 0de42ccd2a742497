#!/usr/bin/env bash
# `insula build` over many lots: reading the lot file must take time linear in the lot count
# (issue 11: reading lots used to re-parse the whole file once per lot, 2,000 lots took 10 s).
# Generates COUNT footprints (bench/make_footprints.mjs, UTM), builds bench/lots.cga on them with
# no output, and times whole runs with farm-bench (medians), then prints the report's read_lots
# stage of one run.
# Usage: [INSULA=path/to/insula] [RUNS=5] bench/lots_job.sh [COUNT...]   (default: 1000 10000 100000)
set -euo pipefail
cd "$(dirname "$0")/.."
insula=$(realpath "${INSULA:-./build/src/apps/cli/insula}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
counts=("$@")
[ ${#counts[@]} -gt 0 ] || counts=(1000 10000 100000)
for n in "${counts[@]}"; do
    node bench/make_footprints.mjs "$n" "$tmp/lots$n.geojson" >/dev/null
    echo "== $n lots: insula build bench/lots.cga --lot lots$n.geojson --threads 1 -q"
    farm-bench -n "${RUNS:-5}" --timeout 900 -- "$insula" build bench/lots.cga --lot "$tmp/lots$n.geojson" \
      --threads 1 -q --report "$tmp/r.json"
    node -e 'const r = require(process.argv[1]);
             console.log("read_lots " + r.seconds.read_lots.toFixed(3) + " s, total " +
                         r.seconds.total.toFixed(3) + " s (one run, from --report)")' "$tmp/r.json"
done
