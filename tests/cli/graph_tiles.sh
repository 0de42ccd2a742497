#!/usr/bin/env bash
# A graph's city tile by tile (issue 17; docs/formats.md "3D Tiles"): `insula build lots.graph.json
# --lot LOTS -o DIR/tileset.json` runs a per-lot graph a tile of lots at a time and gives, lot for
# lot, what the whole run gives (the same buildings, ids, parts, heights and attributes in the
# CityJSON; the same entity and result counts), the same bytes for any thread count, and opens in
# CesiumJS and loaders.gl. A graph that relates lots to each other runs whole and says why; a bad
# lots file is a clear error that leaves nothing behind.
source "$(dirname "$0")/lib/common.sh"

graph="$root/examples/graph/city/lots.graph.json"
node "$root/bench/make_footprints.mjs" 200 "$tmp/lots.geojson" >/dev/null
for threads in 1 2; do
  expect_exit 0 "tiles, $threads thread(s)" "$insula" build "$graph" --lot "$tmp/lots.geojson" \
    --crs EPSG:32633 --tile-faces 15000 --threads "$threads" -o "$tmp/t$threads/tileset.json" \
    -o "$tmp/t$threads.city.jsonl" --report "$tmp/t$threads.json" --quiet
done
tiles=$(ls "$tmp/t1/tiles" | wc -l)
[ "$tiles" -ge 4 ] || fail "expected several tiles, got $tiles"
diff -r "$tmp/t1" "$tmp/t2" >/dev/null || fail "1 and 2 threads wrote different tilesets"
cmp -s "$tmp/t1.city.jsonl" "$tmp/t2.city.jsonl" || fail "1 and 2 threads wrote different CityJSONSeq"
expect_exit 0 "whole run" "$insula" build "$graph" --lot "$tmp/lots.geojson" --crs EPSG:32633 \
  -o "$tmp/whole.city.json" --report "$tmp/whole.json" --quiet
# Each city object (building and part): its type, how many vertices its surfaces name, its top
# height and its attributes, in the whole file and in the tiles' lines.
node -e '
  const fs = require("fs");
  const [seq, whole, tilesReport, wholeReport] = process.argv.slice(1);
  const summary = (objects, vertices, transform, into) => {
    for (const [id, o] of Object.entries(objects)) {
      const corners = [];
      const walk = (x) => (Array.isArray(x) ? x.forEach(walk) : corners.push(x));
      for (const g of o.geometry || []) walk(g.boundaries);
      const top = Math.max(...corners.map((i) => vertices[i][2] * transform.scale[2] +
                                                  transform.translate[2]));
      into[id] = JSON.stringify([o.type, corners.length, corners.length ? top.toFixed(3) : null,
                                 o.attributes || {}]);
    }
    return into;
  };
  const w = JSON.parse(fs.readFileSync(whole));
  const a = summary(w.CityObjects, w.vertices, w.transform, {});
  const lines = fs.readFileSync(seq, "utf8").trim().split("\n").map((l) => JSON.parse(l));
  const b = {};
  for (const f of lines.slice(1)) summary(f.CityObjects, f.vertices, lines[0].transform, b);
  const ids = Object.keys(a);
  if (ids.length !== Object.keys(b).length || ids.length < 400) {
    console.log("objects", ids.length, Object.keys(b).length); process.exit(1);
  }
  for (const id of ids) if (a[id] !== b[id]) { console.log(id, a[id], b[id]); process.exit(1); }
  // The graph groups shapes by building; the building keeps the id of its lot (feature b17).
  if (!("b17" in a) || !("b17-Pane" in a)) { console.log("ids"); process.exit(1); }
  const [t, r] = [tilesReport, wholeReport].map((f) => JSON.parse(fs.readFileSync(f)));
  for (const key of ["entities", "results", "seed"]) {
    if (t[key] !== r[key]) { console.log(key, t[key], r[key]); process.exit(1); }
  }
  for (const [port, leaf] of Object.entries(r.graph.leaves)) {
    if (JSON.stringify(t.graph.leaves[port]) !== JSON.stringify(leaf)) { console.log(port); process.exit(1); }
  }
  if (t.lots !== 200 || "whole_scene_because" in t) process.exit(1);
' "$tmp/t1.city.jsonl" "$tmp/whole.city.json" "$tmp/t1.json" "$tmp/whole.json" ||
  fail "the tiles' buildings differ from the whole run's"
node "$root/tools/check_tileset.mjs" "$tmp/t2/tileset.json" --lonlat 14.3884,49.0055 \
  --tolerance-m 100 >"$tmp/c.txt" 2>&1 ||
  { fail "the graph's tileset does not open in CesiumJS and loaders.gl"; cat "$tmp/c.txt"; }

