#!/usr/bin/env bash
# A CityEngine project as users have one (issue 20; docs/cga-cityengine.md): a rule file in the
# project's rules/ folder, Windows-1252 with CRLF line endings, importing a library by a relative
# path and another by a workspace path, with annotations, consts, functions, parametric rules,
# case and percentage chains, fileRandom over the project's assets; checked, built on two lots
# into a Khronos-valid GLB, with the imported attribute taking the importer's value.
source "$(dirname "$0")/lib/common.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

ws=$tmp/ws
mkdir -p "$ws/Town/rules/lib" "$ws/Town/assets/doors" "$ws/Shared/rules"

# Two door assets for fileRandom (made by Insula itself, OBJ).
printf 'Lot --> s(1, 2, 0) extrude(1) Box\n' >"$tmp/door.cga"
"$insula" build "$tmp/door.cga" -o "$ws/Town/assets/doors/door_a.obj" -q >/dev/null ||
  fail "building door_a"
cp "$ws/Town/assets/doors/door_a.obj" "$ws/Town/assets/doors/door_b.obj"

cat >"$ws/Town/rules/lib/windows.cga" <<'EOF2'
version "2019.0"
attr floorH = 2.5
@Range(min = 0.5, max = 3)
attr windowW = 1.2
const sill = 0.9
Tile --> split(x) { ~1 : Wall. | windowW : Window | ~1 : Wall. }
Window --> split(y) { sill : Wall. | ~1 : color("#8fb4d9") Glass. | 0.3 : Wall. }
EOF2
cat >"$ws/Shared/rules/roofs.cga" <<'EOF2'
version "2019.0"
Roof(kind) -->
	case kind == "hip" : roofHip(30) Tiles.
	else : roofGable(35) Tiles.
EOF2
# The main rule file: CRLF, and "Fa\xe7ade" (Windows-1252 c-cedilla) in a comment and a string.
printf '%s\r\n' \
  'version "2015.2"' \
  '/** File: town.cga  Fa'$'\xe7''ade rules */' \
  'import win : "lib/windows.cga"' \
  'import roof : "/Shared/rules/roofs.cga"' \
  '@Group("Mass") @Order(1) @Range(3, 40)' \
  'attr height = 9' \
  'attr floorH = 3' \
  '@Enum("hip", "gable")' \
  'attr roofKind = "hip"' \
  'const label = "Fa'$'\xe7''ade"' \
  'floors(h) = rint(h / floorH)' \
  '@StartRule' \
  'Lot -->' \
  '	extrude(world.up, height)' \
  '	comp(f) { top : roof.Roof(roofKind) | front : Front | side : Facade(floors(height)) | bottom : NIL }' \
  'Front --> split(y) { floorH : Ground | ~1 : Facade(floors(height) - 1) }' \
  'Ground --> split(x) { ~1 : win.Tile | 2 : Door | ~1 : win.Tile }' \
  'Door --> s('"'"'1, '"'"'1, 0.15) t(0, 0, -0.15) i(fileRandom("doors/door_*.obj"))' \
  'Facade(n) -->' \
  '	case n <= 0 : Wall.' \
  '	else : split(y) { ~floorH : Floor }*' \
  'Floor --> split(x) { ~3 : 80% : win.Tile else : Wall. }*' \
  >"$ws/Town/rules/town.cga"

"$insula" check "$ws/Town/rules/town.cga" 2>"$tmp/check_err" >"$tmp/check_out" ||
  fail "check: $(cat "$tmp/check_err")"
grep -q "warning\[CGA009\]: the file is not UTF-8; it was read as Windows-1252" "$tmp/check_err" ||
  fail "the encoding note: $(cat "$tmp/check_err")"
grep -q "start 'Lot'" "$tmp/check_out" || fail "start rule: $(cat "$tmp/check_out")"

cat >"$tmp/lots.geojson" <<'EOF2'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "properties": {}, "geometry": {"type": "Polygon",
  "coordinates": [[[0, 0], [12, 0], [12, 8], [0, 8], [0, 0]]]}},
 {"type": "Feature", "properties": {"roofKind": "gable", "height": 6}, "geometry": {"type": "Polygon",
  "coordinates": [[[20, 0], [30, 0], [30, 8], [20, 8], [20, 0]]]}}]}
EOF2
"$insula" build "$ws/Town/rules/town.cga" --lot "$tmp/lots.geojson" -o "$tmp/town.glb" \
  -o "$tmp/town.png" --report "$tmp/town.json" 2>"$tmp/err" >/dev/null ||
  fail "build: $(cat "$tmp/err")"
validate_gltf "CityEngine project GLB" "$tmp/town.glb"
[ -s "$tmp/town.png" ] || fail "PNG written"
# Three floors of 3 m (the importer's floorH, not the library's 2.5) on the 9 m building's sides;
# one hip and one gable roof; two doors drawn from the assets.
[ "$(json "$tmp/town.json" 'd["symbols"].get("Door", 0)')" = 2 ] ||
  fail "doors: $(json "$tmp/town.json" 'd["symbols"]')"
