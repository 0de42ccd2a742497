#!/usr/bin/env bash
# End-to-end benchmark of `insula mass` on generated footprints with hip roofs.
# Usage: [INSULA=path/to/insula] bench/mass_job.sh [COUNT] [RUNS]   (prints each run and the median)
set -euo pipefail
cd "$(dirname "$0")/.."
insula=${INSULA:-./build/src/apps/cli/insula}
count=${1:-10000}
runs=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
node bench/make_footprints.mjs "$count" "$tmp/in.geojson"
times=()
for _ in $(seq "$runs"); do
  start=$(date +%s%N)
  "$insula" mass "$tmp/in.geojson" --roof hip -o "$tmp/out.glb" --report "$tmp/r.json" --quiet >/dev/null
  end=$(date +%s%N)
  ms=$(((end - start) / 1000000))
  t=$(printf '%d.%03d' $((ms / 1000)) $((ms % 1000)))
  times+=("$t")
  echo "run: ${t}s  stages: $(node -e 'const r=require(process.argv[1]);console.log(JSON.stringify(r.seconds))' "$tmp/r.json")"
done
median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
echo "buildings: $count  median wall time over $runs runs: ${median}s"
