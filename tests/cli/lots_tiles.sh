#!/usr/bin/env bash
# Lots to 3D Tiles, tile by tile (issue 17; docs/formats.md "3D Tiles"). A CGA city (`insula build
# district.cga --lot LOTS -o DIR/tileset.json`) derives what the whole-scene build derives (the same
# counts in the report), writes the same bytes whatever the thread count, opens in CesiumJS and
# loaders.gl with every terminal a feature, and a lot that fails stops the run with its diagnostic
# and leaves the user's earlier tileset as it was. A .bldg village reports what its whole-scene
# build reports, building for building, and its tiles pass the Khronos validator; with coarse
# parents (--tile-blocks) it still opens in CesiumJS with every content where it belongs.
source "$(dirname "$0")/lib/common.sh"

node "$root/examples/city/make_city.mjs" 150 "$tmp/lots.geojson" >/dev/null
district="$root/examples/cga/district.cga"
for threads in 1 2; do
  expect_exit 0 "district, tiles only, $threads thread(s)" "$insula" build "$district" \
    --lot "$tmp/lots.geojson" --tile-faces 20000 --threads "$threads" \
    -o "$tmp/t$threads/tileset.json" --report "$tmp/t$threads.json" --quiet
done
tiles=$(ls "$tmp/t1/tiles" | wc -l)
[ "$tiles" -ge 4 ] || fail "expected several tiles, got $tiles"
diff -r "$tmp/t1" "$tmp/t2" >/dev/null || fail "1 and 2 threads wrote different tilesets"
# With an OBJ beside it the whole scene is derived at once: the same derivation.
expect_exit 0 "district, whole scene" "$insula" build "$district" --lot "$tmp/lots.geojson" \
  -o "$tmp/whole/tileset.json" -o "$tmp/whole.obj" --report "$tmp/whole.json" --quiet
node -e '
  const [tiles, whole] = process.argv.slice(1, 3).map((f) => require(f));
  for (const key of ["lots", "shapes", "terminals", "rule_applications", "symbols", "start"]) {
    if (JSON.stringify(tiles[key]) !== JSON.stringify(whole[key])) {
      console.log(key, JSON.stringify(tiles[key]), JSON.stringify(whole[key]));
      process.exit(1);
    }
  }
  if (tiles.tiles !== Number(process.argv[3]) || tiles.ranks !== 1) process.exit(1);
