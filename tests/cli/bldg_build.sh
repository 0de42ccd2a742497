#!/usr/bin/env bash
# End-to-end test of `insula build FILE.bldg`: every example of examples/bldg/ to every format,
# checked by the third-party validators (glTF, CityJSON schema, assimp), the report's fields, the
# SVG floor plans, a village built on lots, determinism, and errors that leave no output.
source "$(dirname "$0")/lib/common.sh"
examples=$root/examples/bldg

names=()
for file in "$examples"/*.bldg; do
  name=$(basename "$file" .bldg)
  names+=("$name")
  out=$tmp/$name
  expect_exit 0 "build $name" "$insula" build "$file" -o "$out.glb" -o "$out.city.json" \
    -o "$out.obj" -o "$out.svg" -o "$out.png" --image-size 320x240 --report "$out.json" --quiet
  for f in "$out.glb" "$out.city.json" "$out.obj" "$out.mtl" "$out.svg" "$out.png" "$out.json"; do
    [ -s "$f" ] || fail "$name: missing output $(basename "$f")"
  done
  assimp_info "$name: assimp info obj" "$out.obj"
done
# Third-party validators, every example in one run each.
validate_gltf "glTF validator" "$tmp"/*.glb
validate_cityjson "CityJSON schema" "$tmp"/*.city.json
# Per example: the report (every room with its fields, every room reachable, counts, timings),
# the plan (a panel per storey, every room labelled) and the CityJSON objects (a BuildingRoom per
# room, a BuildingStorey per storey, interior surfaces, doors and windows).
node -e '
  const fs = require("fs");
  const [dir, ...names] = process.argv.slice(1);
  let failed = false;
  for (const name of names) {
    const r = JSON.parse(fs.readFileSync(`${dir}/${name}.json`));
    const c = JSON.parse(fs.readFileSync(`${dir}/${name}.city.json`));
    const svg = fs.readFileSync(`${dir}/${name}.svg`, "utf8");
    const problems = [];
    if (!Array.isArray(r.rooms) || r.rooms.length === 0) problems.push("rooms");
    for (const room of r.rooms || []) {
      for (const k of ["name", "type", "storey", "area", "neighbors", "floor_area"])
        if (!(k in room)) problems.push("room field " + k);
      if (!(room.floor_area > 0 && room.floor_area < room.area)) problems.push("floor_area of " + room.name);
      if (!svg.includes(`>${room.name}</text>`)) problems.push("room " + room.name + " not labelled in the plan");
    }
    for (const k of ["doors", "windows", "entrances", "unreachable_rooms", "stairs"])
      if (!Array.isArray(r[k])) problems.push(k);
    if ((r.unreachable_rooms || []).length !== 0) problems.push("unreachable rooms");
    if ((r.entrances || []).length < 1) problems.push("no entrance");
    if (!(r.vertices > 0 && r.triangles > 0)) problems.push("vertices/triangles");
    for (const k of ["total", "parse", "floor_plan", "build", "walls", "slabs", "roofs", "write_glb"])
      if (typeof (r.seconds || {})[k] !== "number") problems.push("seconds." + k);
    if (r.counts.rooms !== r.rooms.length) problems.push("counts.rooms");
    const panels = (svg.match(/class="storey"/g) || []).length;
    if (panels !== r.storeys) problems.push(`${panels} plan panels for ${r.storeys} storeys`);
    const objects = Object.values(c.CityObjects);
    const count = (t) => objects.filter((o) => o.type === t).length;
    const types = new Set();
    for (const o of objects) for (const g of o.geometry || []) for (const s of (g.semantics || {}).surfaces || []) types.add(s.type);
    if (count("BuildingRoom") !== r.rooms.length) problems.push("CityJSON rooms " + count("BuildingRoom"));
    if (count("BuildingStorey") !== r.storeys) problems.push("CityJSON storeys " + count("BuildingStorey"));
    for (const t of ["FloorSurface", "CeilingSurface", "InteriorWallSurface", "Door", "Window", "RoofSurface", "WallSurface"])
      if (!types.has(t)) problems.push("CityJSON: no " + t);
    if (problems.length) { console.log(`FAIL: ${name}: ${problems.join(", ")}`); failed = true; }
  }
  process.exit(failed ? 1 : 0);' "$tmp" "${names[@]}" || fail "report, plan or CityJSON content"

# The two-storey house: a stair between the storeys, two plan panels.
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.storeys !== 2 || r.stairs.length !== 1 || r.counts.stairs !== 1) process.exit(1);' \
  "$tmp/two_storey.json" || fail "two_storey: one stair between two storeys"
grep -q 'class="stair"' "$tmp/two_storey.svg" || fail "two_storey: stair drawn in the plan"
# Fig. 10: each merged roof is one roof.
for shape in u t s h; do
  node -e 'if (JSON.parse(require("fs").readFileSync(process.argv[1])).counts.roofs !== 1) process.exit(1);' \
    "$tmp/roofs_$shape.json" || fail "roofs_$shape: one merged HipGlued roof"
done

# Same input, same bytes.
expect_exit 0 "rebuild" "$insula" build "$examples/domus.bldg" -o "$tmp/again.glb" -o "$tmp/again.city.json" --quiet
cmp -s "$tmp/domus.glb" "$tmp/again.glb" || fail "domus GLB differs between runs"
cmp -s "$tmp/domus.city.json" "$tmp/again.city.json" || fail "domus CityJSON differs between runs"

# The village: one building per lot, each lot's grammar from its "bldg" property.
village=$examples/village
expect_exit 0 "village" "$insula" build "$village/village.bldg" --lot "$village/village.geojson" \
  -o "$tmp/village.glb" -o "$tmp/village.city.json" --report "$tmp/village.json" --quiet
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.buildings.length !== 27 || r.unreachable_rooms.length !== 0 ||
             !r.rooms.every((room) => typeof room.building === "string")) process.exit(1);' \
  "$tmp/village.json" || fail "village: 27 buildings, all rooms reachable"
validate_gltf "village: glTF validator" "$tmp/village.glb"
validate_cityjson "village: CityJSON schema" "$tmp/village.city.json"

# Lots: warnings name the lot (index and id, on stderr and in the report); on an L-shaped block
# every room is reachable, doors keep 0.9 m and entrances 1.0 m.
printf '{"type": "FeatureCollection", "features": [%s, %s]}' \
  '{"type": "Feature", "id": "plain", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 10], [0, 10], [0, 0]]]}}' \
  '{"type": "Feature", "id": "corner", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [40, 0], [40, 10], [30, 10], [30, 20], [20, 20], [20, 0]]]}}' \
  >"$tmp/l_lots.geojson"
expect_exit 0 "L lot" "$insula" build "$examples/two_storey.bldg" --lot "$tmp/l_lots.geojson" \
  -o "$tmp/l_lot.svg" --report "$tmp/l_lot.json"
grep -q 'warning\[BLD60[01]\]: lot 1 (id "corner"): ' "$tmp/err.txt" || { fail "L lot: warnings name the lot"; cat "$tmp/err.txt"; }
grep 'warning' "$tmp/err.txt" | grep -qv 'warning\[BLD60[0-3]\]: lot [01] (id "[a-z]*"): ' &&
  { fail "L lot: a warning without its lot"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         const corner = r.buildings[1];
         if (corner.id !== "corner" || corner.warnings.length === 0 ||
             !r.warnings.some((w) => w.startsWith("lot 1 (id \"corner\"): ")) ||
             r.unreachable_rooms.length !== 0 || !r.doors.every((d) => d.width === 0.9) ||
             !r.entrances.every((d) => d.width === 1)) process.exit(1);' "$tmp/l_lot.json" ||
  fail "L lot: report names the lot, all rooms reachable, doors 0.9 m, entrances 1.0 m"

# A lot's properties (an OpenStreetMap hospital's tags) are the building's attributes, as with CGA
# and mass; the feature's name replaces the grammar's building name ("Village house").
printf '{"type": "FeatureCollection", "features": [%s]}' \
  '{"type": "Feature", "id": "way/1", "properties": {"building": "hospital", "amenity": "hospital", "name": "Saint Anne", "beds": 40}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [14, 0], [14, 10], [0, 10], [0, 0]]]}}' \
  >"$tmp/tagged_lot.geojson"
expect_exit 0 "tagged lot" "$insula" build "$examples/village/village.bldg" \
  --lot "$tmp/tagged_lot.geojson" -o "$tmp/tagged.city.json" -o "$tmp/tagged.glb" --quiet
node -e 'const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
         const a = c.CityObjects["way/1"].attributes;
         if (a.building !== "hospital" || a.amenity !== "hospital" || a.name !== "Saint Anne" ||
             a.beds !== 40) { console.log(JSON.stringify(a)); process.exit(1); }' \
  "$tmp/tagged.city.json" || fail "tagged lot: the feature's properties are the building's attributes"
grep -aq '"amenity"' "$tmp/tagged.glb" || fail "tagged lot: no amenity column in the GLB's property table"

# A lot that cannot hold the grammar (a strip 0.9 m wide holds no room of the minimum width):
# an error naming the lot without --keep-going; with it, skipped with its reason and counted, the
# other lot built (docs/bldg-floorplan.md, "Rooms that fit").
printf '{"type": "FeatureCollection", "features": [%s, %s]}' \
  '{"type": "Feature", "id": "plain", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [12, 0], [12, 10], [0, 10], [0, 0]]]}}' \
  '{"type": "Feature", "id": "strip", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[20, 0], [20.9, 0], [20.9, 30], [20, 30], [20, 0]]]}}' \
  >"$tmp/strip_lots.geojson"
expect_exit 1 "strip lot" "$insula" build "$examples/two_storey.bldg" --lot "$tmp/strip_lots.geojson" \
  -o "$tmp/strip.glb"
grep -q 'error\[PLAN007\]: the lot cannot hold this grammar: no room of 2.00 m² and 1.00 m wide fits on storey 0' "$tmp/err.txt" &&
  grep -q 'lot 1 (id "strip") cannot be built; --keep-going skips such lots' "$tmp/err.txt" ||
  { fail "strip lot: PLAN007 names the reason and the lot"; cat "$tmp/err.txt"; }
[ -e "$tmp/strip.glb" ] && fail "strip lot: output written after an error"
expect_exit 0 "strip lot --keep-going" "$insula" build "$examples/two_storey.bldg" \
  --lot "$tmp/strip_lots.geojson" --keep-going -o "$tmp/strip.glb" --report "$tmp/strip.json"
grep -q 'warning\[BLD603\]: lot 1 (id "strip"): skipped: the lot cannot hold this grammar: no room' "$tmp/err.txt" ||
  { fail "strip lot --keep-going: BLD603 names the lot and the reason"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         const s = r.skipped_lots;
         if (r.buildings.length !== 1 || r.buildings[0].id !== "plain" || s.length !== 1 ||
             s[0].id !== "strip" || s[0].feature !== 1 || !s[0].reason.includes("no room of 2.00 m²") ||
             typeof r.adaptations.rooms_merged !== "number" ||
             typeof r.buildings[0].adaptations.doors_added !== "number")
           process.exit(1);' "$tmp/strip.json" ||
  fail "strip lot --keep-going: one building, one skipped lot with its reason, adaptations counted"

# Restriction rules change the model: thicker outer walls give less floor area.
printf 'outer_wall_thickness = 0.6\ncolor.RoofSurface = "#336699"\n' >"$tmp/thick.rules"
expect_exit 0 "rules" "$insula" build "$examples/two_storey.bldg" --rules "$tmp/thick.rules" --report "$tmp/thick.json" --quiet
node -e 'const fs = require("fs");
         const a = JSON.parse(fs.readFileSync(process.argv[1])), b = JSON.parse(fs.readFileSync(process.argv[2]));
         const sum = (r) => r.rooms.reduce((s, room) => s + room.floor_area, 0);
         if (!(sum(b) < sum(a) - 1)) process.exit(1);' "$tmp/two_storey.json" "$tmp/thick.json" ||
  fail "--rules: thicker outer walls leave less floor area"

# Errors: file:line:col, exit 1, nothing written.
printf 'b -> building("x", [(0, 0), (1, 0), (1, 1)]) : {p}\np -> buildingpart(Hip, 3) : {f}\nf -> floor() : {r}\nr -> room(kitchen, huge)\n' >"$tmp/bad.bldg"
expect_exit 1 "malformed grammar" "$insula" build "$tmp/bad.bldg" -o "$tmp/bad.glb" --report "$tmp/bad.json"
grep -q "bad.bldg:4:[0-9]*: error" "$tmp/err.txt" || { fail "malformed grammar: file:line:col"; cat "$tmp/err.txt"; }
[ -e "$tmp/bad.glb" ] || [ -e "$tmp/bad.json" ] && fail "malformed grammar: output written"
printf 'h -> building("x", geojson("lots.geojson", "nope")) : {p}\np -> buildingpart(Hip, 3) : {f}\nf -> floor() : {r}\nr -> room(kitchen, medium, 4, 1, true)\n' >"$tmp/lot.bldg"
printf '{"type": "FeatureCollection", "features": [{"type": "Feature", "id": "a", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 8], [0, 8], [0, 0]]]}}]}' >"$tmp/lots.geojson"
expect_exit 1 "missing feature" "$insula" build "$tmp/lot.bldg" -o "$tmp/lot.glb"
grep -q "lot.bldg:1:[0-9]*: error.*no feature 'nope'" "$tmp/err.txt" || { fail "missing feature: message"; cat "$tmp/err.txt"; }
[ -e "$tmp/lot.glb" ] && fail "missing feature: output written"
sed -i 's/"nope"/"a"/' "$tmp/lot.bldg"
expect_exit 0 "outline from a GeoJSON feature" "$insula" build "$tmp/lot.bldg" -o "$tmp/lot.glb" --report "$tmp/lot.json" --quiet
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (Math.abs(r.rooms[0].area - 80) > 1e-6) process.exit(1);' "$tmp/lot.json" ||
  fail "outline from a GeoJSON feature: one 10 x 8 room"
printf 'storey_height = 1\n' >"$tmp/bad.rules"
expect_exit 1 "bad rules" "$insula" build "$examples/two_storey.bldg" --rules "$tmp/bad.rules" -o "$tmp/r.glb"
grep -q "bad.rules:1:[0-9]*: error" "$tmp/err.txt" || { fail "bad rules: file:line:col"; cat "$tmp/err.txt"; }
[ -e "$tmp/r.glb" ] && fail "bad rules: output written"
expect_exit 1 "missing input" "$insula" build "$tmp/none.bldg" -o "$tmp/n.glb"
expect_exit 2 "unknown output format" "$insula" build "$examples/domus.bldg" -o "$tmp/x.xyz"

finish bldg_build