# Two buildings a lot (the graph numbers the border apart in `building`: `C`, then `C/3`) beside a
# lot whose own id is `C/2`, in another tile: the ids stay unique across the tiles' lines, as in
# the whole run (found by review).
cat >"$tmp/two.graph.json" <<'JSON'
{ "format": "insula-graph", "version": 1,
  "attributes": { "building": { "type": "integer", "default": 0 } },
  "nodes": [ { "id": "lots", "type": "create.lots" },
             { "id": "off", "type": "shape.offset", "params": { "distance": -1 } },
             { "id": "apart", "type": "attr.set", "params": { "values": { "building": "= 1" } } },
             { "id": "high", "type": "shape.extrude", "params": { "height": 10 } },
             { "id": "low", "type": "shape.extrude", "params": { "height": 3 } } ],
  "edges": [ "lots.out -> off.in", "off.inside -> high.in", "off.border -> apart.in",
             "apart.out -> low.in" ] }
JSON
node -e 'const fs = require("fs"); const g = JSON.parse(fs.readFileSync(process.argv[1]));
  g.features[1].id = "C/2"; g.features[g.features.length - 1].id = "C";
  fs.writeFileSync(process.argv[2], JSON.stringify(g));' "$tmp/lots.geojson" "$tmp/ids.geojson"
expect_exit 0 "two buildings a lot, tiles" "$insula" build "$tmp/two.graph.json" --lot "$tmp/ids.geojson" \
  --crs EPSG:32633 --tile-faces 2000 -o "$tmp/ids/tileset.json" -o "$tmp/ids.city.jsonl" -q
expect_exit 0 "two buildings a lot, whole" "$insula" build "$tmp/two.graph.json" \
  --lot "$tmp/ids.geojson" --crs EPSG:32633 -o "$tmp/ids.city.json" -q
node -e 'const fs = require("fs");
  const whole = Object.keys(JSON.parse(fs.readFileSync(process.argv[1])).CityObjects).sort();
  const seen = [];
  for (const line of fs.readFileSync(process.argv[2], "utf8").trim().split("\n").slice(1)) {
    seen.push(...Object.keys(JSON.parse(line).CityObjects));
  }
  if (new Set(seen).size !== seen.length || JSON.stringify(seen.sort()) !== JSON.stringify(whole)) {
    console.log(seen.length, new Set(seen).size, whole.length); process.exit(1);
  }
  for (const id of ["C", "C/2", "C/3", "C/2/2"]) if (!whole.includes(id)) process.exit(2);
  ' "$tmp/ids.city.json" "$tmp/ids.city.jsonl" || fail "building ids across tiles differ from the whole run's"

# A graph that relates lots (a count over all of them) runs whole; the report says why.
mkdir -p "$tmp/related"
cp "$root/examples/graph/city/facades.cga" "$tmp/related/"
sed 's|"lots.out -> storeys.in"|"lots.out -> count.in", "count.out -> storeys.in"|;
     s|{ "id": "storeys"|{ "id": "count", "type": "list.count" }, { "id": "storeys"|' \
  "$graph" >"$tmp/related/lots.graph.json"
expect_exit 0 "a graph relating lots" "$insula" build "$tmp/related/lots.graph.json" \
  --lot "$tmp/lots.geojson" --crs EPSG:32633 -o "$tmp/r/tileset.json" --report "$tmp/r.json" -q
grep -q '"whole_scene_because": "node '"'"'count'"'"' (list.count) is a list node"' "$tmp/r.json" ||
  { fail "the whole-scene reason"; grep whole "$tmp/r.json"; }
[ -f "$tmp/r/tileset.json" ] || fail "the whole-scene tileset is missing"

# A lots file that does not parse: exit 1, the file named, no tileset and no staging left.
printf '{"type": "FeatureCollection", "features": [' >"$tmp/bad.geojson"
expect_exit 1 "bad lots" "$insula" build "$graph" --lot "$tmp/bad.geojson" --crs EPSG:32633 \
  -o "$tmp/b/tileset.json"
grep -q "bad.geojson" "$tmp/err.txt" || { fail "bad lots: the file is not named"; cat "$tmp/err.txt"; }
[ -e "$tmp/b" ] && fail "bad lots: an output folder was left"
# The lots reader's warnings show, once per file (a repeated vertex, removed: GEO025), in the
# whole-graph run and tile by tile alike.
printf '%s' '{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
  "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 0], [10, 8], [0, 8],
  [0, 0]]]}}]}' >"$tmp/repeated.geojson"
for out in repeated.glb repeated/tileset.json; do
  expect_exit 0 "lots with a repeated vertex, $out" "$insula" build "$graph" \
    --lot "$tmp/repeated.geojson" --crs EPSG:32633 -o "$tmp/$out"
  [ "$(grep -c "warning\[GEO025\]: feature 0: polygon: outer ring: vertex 2 repeats vertex 1" \
    "$tmp/err.txt")" -eq 1 ] || { fail "repeated vertex, $out: not warned once"; cat "$tmp/err.txt"; }
done
finish graph_tiles
