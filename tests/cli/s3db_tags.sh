#!/usr/bin/env bash
# `insula mass` on OpenStreetMap Simple 3D Buildings tags and register attributes, checked on the
# built geometry by feature (docs/osm-buildings.md): heights with units, the roof height taken from
# the total height, parts replacing their outline, parts above ground, colours into materials,
# where each value came from, warnings, overlaps.
source "$(dirname "$0")/lib/common.sh"

data=$root/tests/data/s3db/tags.geojson
expect_exit 0 "mass on S3DB tags" "$insula" mass "$data" -o "$tmp/t.city.json" -o "$tmp/t.obj" \
  -o "$tmp/t.glb" --height-attr hoehe --levels-attr Floors --report "$tmp/r.json" \
  --report-buildings
validate_cityjson "CityJSON schema" "$tmp/t.city.json"
validate_gltf "glTF validator" "$tmp/t.glb"

grep -q "warning\[MAS002\]: feature 8 (id \"tall\"): height='tall' is not a length in (0, 1000) m; using 10 m" \
  "$tmp/err.txt" || fail "unreadable height: one positioned warning naming the default"
grep -q "warning\[MAS007\]: feature 12 (id \"zero_floors\"): Floors='0' is not a level count above 0; using 10 m" \
  "$tmp/err.txt" || fail "zero floors: a warning and the default"

node -e '
const fs = require("fs");
const city = JSON.parse(fs.readFileSync(process.argv[1]));
const report = JSON.parse(fs.readFileSync(process.argv[2]));
const [sx, sy, sz] = city.transform.scale, [, , tz] = city.transform.translate;
const problems = [];
const check = (ok, what) => { if (!ok) problems.push(what); };
const objects = city.CityObjects;
// The z range of an object and its children, and the z of every vertex of each semantic class.
function zs(id) {
  const o = objects[id];
  const out = {min: Infinity, max: -Infinity, wallTops: [], roof: 0, walls: 0};
  for (const g of o.geometry || []) {
    const surfaces = g.semantics ? g.semantics.surfaces : [];
    g.boundaries[0].forEach((face, f) => {
      const value = g.type === "Solid" ? g.semantics.values[0][f] : g.semantics.values[f];
      const kind = value === null ? "" : surfaces[value].type;  // posts have no class
      if (kind === "RoofSurface") out.roof++;
      if (kind === "WallSurface") out.walls++;
      for (const ring of face) for (const v of ring) {
        const z = city.vertices[v][2] * sz + tz;
        out.min = Math.min(out.min, z); out.max = Math.max(out.max, z);
        if (kind === "WallSurface") out.wallTops.push(z);
      }
    });
  }
  for (const child of o.children || []) {
    const c = zs(child);
    out.min = Math.min(out.min, c.min); out.max = Math.max(out.max, c.max);
    out.wallTops.push(...c.wallTops); out.roof += c.roof; out.walls += c.walls;
  }
  return out;
}
const near = (a, b) => Math.abs(a - b) < 1e-3;
// height=12, roof:shape=gabled, roof:height=3: 12 m high, eaves at 9 m, gable walls up to 12 m.
const gabled = zs("gabled");
check(near(gabled.min, 0) && near(gabled.max, 12), "gabled: 0..12 m, got " + gabled.min + ".." + gabled.max);
check(gabled.wallTops.some((z) => near(z, 12)) && gabled.wallTops.some((z) => near(z, 9)),
      "gabled: eave walls end at 9 m and gable walls reach 12 m");
const attrs = objects.gabled.attributes;
check(attrs["insula:eave_height"] === 9 && attrs["insula:height_source"] === "tag" &&
      attrs["insula:roof"] === "gable" && attrs["insula:roof_source"] === "tag" && attrs.height === "12",
      "gabled: where the values came from, beside the input properties");
