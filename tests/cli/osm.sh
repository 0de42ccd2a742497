#!/usr/bin/env bash
# `insula mass` and `insula build --lot` on OpenStreetMap files (docs/osm.md): .osm and .osm.pbf
# (converted here by osmium-tool) give the same buildings, in UTM 33N; broken elements give one
# error naming the element and exit 1 with no output, or with --keep-going a warning and the good
# buildings; a truncated .osm.pbf fails whatever --keep-going says.
source "$(dirname "$0")/lib/common.sh"

osm=$root/tests/data/osm
osmium cat -O -o "$tmp/b.osm.pbf" "$osm/buildings.osm" || fail "osmium cat"

for input in "$osm/buildings.osm" "$tmp/b.osm.pbf"; do
  name=$(basename "$input")
  expect_exit 0 "mass $name" "$insula" mass "$input" -o "$tmp/$name.city.json" -o "$tmp/$name.obj" \
    --report "$tmp/$name.json" --quiet
  node -e '
    const fs = require("fs");
    const r = JSON.parse(fs.readFileSync(process.argv[1]));
    const c = JSON.parse(fs.readFileSync(process.argv[2]));
    const ids = Object.keys(c.CityObjects).filter((id) => c.CityObjects[id].type !== "BuildingPart").sort();
    const attrs = c.CityObjects["way/101"] && c.CityObjects["way/101"].attributes;
    // way/121 is a building:part inside way/101: S3DB builds the part instead of the outline, as
    // the one part of building way/101 (docs/osm-buildings.md).
    const children = c.CityObjects["way/101"] && c.CityObjects["way/101"].children;
    const ok = r.buildings === 3 && r.watertight === 3 && r.crs === "EPSG:32633" &&
               c.metadata.referenceSystem === "https://www.opengis.net/def/crs/EPSG/0/32633" &&
               ids.join() === "relation/201,relation/202,way/101" &&
               children && children.length === 1 && /way\/121$/.test(children[0]) &&
               attrs && attrs["roof:shape"] === "gabled" && attrs["osm_id"] === "101";
    if (!ok) { console.log(JSON.stringify(r), ids, JSON.stringify(attrs)); process.exit(1); }' \
    "$tmp/$name.json" "$tmp/$name.city.json" || fail "mass $name: report and CityJSON"
done
diff <(grep -v '^mtllib' "$tmp/buildings.osm.obj") <(grep -v '^mtllib' "$tmp/b.osm.pbf.obj") >/dev/null ||
  fail ".osm and .osm.pbf give different OBJ"

