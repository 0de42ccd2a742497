#!/usr/bin/env bash
# `insula build FILE.cga`: the report's counts, identical outputs whatever --threads and for the
# same --seed, --set and lot properties, --start, report-only runs, and bad input (grammar errors,
# unknown --set names, runaway grammars, asset axes) exiting 1 with a positioned diagnostic and no
# output.
set -u
insula=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

ex=$root/examples/cga

# The district: 12 lots from GeoJSON, per-lot height and style.
"$insula" build "$ex/district.cga" --lot "$ex/district.geojson" --threads 1 \
  -o "$tmp/d1.obj" --report "$tmp/d1.json" -q >/dev/null || fail "district build (1 thread)"
"$insula" build "$ex/district.cga" --lot "$ex/district.geojson" --threads 2 \
  -o "$tmp/d2.obj" --report "$tmp/d2.json" -q >/dev/null || fail "district build (2 threads)"
# The OBJ names its own .mtl file; everything else must be byte-identical.
same_obj() { cmp -s <(grep -v '^mtllib' "$1") <(grep -v '^mtllib' "$2"); }
same_obj "$tmp/d1.obj" "$tmp/d2.obj" || fail "OBJ differs between --threads 1 and 2"
cmp -s "$tmp/d1.mtl" "$tmp/d2.mtl" || fail "MTL differs between --threads 1 and 2"
[ "$(json "$tmp/d1.json" "d['lots'], d['shapes'], d['terminals']")" = \
  "$(json "$tmp/d2.json" "d['lots'], d['shapes'], d['terminals']")" ] || fail "report counts differ"
[ "$(json "$tmp/d1.json" "d['lots']")" = "12" ] || fail "12 lots"
[ "$(json "$tmp/d1.json" "d['terminals'] > 1000 and d['symbols']['Lot'] == 12")" = "True" ] ||
  fail "district counts: $(cat "$tmp/d1.json")"
[ "$(json "$tmp/d1.json" "sorted(d['seconds'])")" = \
  "['check', 'compile', 'derive', 'parse', 'read_lots', 'scene', 'total', 'write_obj']" ] ||
  fail "seconds per stage: $(json "$tmp/d1.json" "d['seconds']")"

# Report only: the same counts, no geometry written.
"$insula" build "$ex/district.cga" --lot "$ex/district.geojson" --report "$tmp/r.json" -q \
  >"$tmp/out" || fail "report-only build"
[ "$(json "$tmp/r.json" "d['terminals']")" = "$(json "$tmp/d1.json" "d['terminals']")" ] ||
  fail "report-only terminals differ"

# Seeds: the building's balconies are random; same seed same file, other seed other file.
"$insula" build "$ex/building.cga" --lot "$ex/building_lot.geojson" --seed 3 -o "$tmp/b1.obj" -q \
  >/dev/null || fail "building seed 3"
"$insula" build "$ex/building.cga" --lot "$ex/building_lot.geojson" --seed 3 -o "$tmp/b2.obj" -q \
  >/dev/null || fail "building seed 3 again"
"$insula" build "$ex/building.cga" --lot "$ex/building_lot.geojson" --seed 4 -o "$tmp/b3.obj" -q \
  >/dev/null || fail "building seed 4"
same_obj "$tmp/b1.obj" "$tmp/b2.obj" || fail "same seed, different output"
same_obj "$tmp/b1.obj" "$tmp/b3.obj" && fail "another seed, same output"

# The lot's x axis follows the file's first edge: the same footprint written clockwise, starting
# with the street edge, builds the same model.
cat >"$tmp/cw.geojson" <<'G'
{"type": "FeatureCollection", "features": [{"type": "Feature", "id": "corner_house",
 "properties": {"floors": 4}, "geometry": {"type": "Polygon", "coordinates":
 [[[26, 0], [0, 0], [0, 12], [14, 12], [14, 22], [26, 22], [26, 0]]]}}]}
G
"$insula" build "$ex/building.cga" --lot "$tmp/cw.geojson" --seed 3 -o "$tmp/cw.obj" -q \
  >/dev/null || fail "building from a clockwise ring"
same_obj "$tmp/b1.obj" "$tmp/cw.obj" || fail "clockwise ring: another start shape"