// building:levels=4, roof:levels=1: 12 m of walls under a 3 m roof.
const levels = zs("levels");
check(near(levels.max, 15) && objects.levels.attributes["insula:height_source"] === "levels", "levels: 15 m");
// The outline is replaced by its parts; the tower part floats 10 m up.
check(!objects.church.geometry || objects.church.geometry.length === 0, "church outline not built");
check((objects.church.children || []).length === 2, "church: two parts, got " + JSON.stringify(objects.church.children));
check(!objects.nave && !objects.tower, "parts are parts of the outline, not buildings");
const church = zs("church");
check(near(church.min, 0) && near(church.max, 30), "church: 0..30 m");
const towerId = objects.church.children.find((c) => zs(c).min > 1);
check(towerId && near(zs(towerId).min, 10) && near(zs(towerId).max, 30), "tower part 10..30 m");
// A part outside every outline is a building of its own, 5 m above the ground.
const bridge = zs("bridge");
check(near(bridge.min, 5) && near(bridge.max, 8), "bridge: 5..8 m, got " + bridge.min + ".." + bridge.max);
// building=roof: a roof on posts, no walls, standing on the ground.
const carport = zs("carport");
check(carport.walls === 0 && carport.roof > 0 && near(carport.min, 0) && near(carport.max, 3),
      "carport: roof on posts, no walls, 0..3 m: " + JSON.stringify({walls: carport.walls, min: carport.min, max: carport.max}));
// 40 ft.
check(near(zs("feet").max, 12.192), "feet: 12.192 m");
// Registers: --height-attr hoehe is the wall height, --levels-attr Floors x 3 m.
check(objects.register.attributes["insula:eave_height"] === 7.5 &&
      objects.register.attributes["insula:height_source"] === "attribute", "register: hoehe");
check(objects.floors.attributes["insula:eave_height"] === 9 &&
      objects.floors.attributes["insula:height_source"] === "levels", "floors: 3 x 3 m");
// The report: overlaps and one entry per building.
check(report.overlaps === 1 && report.largest_overlap.first === "floors" &&
      report.largest_overlap.second === "duplicate" && near(report.largest_overlap.area, 36),
      "one overlapping pair (36 m2): " + JSON.stringify(report.largest_overlap));
const made = report.buildings_made;
check(made.length === report.buildings && made.find((b) => b.id === "church").parts.length === 2,
      "--report-buildings lists every building and the church parts");
check(made.find((b) => b.id === "tall").height_source === "default", "tall: default height");
if (problems.length) { console.log(problems.join("\n")); process.exit(1); }
' "$tmp/t.city.json" "$tmp/r.json" || fail "geometry and attributes by feature"

# Colours become materials: the wall of "gabled" is sienna #a0522d (linear 0.3515 0.0844 0.0273).
grep -A3 "newmtl osm-_a0522d" "$tmp/t.mtl" | grep -q "Kd 0.351" || fail "building:colour into the MTL"
grep -q "newmtl osm-darkred" "$tmp/t.mtl" || fail "roof:colour into the MTL"

# The OpenStreetMap example, read directly: every building closed, the church's outline replaced by
# its three parts, every S3DB roof shape built as tagged.
expect_exit 0 "the OSM example" "$insula" mass "$root/examples/osm/town.osm" -o "$tmp/town.glb" \
  -o "$tmp/town.city.json" --report "$tmp/town.json" --report-buildings --quiet
validate_gltf "glTF validator (OSM example)" "$tmp/town.glb"
validate_cityjson "CityJSON schema (OSM example)" "$tmp/town.city.json"
node -e '
const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
const roofs = new Set();
for (const b of r.buildings_made) for (const p of b.parts || [b]) roofs.add(p.roof);
const want = ["gable", "hip", "pyramid", "half_hipped", "gambrel", "saltbox", "mansard", "dome",
              "round", "onion", "shed", "flat"];
const church = r.buildings_made.find((b) => b.id === "way/2001");
const ok = r.buildings === 15 && r.watertight === 15 && r.failed === 0 && church.parts.length === 3 &&
           want.every((w) => roofs.has(w)) && Object.keys(r.warning_counts).length === 0;
