#!/usr/bin/env bash
# City scale (issue 17): `insula mass` of COUNT generated hip-roofed footprints to 3D Tiles, tile
# by tile. Prints each run's wall time, peak memory (maximum resident set) and stages, then the
# medians. Usage: [INSULA=path/to/insula] bench/tiles_job.sh [COUNT] [RUNS]
set -euo pipefail
cd "$(dirname "$0")/.."
insula=${INSULA:-./build/src/apps/cli/insula}
count=${1:-100000}
runs=${2:-3}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
node bench/make_footprints.mjs "$count" "$tmp/in.geojson"
times=()
peaks=()
for _ in $(seq "$runs"); do
  rm -rf "$tmp/city"
  /usr/bin/time -f "%e %M" -o "$tmp/time.txt" "$insula" mass "$tmp/in.geojson" --crs EPSG:32633 \
    --roof hip -o "$tmp/city/tileset.json" --report "$tmp/r.json" --quiet >/dev/null
  read -r seconds kb <"$tmp/time.txt"
  times+=("$seconds")
  peaks+=("$((kb / 1024))")
  echo "run: ${seconds}s  peak: $((kb / 1024)) MB  stages: $(node -e \
    'const r=require(process.argv[1]);console.log(JSON.stringify(r.seconds))' "$tmp/r.json")"
done
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
tiles=$(ls "$tmp/city/tiles" | wc -l)
size=$(du -sm "$tmp/city" | cut -f1)
echo "buildings: $count  tiles: $tiles  size: ${size} MB  median over $runs runs:" \
  "$(median "${times[@]}") s, peak $(median "${peaks[@]}") MB"