# --set wins over lot properties, which win over attr defaults.
cat >"$tmp/h.cga" <<'G'
attr height = 5
Lot --> extrude(height) Mass
Mass --> report("height", Scope.sy) M
G
cat >"$tmp/lot.geojson" <<'G'
{"type": "Feature", "id": "a", "properties": {"height": 7},
 "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}}
G
"$insula" build "$tmp/h.cga" --report "$tmp/h1.json" -q >/dev/null
[ "$(json "$tmp/h1.json" "d['reports']['height']['sum']")" = "5.0" ] || fail "attr default"
"$insula" build "$tmp/h.cga" --lot "$tmp/lot.geojson" --report "$tmp/h2.json" -q >/dev/null
[ "$(json "$tmp/h2.json" "d['reports']['height']['sum']")" = "7.0" ] || fail "lot property"
"$insula" build "$tmp/h.cga" --lot "$tmp/lot.geojson" --set height=9 --report "$tmp/h3.json" -q \
  >/dev/null
[ "$(json "$tmp/h3.json" "d['reports']['height']['sum']")" = "9.0" ] || fail "--set"

# --start picks another start symbol.
"$insula" build "$tmp/h.cga" --start Mass --report "$tmp/s.json" -q >/dev/null ||
  fail "--start Mass"
[ "$(json "$tmp/s.json" "d['start'], d['symbols'].get('Lot', 0)")" = "Mass 0" ] ||
  fail "--start report: $(cat "$tmp/s.json")"

# Bad input: exit 1, a positioned diagnostic, no output files.
cat >"$tmp/runaway.cga" <<'G'
Lot --> A
grow: A ~> T(0, 0, 1) A
G
"$insula" build "$tmp/runaway.cga" -o "$tmp/x.obj" --report "$tmp/x.json" 2>"$tmp/err" >/dev/null
[ $? -eq 1 ] || fail "runaway grammar exits 1"
grep -qF "runaway.cga:2:1: error[CGA601]: derivation depth limit of 10000 reached in rule 'grow' (line 2)" \
  "$tmp/err" || { fail "depth limit message"; cat "$tmp/err"; }
[ -e "$tmp/x.obj" ] || [ -e "$tmp/x.json" ] && fail "output written after an error"

"$insula" build "$tmp/h.cga" --set hieght=3 --report "$tmp/y.json" 2>"$tmp/err" >/dev/null
[ $? -eq 1 ] || fail "unknown --set exits 1"
grep -qF "error: --set 'hieght': the grammar declares no attr 'hieght'" "$tmp/err" ||
  { fail "unknown --set message"; cat "$tmp/err"; }

printf 'Lot --> split("x"){ 2: A | ~1: B\n' >"$tmp/bad.cga"
"$insula" build "$tmp/bad.cga" --report "$tmp/z.json" 2>"$tmp/err" >/dev/null
[ $? -eq 1 ] || fail "syntax error exits 1"
grep -qE "bad.cga:[0-9]+:[0-9]+: error\[CGA1" "$tmp/err" || { fail "syntax message"; cat "$tmp/err"; }
[ -e "$tmp/z.json" ] && fail "report written after a syntax error"

# A wrong axes selector of an asset selection function (assetBestSize, ...): CGA603 at the call.
printf 'version "2019.0"\nLot --> i(assetBestSize("*.obj", "xw"))\n' >"$tmp/axes.cga"
"$insula" build "$tmp/axes.cga" --report "$tmp/axes.json" 2>"$tmp/err" >/dev/null
[ $? -eq 1 ] || fail "wrong asset axes exits 1"
grep -qE "axes.cga:2:[0-9]+: error\[CGA603\]: the axes of an asset size are one to three of x, y, z" \
  "$tmp/err" || { fail "asset axes message"; cat "$tmp/err"; }
[ -e "$tmp/axes.json" ] && fail "report written after CGA603"

# A probability computed while deriving (here from --set) outside [0, 1] is CGA605 at the
# expression, naming the rule and the value: exit 1, no output (seed 004 §IV.B constraint 1).
printf 'attr p = 0.5\nr1: Lot ~> A : (p) ~> B : (1 - p)\n' >"$tmp/p.cga"
"$insula" build "$tmp/p.cga" --set p=0.25 -o "$tmp/p0.obj" -q >/dev/null || fail "p = 0.25"
"$insula" build "$tmp/p.cga" --set p=-0.5 -o "$tmp/p.obj" --report "$tmp/p.json" 2>"$tmp/err" \
  >/dev/null
[ $? -eq 1 ] || fail "negative probability exits 1"
grep -qF "p.cga:2:17: error[CGA605]: the probability of rule 'r1' (line 2) evaluates to -0.5, not a number in [0, 1]" \
  "$tmp/err" || { fail "negative probability message"; cat "$tmp/err"; }
[ -e "$tmp/p.obj" ] || [ -e "$tmp/p.json" ] && fail "output written after CGA605"

# The paper's BS( "XY", 3, 5, 7) (§VI) builds: 9 cells of the facade, 3 per successor.
"$insula" build "$root/tests/data/cga/derive/paper_bs_xy.cga" --report "$tmp/bs.json" -q \
  >/dev/null || fail "paper BS XY build"
[ "$(json "$tmp/bs.json" "d['symbols']['balcony'], d['symbols']['floor'], d['symbols']['door']")" = \
  "3 3 3" ] || fail "paper BS XY counts: $(cat "$tmp/bs.json")"

# --height-unit ft: a register lot's bare height (a number, or a text that is only a number) is
# feet for the grammar; a text with a unit and an OpenStreetMap lot's height keep theirs.
cat >"$tmp/feet.geojson" <<'G'
{"type": "FeatureCollection", "features": [
 {"type": "Feature", "id": "n", "properties": {"height": 10},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}},
 {"type": "Feature", "id": "t", "properties": {"height": "20"},
  "geometry": {"type": "Polygon", "coordinates": [[[20,0],[30,0],[30,8],[20,8],[20,0]]]}},
 {"type": "Feature", "id": "u", "properties": {"height": "4 m"},
  "geometry": {"type": "Polygon", "coordinates": [[[40,0],[50,0],[50,8],[40,8],[40,0]]]}},
 {"type": "Feature", "id": "o", "properties": {"building": "yes", "height": "6"},
  "geometry": {"type": "Polygon", "coordinates": [[[60,0],[70,0],[70,8],[60,8],[60,0]]]}}]}