[ "$(json "$tmp/town.json" 'd["symbols"].get("roof.Roof", 0)')" = 2 ] ||
  fail "roofs: $(json "$tmp/town.json" 'd["symbols"]')"
floors=$(json "$tmp/town.json" 'd["symbols"].get("Floor", 0)')
# Lot 1 (12 x 8, 9 m): back and 2 sides x 3 floors + front upper 6 m x 2 floors = 11;
# lot 2 (10 x 8, 6 m): 3 sides x 2 floors + front upper 3 m x 1 floor = 7.
[ "$floors" = 18 ] || fail "floors: $floors ($(json "$tmp/town.json" 'd["symbols"]'))"

# --set is checked against @Range and @Enum.
"$insula" build "$ws/Town/rules/town.cga" --set height=12 --set roofKind=gable -q >/dev/null 2>&1 ||
  fail "--set inside @Range/@Enum refused"
if "$insula" build "$ws/Town/rules/town.cga" --set height=50 -q 2>"$tmp/set_err" >/dev/null; then
  fail "--set height=50 outside @Range(3, 40) accepted"
fi
grep -q "town.cga: error: --set height=50: outside @Range 3 .. 40" "$tmp/set_err" ||
  fail "@Range message: $(cat "$tmp/set_err")"
if "$insula" build "$ws/Town/rules/town.cga" --set roofKind=dome -q 2>"$tmp/set_err" >/dev/null; then
  fail "--set roofKind=dome outside @Enum accepted"
fi
grep -q 'error: --set roofKind=dome: not one of @Enum "hip", "gable"' "$tmp/set_err" ||
  fail "@Enum message: $(cat "$tmp/set_err")"

# A missing import is an error at its line and column, and nothing is written.
sed 's|"lib/windows.cga"|"lib/nowhere.cga"|' "$ws/Town/rules/town.cga" >"$ws/Town/rules/bad.cga"
if "$insula" build "$ws/Town/rules/bad.cga" -o "$tmp/bad.glb" 2>"$tmp/bad_err" >/dev/null; then
  fail "a missing import must fail"
fi
grep -q "bad.cga:3:14: error\[CGA340\]: cannot import \"lib/nowhere.cga\": no such file" \
  "$tmp/bad_err" || fail "missing import message: $(cat "$tmp/bad_err")"
[ ! -e "$tmp/bad.glb" ] || fail "no output after an error"
# scatter (docs/operations-cityengine.md): twenty point shapes on a park lot, each with an asset
# inserted at its point, in a Khronos-valid GLB; the same seed gives the same file.
cat >"$ws/Town/rules/park.cga" <<'EOF2'
version "2023.0"
Park --> scatter(surface, 20, uniform) { Tree }
Tree --> i("doors/door_a.obj")
EOF2
"$insula" build "$ws/Town/rules/park.cga" --lot "$tmp/lots.geojson" -o "$tmp/park.glb" \
  --report "$tmp/park.json" 2>"$tmp/park_err" >/dev/null || fail "park: $(cat "$tmp/park_err")"
validate_gltf "scatter GLB" "$tmp/park.glb"
[ "$(json "$tmp/park.json" 'd["symbols"].get("Tree", 0)')" = 40 ] ||
  fail "trees: $(json "$tmp/park.json" 'd["symbols"]')"
"$insula" build "$ws/Town/rules/park.cga" --lot "$tmp/lots.geojson" -o "$tmp/park2.glb" -q \
  >/dev/null 2>&1 || fail "park again"
cmp -s "$tmp/park.glb" "$tmp/park2.glb" || fail "scatter is not deterministic"

# getGeoCoord: the scope origin in the lots' CRS (UTM 33N) and in WGS 84 through PROJ; lots in
# local meters have no lon/lat: a positioned error.
cat >"$tmp/geo.cga" <<'EOF2'
version "2019.0"
Lot --> print(getGeoCoord(x)) print(getGeoCoord(lon)) print(getGeoCoord(lat)) X.
EOF2
"$insula" build "$tmp/geo.cga" --lot "$root/examples/town.geojson" -o "$tmp/geo.glb" \
  2>"$tmp/geo_err" >/dev/null || fail "geo: $(cat "$tmp/geo_err")"
grep -q "print: 455120$" "$tmp/geo_err" || fail "geo x: $(head -3 "$tmp/geo_err")"
grep -q "print: 14\.38" "$tmp/geo_err" || fail "geo lon: $(head -3 "$tmp/geo_err")"
grep -q "print: 49\.00" "$tmp/geo_err" || fail "geo lat: $(head -3 "$tmp/geo_err")"
if "$insula" build "$tmp/geo.cga" --lot "$tmp/lots.geojson" -o "$tmp/geo2.glb" 2>"$tmp/geo_err2" \
  >/dev/null; then
  fail "lon/lat without a CRS should fail"
fi
grep -q "geo.cga:2:[0-9]*: error\[CGA603\]: getGeoCoord(lon) needs the lots' coordinate system" \
  "$tmp/geo_err2" || fail "geo error: $(cat "$tmp/geo_err2")"
finish cga_cityengine