if (!ok) { console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/town.json" || fail "OSM example report"

# An input property the program writes itself (insula:height...) is replaced with a warning
# naming the feature and the property, not silently.
cat >"$tmp/own.geojson" <<'G'
{"type": "Feature", "id": "again", "properties": {"height": 6, "insula:height": 99, "insula:roof": "x"},
 "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}}
G
expect_exit 0 "mass: insula:* input properties" "$insula" mass "$tmp/own.geojson" --roof flat \
  -o "$tmp/own.city.json" --report "$tmp/own.json"
grep -qF "warning[MAS009]: feature 0 (id \"again\"): property 'insula:height' ('99') is replaced by the value insula writes under that name" \
  "$tmp/err.txt" || { fail "insula:height in the input: MAS009"; cat "$tmp/err.txt"; }
[ "$(grep -c 'warning\[MAS009\]' "$tmp/err.txt")" = 2 ] || fail "insula:* in the input: one MAS009 per property"
node -e 'const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.exit(c.CityObjects.again.attributes["insula:height"] === 6 ? 0 : 1);' "$tmp/own.city.json" ||
  fail "insula:height is the built height"

# A map export's areas that are not buildings (landuse, amenity=parking: no building tag) are
# left out of mass and of --lot, with a note naming their tags; an untagged footprint of a
# register (a numeric `area` column) stays a building.
cat >"$tmp/areas.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "house", "properties": {"building": "house", "height": 6},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}},
 {"type": "Feature", "id": "forest", "properties": {"landuse": "forest"},
  "geometry": {"type": "Polygon", "coordinates": [[[-50,-50],[150,-50],[150,150],[-50,150],[-50,-50]]]}},
 {"type": "Feature", "id": "parking", "properties": {"amenity": "parking"},
  "geometry": {"type": "Polygon", "coordinates": [[[20,0],[40,0],[40,15],[20,15],[20,0]]]}},
 {"type": "Feature", "id": "register", "properties": {"area": 80, "height": 5},
  "geometry": {"type": "Polygon", "coordinates": [[[50,0],[60,0],[60,8],[50,8],[50,0]]]}},
 {"type": "Feature", "id": "garage", "properties": {"amenity": "parking", "height": 12},
  "geometry": {"type": "Polygon", "coordinates": [[[70,0],[90,0],[90,15],[70,15],[70,0]]]}}]}
G
expect_exit 0 "mass: map areas" "$insula" mass "$tmp/areas.geojson" --roof flat \
  -o "$tmp/areas.city.json" --report "$tmp/areas.json"
grep -qF "note: 2 map areas that are not a building left out (landuse=forest, amenity=parking; no building or building:part tag)" \
  "$tmp/err.txt" || { fail "map areas: the note"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const c = JSON.parse(require("fs").readFileSync(process.argv[2]));
  const ids = Object.keys(c.CityObjects).filter((k) => c.CityObjects[k].type === "Building").sort();
  process.exit(r.buildings === 3 && r.not_buildings === 2 && ids.join() === "garage,house,register" ? 0 : 1);' \
  "$tmp/areas.json" "$tmp/areas.city.json" ||
  fail "map areas: mass builds the house, the register footprint and the car park with a height only"
expect_exit 0 "build --lot: map areas" "$insula" build "$root/examples/cga/footprints.cga" \
  --lot "$tmp/areas.geojson" --report "$tmp/areas_lots.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.exit(r.lots === 3 ? 0 : 1);' "$tmp/areas_lots.json" || fail "map areas: 3 lots"
grep -qF "note: 2 map areas" "$tmp/err.txt" || fail "map areas: the lots' note"

# A register (no building tags) whose text column is called like an OSM key keeps every footprint.
cat >"$tmp/register.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "r1", "properties": {"landuse": "R1", "height": 7},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}}]}
G
expect_exit 0 "mass: a register's landuse column" "$insula" mass "$tmp/register.geojson" \
  -o "$tmp/register.obj" --report "$tmp/register.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.exit(r.buildings === 1 && r.not_buildings === 0 ? 0 : 1);' "$tmp/register.json" ||
  fail "a register's landuse column: the footprint is built"

# Map areas are left out before their geometry is checked: a self-crossing meadow, a tree row
# thinner than any footprint and a verge whose ring has 3 positions (GEO022, GEO028, GEO010 if
# they were buildings) fail nothing, count as not_buildings rather than invalid, and `check`
# still checks them. The --lot reports count what
# was left out: map areas, an outline its parts replace, a part above the ground.
cat >"$tmp/bad_areas.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "house", "properties": {"building": "house", "height": 6},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[12,0],[12,9],[0,9],[0,0]]]}},
 {"type": "Feature", "id": "church", "properties": {"building": "church"},
  "geometry": {"type": "Polygon", "coordinates": [[[20,0],[40,0],[40,10],[20,10],[20,0]]]}},
 {"type": "Feature", "id": "nave", "properties": {"building:part": "yes", "height": 12},
  "geometry": {"type": "Polygon", "coordinates": [[[20,0],[40,0],[40,10],[20,10],[20,0]]]}},
 {"type": "Feature", "id": "bridge", "properties": {"building:part": "yes", "min_height": 5, "height": 8},
  "geometry": {"type": "Polygon", "coordinates": [[[50,0],[62,0],[62,9],[50,9],[50,0]]]}},
 {"type": "Feature", "id": "meadow", "properties": {"landuse": "meadow"},
  "geometry": {"type": "Polygon", "coordinates": [[[-50,-50],[150,150],[150,-50],[-50,150],[-50,-50]]]}},
 {"type": "Feature", "id": "trees", "properties": {"natural": "tree_row"},
  "geometry": {"type": "Polygon", "coordinates": [[[70,0],[73,0],[73,0.2],[70,0.2],[70,0]]]}},
 {"type": "Feature", "id": "verge", "properties": {"landuse": "grass"},
  "geometry": {"type": "Polygon", "coordinates": [[[80,0],[90,0],[80,0]]]}}]}
