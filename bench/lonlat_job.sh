#!/usr/bin/env bash
# The same town in UTM meters and in longitude/latitude (as an OpenStreetMap export gives it,
# 7 decimals), each built with `insula mass -o GLB -o PNG --keep-going`: the issue 19 target is the
# same rate per building in both (within 20 %). Prints each run, the medians and their ratio.
# Usage: [INSULA=path/to/insula] bench/lonlat_job.sh [COUNT | LONLAT.geojson] [RUNS]
#   COUNT: a generated town (bench/make_footprints.mjs, in UTM 33N) reprojected to lon/lat;
#   LONLAT.geojson: a real export, reprojected to its UTM zone (millimetres) for the comparison.
set -euo pipefail
cd "$(dirname "$0")/.."
insula=${INSULA:-./build/src/apps/cli/insula}
source=${1:-6471}
runs=${2:-5}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
positions() {  # in.geojson out.txt: every position, one "x y" per line
  node -e '
    const fs = require("fs");
    const doc = JSON.parse(fs.readFileSync(process.argv[1]));
    const out = [];
    const walk = (c) => (typeof c[0] === "number" ? out.push(c[0] + " " + c[1]) : c.forEach(walk));
    doc.features.forEach((f) => f.geometry && walk(f.geometry.coordinates));
    fs.writeFileSync(process.argv[2], out.join("\n") + "\n");' "$1" "$2"
}
replace_positions() {  # in.geojson positions.txt crs|"" out.geojson
  node -e '
    const fs = require("fs");
    const doc = JSON.parse(fs.readFileSync(process.argv[1]));
    const xy = fs.readFileSync(process.argv[2], "utf8").trim().split("\n").map((l) => l.split(/\s+/).slice(0, 2).map(Number));
    let next = 0;
    const walk = (c) => (typeof c[0] === "number" ? xy[next++] : c.map(walk));
    doc.features.forEach((f) => { if (f.geometry) f.geometry.coordinates = walk(f.geometry.coordinates); });
    if (process.argv[3]) doc.crs = { type: "name", properties: { name: process.argv[3] } }; else delete doc.crs;
    fs.writeFileSync(process.argv[4], JSON.stringify(doc));' "$1" "$2" "$3" "$4"
}
if [ -f "$source" ]; then
  cp "$source" "$tmp/lonlat.geojson"
  positions "$tmp/lonlat.geojson" "$tmp/ll.txt"
  zone=$(head -1 "$tmp/ll.txt" | awk '{z = int(($1 + 180) / 6) + 1; printf "%d%02d", ($2 < 0 ? 327 : 326), z}')
  cs2cs -f %.3f OGC:CRS84 "EPSG:$zone" <"$tmp/ll.txt" >"$tmp/xy.txt"
  replace_positions "$tmp/lonlat.geojson" "$tmp/xy.txt" "urn:ogc:def:crs:EPSG::$zone" "$tmp/utm.geojson"
else
  node bench/make_footprints.mjs "$source" "$tmp/plain.geojson"
  positions "$tmp/plain.geojson" "$tmp/xy.txt"
  cs2cs -f %.7f EPSG:32633 OGC:CRS84 <"$tmp/xy.txt" >"$tmp/ll.txt"
  replace_positions "$tmp/plain.geojson" "$tmp/xy.txt" "urn:ogc:def:crs:EPSG::32633" "$tmp/utm.geojson"
  replace_positions "$tmp/plain.geojson" "$tmp/ll.txt" "" "$tmp/lonlat.geojson"
fi
median() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
run() {  # file: seconds of one run
  local start end
  start=$(date +%s%N)
  "$insula" mass "$1" -o "$tmp/out.glb" -o "$tmp/out.png" --keep-going --quiet >/dev/null
  end=$(date +%s%N)
  echo "scale=3; ($end - $start) / 1000000000" | bc
}
utm=() lonlat=()
for _ in $(seq "$runs"); do  # alternate, so drift in the machine's speed hits both alike
  utm+=("$(run "$tmp/utm.geojson")")
  lonlat+=("$(run "$tmp/lonlat.geojson")")
  echo "run: utm ${utm[-1]}s lonlat ${lonlat[-1]}s"
done
u=$(median "${utm[@]}") l=$(median "${lonlat[@]}")
echo "median utm ${u}s  lonlat ${l}s  lonlat/utm $(echo "scale=3; $l / $u" | bc)"