# Lots from a .osm.pbf (tags are strings: this grammar reads none). way/101's building:part
# way/121 starts 5 m above the ground (min_height): a lot is built from the ground, so the part
# is left out, and the outline, which no part on the ground replaces, is a lot.
printf 'Lot --> extrude(6) Mass\n' >"$tmp/lots.cga"
expect_exit 0 "build --lot pbf" "$insula" build "$tmp/lots.cga" --lot "$tmp/b.osm.pbf" \
  --report "$tmp/lots.json" -o "$tmp/lots.obj" -q
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.lots !== 3) { console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/lots.json" ||
  fail "build --lot pbf: 3 lots"
expect_exit 0 "build --lot pbf, the note" "$insula" build "$tmp/lots.cga" --lot "$tmp/b.osm.pbf" \
  -o "$tmp/lots2.obj"
grep -qx "note: 1 building or part above the ground (min_height, building:min_level) left out: lots are built from the ground" \
  "$tmp/err.txt" || fail "build --lot pbf: the note on the part left out: $(cat "$tmp/err.txt")"
grep -q "^o way/121" "$tmp/lots2.obj" && fail "build --lot pbf: the raised part way/121 was built"
# OSM tags are text; an attr declared with a number takes a tag such as height=12 as 12.
printf 'attr height = 7\nLot --> extrude(height) Mass\n' >"$tmp/heights.cga"
expect_exit 0 "build --lot osm, numeric tags" "$insula" build "$tmp/heights.cga" --lot "$osm/buildings.osm" \
  -o "$tmp/heights.city.json" -q
node -e '
  const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const top = (id) => {
    let max = -Infinity;
    const walk = (x) => (typeof x === "number" ? (max = Math.max(max, c.vertices[x][2] * c.transform.scale[2] + c.transform.translate[2])) : x.forEach(walk));
    for (const child of c.CityObjects[id].children) for (const g of c.CityObjects[child].geometry) walk(g.boundaries);
    return max;
  };
  if (Math.abs(top("way/101") - 12) > 1e-3 || Math.abs(top("relation/202") - 7) > 1e-3) {
    console.log(top("way/101"), top("relation/202")); process.exit(1);
  }' "$tmp/heights.city.json" || fail "build --lot osm: height=12 extrudes 12 m, no height 7 m"
# A graph's create.lots reads the same OpenStreetMap file.
cat >"$tmp/lots.graph.json" <<'JSON'
{ "format": "insula-graph", "version": 1,
  "nodes": [ { "id": "lots", "type": "create.lots" },
             { "id": "mass", "type": "shape.extrude", "params": { "height": 6 } } ],
  "edges": [ "lots.out -> mass.in" ] }
JSON
expect_exit 0 "graph build --lot osm" "$insula" build "$tmp/lots.graph.json" --lot "$tmp/b.osm.pbf" \
  --report "$tmp/graph.json" -o "$tmp/graph.obj" -q
grep -c "^o " "$tmp/graph.obj" | grep -qx 3 || fail "graph build --lot osm: 3 lots extruded"
# Every --lot front-end's report says the lots were reprojected from lon/lat, as mass's does.
for report in "$tmp/lots.json" "$tmp/graph.json"; do
  node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
           if (r.reprojected_from !== "OGC:CRS84") process.exit(1);' "$report" ||
    fail "$report: no reprojected_from OGC:CRS84"
done
# OSM tags as a graph's attributes: building:levels is attribute building_levels, and its text
# "4" a number (as for CGA attrs and mass models); one storey of 3 m by default.
cat >"$tmp/levels.graph.json" <<'JSON'
{ "format": "insula-graph", "version": 1,
  "attributes": { "building_levels": { "type": "number", "default": 1 } },
  "nodes": [ { "id": "lots", "type": "create.lots" },
             { "id": "mass", "type": "shape.extrude", "params": { "height": "= @building_levels * 3" } } ],
  "edges": [ "lots.out -> mass.in" ] }
JSON
printf '%s' '{"type": "FeatureCollection", "features": [{"type": "Feature",
  "properties": {"building:levels": "4"}, "geometry": {"type": "Polygon",
  "coordinates": [[[0, 0], [10, 0], [10, 8], [0, 8], [0, 0]]]}}]}' >"$tmp/levels.geojson"
expect_exit 0 "graph: OSM tags as attributes" "$insula" build "$tmp/levels.graph.json" \
  --lot "$tmp/levels.geojson" --crs EPSG:32633 -o "$tmp/levels.obj"
awk '/^v /{ if ($3 > top) top = $3 } END { exit !(top > 11.999 && top < 12.001) }' "$tmp/levels.obj" ||
  fail "graph: building:levels=4 extrudes 12 m"
grep -q "W030" "$tmp/err.txt" && fail "graph: OSM tags as attributes: $(cat "$tmp/err.txt")"
expect_exit 0 "bldg build --lot osm" "$insula" build "$root/examples/bldg/two_storey.bldg" \
  --lot "$osm/buildings.osm" -o "$tmp/bldg.obj" -q

# The footprints example on the town: each OSM building is built on its own outline, its tags
# read by their identifier spelling (height=66' is 20.1168 m, plus a 0.6 m parapet on its flat
# roof), the church's outline replaced by its parts, the bridge (min_height=6) left out; no
# warnings.
expect_exit 0 "footprints.cga on the OSM town" "$insula" build "$root/examples/cga/footprints.cga" \
  --lot "$root/examples/osm/town.osm" -o "$tmp/fp.glb" -o "$tmp/fp.city.json" --report "$tmp/fp.json"
