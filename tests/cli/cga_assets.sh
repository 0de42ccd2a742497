#!/usr/bin/env bash
# Assets in a CityEngine project layout (docs/assets.md): a GLB made by `insula build` is
# inserted by a rule file in rules/ from the project's assets/ folder, by a workspace path and
# under --workspace; a missing asset is one AST100 warning for all its inserts and the model is
# still made, without the inserts.
source "$(dirname "$0")/lib/common.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }
# The bounding box of an OBJ's vertices, rounded to mm: "minx miny minz maxx maxy maxz".
bbox() {
  python3 -c "
import sys
v=[list(map(float,l.split()[1:4])) for l in open(sys.argv[1]) if l.startswith('v ')]
print(' '.join('%.3f' % f(c[i] for c in v) for f in (min, max) for i in range(3)))" "$1"
}

ws=$tmp/ws
mkdir -p "$ws/City/rules" "$ws/City/assets/doors" "$ws/Lib/assets"

# The asset: a 1 x 2 m box 3 m high, made by Insula itself and written as GLB (y up).
cat >"$tmp/box.cga" <<'EOF'
Lot --> s(1, 2, 0) extrude(3) Box
EOF
"$insula" build "$tmp/box.cga" -o "$ws/City/assets/doors/door.glb" -q >/dev/null ||
  fail "building the GLB asset"
cp "$ws/City/assets/doors/door.glb" "$ws/Lib/assets/lib_door.glb"

# Two 10 x 10 lots; on each, assets inserted into 2 x 4 x 0.5 scopes on the top of a 1 m base.
cat >"$ws/City/rules/street.cga" <<'EOF'
Lot --> extrude(1) comp(f) { top : Top | side : Base | bottom : Base }
Top --> split(x) { 1 : Gap | 2 : Door | 2 : Gap | 2 : Missing | 1 : Gap | 2 : Lib }
Gap --> NIL
Door --> s('1, 4, 0.5) i("doors/door.glb")
Missing --> s('1, 4, 0.5) i("doors/none.glb")
Lib --> s('1, 4, 0.5) i("/Lib/assets/lib_door.glb")
EOF
cat >"$tmp/lot.geojson" <<'EOF'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
  "coordinates": [[[0, 0], [10, 0], [10, 10], [0, 10], [0, 0]]]}},
 {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
  "coordinates": [[[20, 0], [30, 0], [30, 10], [20, 10], [20, 0]]]}}]}
EOF
"$insula" build "$ws/City/rules/street.cga" --lot "$tmp/lot.geojson" -o "$tmp/street.obj" \
  --obj-world -o "$tmp/street.glb" -o "$tmp/street.png" --report "$tmp/street.json" --threads 2 \
  2>"$tmp/err" >/dev/null || fail "street build: $(cat "$tmp/err")"
[ "$(grep -c 'AST100' "$tmp/err")" = 1 ] ||
  fail "one AST100 warning for two inserts: $(cat "$tmp/err")"
grep -q "street.cga: warning\[AST100\]: asset 'doors/none.glb' not found (looked in .*/City/rules/doors/none.glb, .*/City/assets/doors/none.glb, .*/City/doors/none.glb); asked for 2 times, inserted nothing" "$tmp/err" ||
  fail "AST100 text: $(cat "$tmp/err")"
[ "$(json "$tmp/street.json" 'd["missing_assets"]')" = "{'doors/none.glb': 2}" ] ||
  fail "report missing_assets: $(json "$tmp/street.json" 'd.get("missing_assets")')"
[ -s "$tmp/street.png" ] || fail "PNG written"
validate_gltf "street GLB with inserted GLB assets" "$tmp/street.glb"
# The inserted boxes stand 0.5 m (scope z, the top face's normal) on the 1 m base.
[ "$(bbox "$tmp/street.obj")" = "0.000 0.000 0.000 30.000 10.000 1.500" ] ||
  fail "street bbox $(bbox "$tmp/street.obj")"
[ "$(json "$tmp/street.json" 'd["symbols"].get("Door", 0), d["symbols"].get("Missing", 0)')" = "2 2" ] ||
  fail "symbols $(json "$tmp/street.json" 'd["symbols"]')"

# Only the Door insert, isolated: a 2 x 4 x 0.5 box from x = 1 to 3 (21 to 23 on the second lot)
# on the 1 m base.
cat >"$ws/City/rules/one.cga" <<'EOF'
Lot --> extrude(1) comp(f) { top : Top }
Top --> split(x) { 1 : Gap | 2 : Door | ~1 : Gap }
Gap --> NIL
Door --> s('1, 4, 0.5) i("doors/door.glb")
EOF
"$insula" build "$ws/City/rules/one.cga" --lot "$tmp/lot.geojson" -o "$tmp/one.obj" -q \
  --obj-world >/dev/null || fail "one build"
[ "$(bbox "$tmp/one.obj")" = "1.000 0.000 1.000 23.000 4.000 1.500" ] ||
  fail "one bbox $(bbox "$tmp/one.obj")"
[ "$(grep -c '^f ' "$tmp/one.obj")" = 24 ] ||
  fail "two inserted boxes of 12 triangles: $(grep -c '^f ' "$tmp/one.obj")"

# --workspace: the library moved elsewhere is found under it, and not without it.
mkdir -p "$tmp/other/Lib/assets"
mv "$ws/Lib/assets/lib_door.glb" "$tmp/other/Lib/assets/"
"$insula" build "$ws/City/rules/street.cga" -o "$tmp/w.obj" --workspace "$tmp/other" \
  2>"$tmp/err" >/dev/null || fail "--workspace build"
grep -q "lib_door" "$tmp/err" && fail "library asset under --workspace: $(cat "$tmp/err")"
"$insula" build "$ws/City/rules/street.cga" -o "$tmp/w.obj" 2>"$tmp/err" >/dev/null
grep -q "asset '/Lib/assets/lib_door.glb' not found" "$tmp/err" ||
  fail "library asset without --workspace: $(cat "$tmp/err")"
"$insula" build "$ws/City/rules/street.cga" -o "$tmp/w.obj" --workspace "$tmp/none" \
  2>"$tmp/err" >/dev/null && fail "--workspace of a missing folder accepted"

finish cga_assets