G
"$insula" build "$tmp/h.cga" --lot "$tmp/feet.geojson" --height-unit ft --report "$tmp/ft.json" -q \
  >/dev/null || fail "--height-unit ft"
# 10 ft + 20 ft = 9.144 m, and 4 m and 6 m as they are.
[ "$(json "$tmp/ft.json" "round(d['reports']['height']['sum'], 6)")" = "19.144" ] ||
  fail "--height-unit ft: lots' heights in feet: $(json "$tmp/ft.json" "d['reports']")"
"$insula" build "$tmp/h.cga" --lot "$tmp/feet.geojson" --report "$tmp/m.json" -q >/dev/null
[ "$(json "$tmp/m.json" "round(d['reports']['height']['sum'], 6)")" = "40.0" ] || fail "meters by default"

# A --lot file whose every feature is left out (an S3DB part above the ground) builds nothing: no
# invented default lot at the origin, an empty OBJ and a report of 0 lots.
cat >"$tmp/up.geojson" <<'G'
{"type": "FeatureCollection", "features": [{"type": "Feature", "id": "upper",
  "properties": {"building:part": "yes", "building:min_level": "2", "building:levels": "3"},
  "geometry": {"type": "Polygon", "coordinates": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}}]}
G
"$insula" build "$ex/footprints.cga" --lot "$tmp/up.geojson" -o "$tmp/up.obj" \
  --report "$tmp/up.json" >/dev/null 2>"$tmp/up.err" || fail "all lots left out: exit 0"
[ "$(json "$tmp/up.json" "d['lots'], d['terminals']")" = "0 0" ] ||
  fail "all lots left out: nothing built: $(cat "$tmp/up.json")"
grep -q '^[of] ' "$tmp/up.obj" && fail "all lots left out: the OBJ holds geometry"
grep -q 'above the ground' "$tmp/up.err" || fail "all lots left out: the note says why"

[ $failures -eq 0 ] && echo "cga_build: ok"
exit $((failures > 0))