' "$tmp/t2.json" "$tmp/whole.json" "$tiles" || fail "the tile job's report differs from the whole scene's"
# A tile's feature is a building's terminals alike in symbol and attributes (docs/formats.md):
# this grammar sets colours only, so the whole scene's distinct (building, symbol, material).
parts=$(awk '/^o /{b=$2} /^g /{n=substr($2, length(b) + 2); sub(/\.[^.]*$/, "", n)}
             /^usemtl /{print b "|" n "|" $2}' "$tmp/whole.obj" | sort -u | wc -l)
terminals=$(node -e 'console.log(require(process.argv[1]).terminals)' "$tmp/t2.json")
[ "$parts" -gt 150 ] && [ "$parts" -lt "$terminals" ] ||
  fail "alike terminals: $parts parts of $terminals terminals on 150 lots"
# The whole scene's tiles (written beside its OBJ, which keeps a group per terminal) merge them the
# same way: as many features (property table rows) as the streamed tiles.
features() { node -e '
  const fs = require("fs");
  let rows = 0;
  for (const f of fs.readdirSync(process.argv[1])) {
    const glb = fs.readFileSync(process.argv[1] + "/" + f);
    const json = JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString());
    rows += json.extensions.EXT_structural_metadata.propertyTables[0].count;
  }
  console.log(rows);' "$1"; }
[ "$(features "$tmp/t2/tiles")" = "$parts" ] || fail "streamed tiles: not $parts features"
[ "$(features "$tmp/whole/tiles")" = "$parts" ] ||
  fail "whole-scene tiles: $(features "$tmp/whole/tiles") features, not $parts"
node "$root/tools/check_tileset.mjs" "$tmp/t2/tileset.json" --lonlat 14.3840,49.0033 \
  --tolerance-m 50 --expect-features "$parts" >"$tmp/c.txt" 2>&1 ||
  { fail "the CGA tileset does not open in CesiumJS and loaders.gl"; cat "$tmp/c.txt"; }

# CityJSONSeq is streamed the same way, a line per building as its tile is made: valid against the
# CityJSON 2.0.2 schema, the same buildings (ids) as the whole-scene file, the same tiles beside it.
expect_exit 0 "district, tiles and CityJSONSeq" "$insula" build "$district" \
  --lot "$tmp/lots.geojson" --tile-faces 20000 -o "$tmp/s/tileset.json" \
  -o "$tmp/district.city.jsonl" --quiet
diff -r "$tmp/t1" "$tmp/s" >/dev/null || fail "with CityJSONSeq: other tiles"
expect_exit 0 "district, CityJSONSeq of the whole scene" "$insula" build "$district" \
  --lot "$tmp/lots.geojson" -o "$tmp/whole.city.jsonl" -o "$tmp/whole2.obj" \
  -o "$tmp/whole.city.json" --quiet
# The header and the first ten lines through the schema (ajv takes about 0.7 s per building here).
head -n 11 "$tmp/district.city.jsonl" >"$tmp/first.city.jsonl"
node "$root/tools/validate_cityjsonseq.mjs" "$tmp/first.city.jsonl" >"$tmp/v.txt" 2>&1 ||
  { fail "streamed CityJSONSeq: invalid"; cat "$tmp/v.txt"; }
ids() { node -e '
  const lines = require("fs").readFileSync(process.argv[1], "utf8").trim().split("\n").slice(1);
  console.log(lines.map((l) => JSON.parse(l).id).sort().join(" "));' "$1"; }
[ "$(ids "$tmp/district.city.jsonl")" = "$(ids "$tmp/whole.city.jsonl")" ] ||
  fail "streamed CityJSONSeq: other buildings than the whole scene's"
# Streamed or from the whole scene (whose OBJ keeps a group per terminal), CityJSON has one part
# per set of alike terminals: the same city objects with the same surface counts (formats.md).
objects() { node -e '
  const text = require("fs").readFileSync(process.argv[1], "utf8").trim();
  const docs = process.argv[1].endsWith("l") ? text.split("\n").slice(1).map(JSON.parse)
                                             : [JSON.parse(text)];
  const rows = [];
  for (const d of docs) for (const [id, o] of Object.entries(d.CityObjects)) {
    const g = (o.geometry || [])[0];
    const n = !g ? 0 : g.type === "Solid" ? g.boundaries[0].length : g.boundaries.length;
    rows.push(`${id}:${o.type}:${g ? g.type : "-"}:${n}`);
  }
  console.log(rows.sort().join("\n"));' "$1"; }
objects "$tmp/district.city.jsonl" >"$tmp/o1.txt"
objects "$tmp/whole.city.jsonl" >"$tmp/o2.txt"
objects "$tmp/whole.city.json" >"$tmp/o3.txt"
streamed_parts=$(awk -F: '$2 == "BuildingPart"' "$tmp/o1.txt" | wc -l)
[ "$streamed_parts" -lt $((20 * $(ids "$tmp/district.city.jsonl" | wc -w))) ] ||
  fail "streamed CityJSONSeq: $streamed_parts parts, not merged"
cmp -s "$tmp/o1.txt" "$tmp/o2.txt" || fail "CityJSONSeq: other objects from the whole scene"
cmp -s "$tmp/o1.txt" "$tmp/o3.txt" || fail "CityJSON of the whole scene: other objects"
ls "$tmp" | grep -q "city.jsonl.insula" && fail "streamed CityJSONSeq: a staging file is left"

# Missing assets are counted per request, as the whole scene counts them (the lots sampled to plan
# the tiles are not counted); an output named twice is written once.
cat >"$tmp/asset.cga" <<'EOF'
Lot --> extrude(10) comp(f){ top: Roof | side: Wall }
Roof --> i("nothere.obj")
EOF
expect_exit 0 "missing asset, tiles" "$insula" build "$tmp/asset.cga" --lot "$tmp/lots.geojson" \
  -o "$tmp/a/tileset.json" -o "$tmp/a/tileset.json" --report "$tmp/a.json" --quiet
expect_exit 0 "missing asset, whole scene" "$insula" build "$tmp/asset.cga" \
  --lot "$tmp/lots.geojson" -o "$tmp/aw/tileset.json" -o "$tmp/aw.obj" --report "$tmp/aw.json" --quiet
node -e '
  const [a, w] = process.argv.slice(1, 3).map((f) => require(f));
  if (JSON.stringify(a.missing_assets) !== JSON.stringify(w.missing_assets) ||
      !(a.missing_assets["nothere.obj"] >= 150)) process.exit(1);
' "$tmp/a.json" "$tmp/aw.json" || fail "missing assets: counted otherwise than the whole scene"

# Ids stay unique across a streamed CityJSONSeq's tiles: lot "X" (part "X-Mass") and lot "X-Mass"
# in tiles of their own.
node -e '
  const f = (id, x, y) => ({type: "Feature", id, properties: {},
    geometry: {type: "Polygon", coordinates: [[[x, y], [x + 8, y], [x + 8, y + 8], [x, y + 8], [x, y]]]}});
  const features = [];
  for (let i = 0; i < 30; ++i) features.push(f(i ? "a" + i : "X", 455000 + 10 * i, 5427000));
  for (let i = 0; i < 30; ++i) features.push(f(i ? "b" + i : "X-Mass", 457000 + 10 * i, 5429000));
  console.log(JSON.stringify({type: "FeatureCollection", features,
    crs: {type: "name", properties: {name: "urn:ogc:def:crs:EPSG::32633"}}}));' >"$tmp/ids.geojson"
printf 'Lot --> extrude(10) Mass\n' >"$tmp/mass.cga"
expect_exit 0 "ids across tiles" "$insula" build "$tmp/mass.cga" --lot "$tmp/ids.geojson" \
  --tile-faces 100 -o "$tmp/ids/tileset.json" -o "$tmp/ids.city.jsonl" --quiet
[ "$(ls "$tmp/ids/tiles" | wc -l)" -ge 2 ] || fail "ids across tiles: expected several tiles"
node "$root/tools/validate_cityjsonseq.mjs" "$tmp/ids.city.jsonl" >"$tmp/v.txt" 2>&1 ||
  { fail "ids across tiles: a repeated id"; cat "$tmp/v.txt"; }

# A lot whose derivation fails (runaway recursion on the tallest lots): exit 1, the lot's
# diagnostic, the earlier tileset and no staging folder left.
cat >"$tmp/fails.cga" <<'EOF'
attr height = 10
Lot --> case height > 30: Grow else: extrude(height) Mass
Grow --> Grow
EOF
cp -r "$tmp/t1" "$tmp/keep"
expect_exit 1 "a lot fails" "$insula" build "$tmp/fails.cga" --lot "$tmp/lots.geojson" \
  -o "$tmp/keep/tileset.json" --quiet
grep -q "error\[" "$tmp/err.txt" || { fail "a lot fails: no diagnostic"; cat "$tmp/err.txt"; }
diff -r "$tmp/t1" "$tmp/keep" >/dev/null || fail "a lot fails: the earlier tileset changed"
[ -e "$tmp/keep/tiles.insula-partial" ] && fail "a lot fails: the staging folder is left"

# A .bldg village (seed 000, Fig. 12): 27 buildings with interiors, every one its own grammar.
village="$root/examples/bldg/village"
for threads in 1 2; do
  expect_exit 0 "village, tiles only, $threads thread(s)" "$insula" build "$village/village.bldg" \
    --lot "$village/village.geojson" --crs EPSG:3857 --tile-faces 20000 --threads "$threads" \
    -o "$tmp/v$threads/tileset.json" --report "$tmp/v$threads.json" --quiet
done
diff -r "$tmp/v1" "$tmp/v2" >/dev/null || fail "village: 1 and 2 threads wrote different tilesets"
expect_exit 0 "village, whole scene" "$insula" build "$village/village.bldg" \
  --lot "$village/village.geojson" --crs EPSG:3857 -o "$tmp/vw/tileset.json" -o "$tmp/vw.glb" \
  --report "$tmp/vw.json" --quiet
node -e '
  const [tiles, whole] = process.argv.slice(1, 3).map((f) => require(f));
  for (const r of [tiles, whole]) for (const k of ["seconds", "tiles", "ranks", "tiles_by_rank"]) delete r[k];
  if (JSON.stringify(tiles) !== JSON.stringify(whole) || tiles.buildings.length !== 27) process.exit(1);
' "$tmp/v2.json" "$tmp/vw.json" || fail "village: the tile job's report differs from the whole scene's"
[ "$(ls "$tmp/v1/tiles" | wc -l)" -ge 3 ] || fail "village: expected several tiles"
validate_gltf "village tiles (Khronos validator)" "$tmp"/v1/tiles/*.glb

# Coarse parents (--tile-blocks): inner tiles show their buildings as blocks; their transforms
# compose with the leaves' (Cesium's check puts every content inside its tile's region).
expect_exit 0 "village with blocks" "$insula" build "$village/village.bldg" \
  --lot "$village/village.geojson" --crs EPSG:3857 --tile-faces 20000 --tile-blocks 100 \
  -o "$tmp/vb/tileset.json" --quiet
node -e '
  const t = require(process.argv[1]);
  const inner = [];
  const walk = (tile) => { if (tile.children) { if (tile.content) inner.push(tile); tile.children.forEach(walk); } };
  walk(t.root);
  if (inner.length === 0 || !inner.every((tile) => tile.transform)) process.exit(1);
' "$tmp/vb/tileset.json" || fail "blocks: no inner tile with content and a transform"
node "$root/tools/check_tileset.mjs" "$tmp/vb/tileset.json" >"$tmp/c.txt" 2>&1 ||
  { fail "blocks: the tileset does not open in CesiumJS and loaders.gl"; cat "$tmp/c.txt"; }

finish lots_tiles