grep -qx "note: 1 building outline left out: the building:parts inside it are built instead (Simple 3D Buildings)" \
  "$tmp/err.txt" || fail "footprints.cga: the note on the church outline"
grep -q "^note: 1 building or part above the ground" "$tmp/err.txt" ||
  fail "footprints.cga: the note on the bridge"
grep -q "warning" "$tmp/err.txt" && fail "footprints.cga: warnings: $(cat "$tmp/err.txt")"
node -e '
  const fs = require("fs");
  const r = JSON.parse(fs.readFileSync(process.argv[1]));
  const c = JSON.parse(fs.readFileSync(process.argv[2]));
  const top = (id) => {
    let max = -Infinity;
    const walk = (x) => (typeof x === "number" ? (max = Math.max(max, c.vertices[x][2] * c.transform.scale[2] + c.transform.translate[2])) : x.forEach(walk));
    for (const child of c.CityObjects[id].children) for (const g of c.CityObjects[child].geometry) walk(g.boundaries);
    return max;
  };
  // 18 footprints, less the church outline and the bridge; 2 flat roofs (a deck each), every
  // other roof pitched.
  if (r.lots !== 16 || r.symbols.RoofDeck !== 2 || Math.abs(top("way/2015") - (66 * 0.3048 + 0.6)) > 2e-3) {
    console.log(r.lots, JSON.stringify(r.symbols), top("way/2015")); process.exit(1);
  }' "$tmp/fp.json" "$tmp/fp.city.json" || fail "footprints.cga: lots, flat roofs, the 66-foot office"
validate_gltf "footprints.cga GLB" "$tmp/fp.glb"
validate_cityjson "footprints.cga CityJSON" "$tmp/fp.city.json"

# Broken elements: the error names the element; --keep-going keeps the good building.
for broken in missing_node:OSM003:"way 102" unclosed_multipolygon:OSM004:"relation 203" open_way:OSM002:"way 104"; do
  IFS=: read -r file code element <<<"$broken"
  expect_exit 1 "$file" "$insula" mass "$osm/$file.osm" -o "$tmp/$file.obj"
  grep -qF "$file.osm: error[$code]: $element: " "$tmp/err.txt" || { fail "$file: message"; cat "$tmp/err.txt"; }
  [ -e "$tmp/$file.obj" ] && fail "$file: partial output"
  expect_exit 0 "$file --keep-going" "$insula" mass "$osm/$file.osm" -o "$tmp/$file.obj" --keep-going \
    --report "$tmp/$file.json"
  grep -qF "$file.osm: warning[$code]: $element: " "$tmp/err.txt" || { fail "$file: warning"; cat "$tmp/err.txt"; }
  node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
           if (r.buildings !== 1 || r.invalid !== 1) { console.log(JSON.stringify(r)); process.exit(1); }' \
    "$tmp/$file.json" || fail "$file --keep-going: 1 building, 1 invalid"
done

# `check` reads as mass does.
expect_exit 0 "check osm" "$insula" check "$tmp/b.osm.pbf"
grep -qx "$tmp/b.osm.pbf: ok: 4 footprints, in EPSG:32633 (reprojected from OGC:CRS84)" "$tmp/out.txt" ||
  { fail "check osm: summary"; cat "$tmp/out.txt"; }
expect_exit 1 "check broken osm" "$insula" check "$osm/missing_node.osm"
grep -qF "missing_node.osm: error[OSM003]: way 102: " "$tmp/err.txt" || { fail "check broken osm: message"; cat "$tmp/err.txt"; }

# A truncated .osm.pbf: one error, exit 1, no output, even with --keep-going.
head -c 300 "$tmp/b.osm.pbf" >"$tmp/cut.osm.pbf"
expect_exit 1 "truncated pbf" "$insula" mass "$tmp/cut.osm.pbf" -o "$tmp/cut.obj" --keep-going
grep -qF "cut.osm.pbf: error[OSM001]: not a valid .osm.pbf file (truncated or damaged?)" "$tmp/err.txt" ||
  { fail "truncated pbf: message"; cat "$tmp/err.txt"; }
[ -e "$tmp/cut.obj" ] && fail "truncated pbf: partial output"

finish osm
