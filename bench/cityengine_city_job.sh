#!/usr/bin/env bash
# A CityEngine rule file on many lots, end to end (issue 20: "the International City building
# rules on 1,000 lots in seconds"). The rule files are not in the repository (fetched material
# stays out of commits): give the rule file and the workspace its `/ESRI.lib/...` imports resolve
# in. Generates COUNT footprints (bench/make_footprints.mjs, UTM), builds a GLB from them and times
# whole runs with farm-bench (medians), then prints one run's report.
# Usage: [INSULA=path/to/insula] [RUNS=5] [THREADS=2] bench/cityengine_city_job.sh RULE.cga WORKSPACE [COUNT]
set -euo pipefail
cd "$(dirname "$0")/.."
rule=$(realpath "${1:?usage: cityengine_city_job.sh RULE.cga WORKSPACE [COUNT]}")
workspace=$(realpath "${2:?usage: cityengine_city_job.sh RULE.cga WORKSPACE [COUNT]}")
count=${3:-1000}
insula=$(realpath "${INSULA:-./build/src/apps/cli/insula}")
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
node bench/make_footprints.mjs "$count" "$tmp/lots.geojson" >/dev/null
echo "== $count lots: insula build '$(basename "$rule")' --workspace WS --threads ${THREADS:-2} -o city.glb"
farm-bench -n "${RUNS:-5}" --timeout 900 -- "$insula" build "$rule" --workspace "$workspace" \
  --lot "$tmp/lots.geojson" --threads "${THREADS:-2}" -q -o "$tmp/city.glb" --report "$tmp/r.json"
node -e 'const r = require(process.argv[1]);
         const s = Object.entries(r.seconds).map(([k, v]) => k + " " + v.toFixed(3)).join(", ");
         console.log("one run: lots " + r.lots + ", terminals " + r.terminals + ", seconds: " + s)' \
  "$tmp/r.json"
ls -la "$tmp/city.glb" | awk '{print "GLB bytes " $5}'