G
expect_exit 0 "mass: invalid map areas" "$insula" mass "$tmp/bad_areas.geojson" --roof flat \
  -o "$tmp/bad_areas.city.json" --report "$tmp/bad_areas.json"
grep -qF "note: 3 map areas that are not a building left out (landuse=meadow, natural=tree_row, landuse=grass;" \
  "$tmp/err.txt" || { fail "invalid map areas: the note"; cat "$tmp/err.txt"; }
grep -q "GEO0[12]" "$tmp/err.txt" && fail "invalid map areas: their geometry is not checked"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.exit(r.buildings === 3 && r.not_buildings === 3 && r.invalid === 0 ? 0 : 1);' \
  "$tmp/bad_areas.json" || { fail "invalid map areas: mass report"; cat "$tmp/bad_areas.json"; }
# `check`: the verge's error while reading; without the verge, the others' geometry errors.
expect_exit 1 "check: invalid map areas" "$insula" check "$tmp/bad_areas.geojson"
grep -q "error\[GEO010\]: feature 6 (id \"verge\")" "$tmp/err.txt" ||
  { fail "check: the verge is read"; cat "$tmp/err.txt"; }
node -e 'const fs = require("fs"); const c = JSON.parse(fs.readFileSync(process.argv[1]));
  c.features.pop(); fs.writeFileSync(process.argv[2], JSON.stringify(c));' \
  "$tmp/bad_areas.geojson" "$tmp/bad_areas_read.geojson"
expect_exit 1 "check: invalid map areas' geometry" "$insula" check "$tmp/bad_areas_read.geojson"
grep -q "error\[GEO022\]: feature 4 (id \"meadow\")" "$tmp/err.txt" &&
  grep -q "error\[GEO028\]: feature 5 (id \"trees\")" "$tmp/err.txt" ||
  { fail "check: every feature is checked"; cat "$tmp/err.txt"; }
lots_left='r.not_buildings === 3 && r.replaced_outlines === 1 && r.elevated_lots === 1 && r.invalid_lots === 0'
expect_exit 0 "build --lot: invalid map areas" "$insula" build "$root/examples/cga/district.cga" \
  --lot "$tmp/bad_areas.geojson" --report "$tmp/bad_lots.json" -o "$tmp/bad_lots.obj"
node -e "const r = JSON.parse(require('fs').readFileSync(process.argv[1]));
  process.exit(r.lots === 2 && $lots_left ? 0 : 1);" "$tmp/bad_lots.json" ||
  { fail "build --lot: the report counts the lots left out"; cat "$tmp/bad_lots.json"; }
expect_exit 0 ".bldg village: map areas" "$insula" build "$root/examples/bldg/village/village.bldg" \
  --lot "$tmp/bad_areas.geojson" --report "$tmp/bad_village.json" -o "$tmp/bad_village.glb"
node -e "const r = JSON.parse(require('fs').readFileSync(process.argv[1]));
  process.exit(r.buildings.length === 2 && $lots_left ? 0 : 1);" "$tmp/bad_village.json" ||
  fail ".bldg village: the report counts the lots left out"
