#!/usr/bin/env bash
# `insula build --lot` on many lots and on invalid lots: reading 10,000 lots takes time linear in
# their number (issue 11: each lot used to re-parse the whole file, 2,000 lots took 10 s), and
# --keep-going skips invalid lot features for CGA and .bldg villages with one positioned warning
# each, counted in the report; without it the error names the feature and suggests the flag.
source "$(dirname "$0")/lib/common.sh"

node "$root/bench/make_footprints.mjs" 10000 "$tmp/lots.geojson" >/dev/null
expect_exit 0 "10,000 lots" timeout 300 "$insula" build "$root/bench/lots.cga" --lot "$tmp/lots.geojson" \
  --report "$tmp/r.json" -q
# Quadratic reading took minutes here; linear reading takes well under a second on an idle
# machine: 5 s leaves room for a loaded one.
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.lots !== 10000 || !(r.seconds.read_lots < 5)) { console.log(JSON.stringify(r)); process.exit(1); }' \
  "$tmp/r.json" || fail "10,000 lots: read in under 5 s"

# A bow-tie lot among good ones.
cat >"$tmp/bad_lots.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "good", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 9], [0, 9], [0, 0]]]}},
 {"type": "Feature", "id": "bowtie", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [30, 10], [30, 0], [20, 10], [20, 0]]]}}]}
G
bowtie='bad_lots.geojson:3:105: error[GEO022]: feature 1 (id "bowtie"): polygon: outer ring: edges 0-1 and 2-3 cross at (25, 5)'
expect_exit 1 "CGA: invalid lot" "$insula" build "$root/bench/lots.cga" --lot "$tmp/bad_lots.geojson" -q
grep -qF "$bowtie" "$tmp/err.txt" || { fail "CGA: invalid lot message"; cat "$tmp/err.txt"; }
grep -qF "note: --keep-going skips invalid features, each with a warning" "$tmp/err.txt" ||
  { fail "CGA: --keep-going suggested"; cat "$tmp/err.txt"; }
expect_exit 0 "CGA: --keep-going" "$insula" build "$root/bench/lots.cga" --lot "$tmp/bad_lots.geojson" \
  --keep-going --report "$tmp/k.json" -o "$tmp/k.obj"
grep -qF "${bowtie/error/warning}" "$tmp/err.txt" || { fail "CGA: --keep-going warning"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.lots !== 1 || r.invalid_lots !== 1) { console.log(JSON.stringify(r)); process.exit(1); }' \
  "$tmp/k.json" || fail "CGA: --keep-going report"

# A lot's seed is its feature's place in the file: mending the bow-tie that --keep-going skipped
# leaves the good building's random height as it was (it used to be seeded by its place among
# the valid lots, so it changed), in one scene and in 3D Tiles.
printf 'Lot --> extrude(rand(3, 30)) Mass\n' >"$tmp/rand.cga"
node -e 'const fs = require("fs"); const c = JSON.parse(fs.readFileSync(process.argv[1]));
         c.features.reverse(); fs.writeFileSync(process.argv[2], JSON.stringify(c));
         c.features[0].geometry.coordinates = [[[20, 0], [30, 0], [30, 10], [20, 10], [20, 0]]];
         fs.writeFileSync(process.argv[3], JSON.stringify(c));' \
  "$tmp/bad_lots.geojson" "$tmp/bad_first.geojson" "$tmp/mended.geojson"
expect_exit 0 "CGA seeds: bad lot first" "$insula" build "$tmp/rand.cga" --lot "$tmp/bad_first.geojson" \
  --keep-going -q -o "$tmp/bad_first.obj" --crs EPSG:32633 -o "$tmp/bad_first/tileset.json"
expect_exit 0 "CGA seeds: mended" "$insula" build "$tmp/rand.cga" --lot "$tmp/mended.geojson" -q \
  -o "$tmp/mended.obj" --crs EPSG:32633 -o "$tmp/mended/tileset.json"
good_top() { awk '/^o /{f = ($2 == "good")} f && /^v / && $3 > top {top = $3} END {print top}' "$1"; }
[ -n "$(good_top "$tmp/mended.obj")" ] && [ "$(good_top "$tmp/bad_first.obj")" = "$(good_top "$tmp/mended.obj")" ] ||
  fail "CGA seeds: the good lot's height moved: $(good_top "$tmp/bad_first.obj") vs $(good_top "$tmp/mended.obj")"
node -e 'const fs = require("fs"); const top = (f) => JSON.parse(fs.readFileSync(f)).root.boundingVolume.region[5];
         if (top(process.argv[1]) !== top(process.argv[2])) process.exit(1);' \
  "$tmp/bad_first/tileset.json" "$tmp/mended/tileset.json" || fail "CGA seeds: tiles' heights differ"

# The same for a graph's create.lots (a skipped feature counts as one lot): the lots graph draws
# each lot's storeys at random.
for f in bad_first mended; do
  expect_exit 0 "graph seeds: $f" "$insula" build "$root/examples/graph/city/lots.graph.json" \
    --lot "$tmp/$f.geojson" --keep-going -q -o "$tmp/g_$f.obj"
done
[ -n "$(good_top "$tmp/g_mended.obj")" ] && [ "$(good_top "$tmp/g_bad_first.obj")" = "$(good_top "$tmp/g_mended.obj")" ] ||
  fail "graph seeds: the good lot's height moved: $(good_top "$tmp/g_bad_first.obj") vs $(good_top "$tmp/g_mended.obj")"

village=$root/examples/bldg/village/village.bldg
expect_exit 1 ".bldg village: invalid lot" "$insula" build "$village" --lot "$tmp/bad_lots.geojson" -q -o "$tmp/v.glb"
grep -qF "$bowtie" "$tmp/err.txt" || { fail ".bldg: invalid lot message"; cat "$tmp/err.txt"; }
[ -e "$tmp/v.glb" ] && fail ".bldg: invalid lot: nothing written"
expect_exit 0 ".bldg village: --keep-going" "$insula" build "$village" --lot "$tmp/bad_lots.geojson" \
  --keep-going --report "$tmp/v.json" -o "$tmp/v.glb"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.buildings.length !== 1 || r.invalid_lots !== 1) { console.log(JSON.stringify(r)); process.exit(1); }' \
  "$tmp/v.json" || fail ".bldg: --keep-going report"

finish lots