expect_exit 0 "graph: map areas" "$insula" build "$root/examples/graph/city/lots.graph.json" \
  --lot "$tmp/bad_areas.geojson" --report "$tmp/bad_graph.json" -o "$tmp/bad_graph.obj" -q
node -e "const r = JSON.parse(require('fs').readFileSync(process.argv[1]));
  process.exit(r.buildings > 0 && $lots_left ? 0 : 1);" "$tmp/bad_graph.json" ||
  fail "graph: the report counts the lots left out"

# Longitude/latitude: a forest of three polygons, each wider than 0.05 degrees, outvoted the two
# buildings, and the file was read as meters (every building a sliver). Map areas do not vote.
cat >"$tmp/lonlat_areas.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "house", "properties": {"building": "house", "height": 6},
  "geometry": {"type": "Polygon", "coordinates": [[[9.52,47.14],[9.5202,47.14],[9.5202,47.1401],[9.52,47.1401],[9.52,47.14]]]}},
 {"type": "Feature", "id": "barn", "properties": {"building": "barn"},
  "geometry": {"type": "Polygon", "coordinates": [[[9.521,47.14],[9.5212,47.14],[9.5212,47.1401],[9.521,47.1401],[9.521,47.14]]]}},
 {"type": "Feature", "id": "forest", "properties": {"landuse": "forest"},
  "geometry": {"type": "MultiPolygon", "coordinates": [
   [[[9.40,47.00],[9.50,47.00],[9.50,47.10],[9.40,47.10],[9.40,47.00]]],
   [[[9.55,47.00],[9.65,47.00],[9.65,47.10],[9.55,47.10],[9.55,47.00]]],
   [[[9.40,47.20],[9.50,47.20],[9.50,47.30],[9.40,47.30],[9.40,47.20]]]]}}]}
G
expect_exit 0 "mass: lon/lat beside big map areas" "$insula" mass "$tmp/lonlat_areas.geojson" \
  -o "$tmp/lonlat_areas.obj" --report "$tmp/lonlat_areas.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.exit(r.buildings === 2 && r.not_buildings === 1 && r.crs === "EPSG:32632" &&
               r.reprojected_from === "OGC:CRS84" ? 0 : 1);' "$tmp/lonlat_areas.json" ||
  { fail "lon/lat beside big map areas: reprojected from degrees"; cat "$tmp/lonlat_areas.json"; }
expect_exit 0 "check: lon/lat beside big map areas" "$insula" check "$tmp/lonlat_areas.geojson"
grep -qF "(reprojected from OGC:CRS84)" "$tmp/out.txt" || fail "check: decides degrees as mass does"

# An outline replaced by its parts keeps none of its input insula:* properties (MAS009 says they
# are replaced): its height is the parts' top.
cat >"$tmp/joined.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "church", "properties": {"building": "church", "insula:roof": "x", "insula:height": 99},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[20,0],[20,10],[0,10],[0,0]]]}},
 {"type": "Feature", "id": "nave", "properties": {"building:part": "yes", "height": 12},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[20,0],[20,10],[0,10],[0,0]]]}}]}
G
expect_exit 0 "mass: an outline's insula:* properties" "$insula" mass "$tmp/joined.geojson" \
  --roof flat -o "$tmp/joined.city.json"
node -e 'const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const a = c.CityObjects.church.attributes;
  process.exit(a["insula:height"] === 12 && !("insula:roof" in a) ? 0 : 1);' "$tmp/joined.city.json" ||
  fail "an outline replaced by its parts: insula:* replaced"

# A footprint larger than any building (1.44 km2 here) is built, with warning MAS010 saying so.
cat >"$tmp/vast.geojson" <<'G'
{"type": "Feature", "id": "what", "properties": {"FIXME": "what is this?"},
 "geometry": {"type": "Polygon", "coordinates": [[[0,0],[1200,0],[1200,1200],[0,1200],[0,0]]]}}
G
expect_exit 0 "mass: a vast footprint" "$insula" mass "$tmp/vast.geojson" --roof flat -o "$tmp/vast.obj"
grep -qF 'warning[MAS010]: feature 0 (id "what"): a footprint of 1.44 km2, larger than any building' \
  "$tmp/err.txt" || { fail "vast footprint: MAS010"; cat "$tmp/err.txt"; }

finish s3db_tags
