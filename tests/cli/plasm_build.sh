#!/usr/bin/env bash
# `insula build FILE.psm` (docs/plasm-language.md, "Output"): every example that draws builds to
# glTF (checked by the glTF validator), CityJSON (the schema) and OBJ (assimp), its parts named
# after the program's DEFs; the report counts the cells; a failing program exits 1, writes nothing
# and leaves an existing output file as it was.
source "$(dirname "$0")/lib/common.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

built=0
for f in "$root"/examples/plasm/*.psm; do
  name=$(basename "$f" .psm)
  # Listing 1 defines functions only: nothing to draw (PSM420, checked below).
  [ "$name" = listing1_definition ] && continue
  out=$tmp/$name
  expect_exit 0 "$name: build" "$insula" build "$f" -o "$out.glb" -o "$out.city.json" \
    -o "$out.obj" --report "$out.json" -q
  for ext in glb city.json obj json; do
    [ -s "$out.$ext" ] || fail "$name: missing $name.$ext"
  done
  assimp_info "$name: assimp info obj" "$out.obj"
  [ "$(json "$out.json" "d['cells']['solid'] + d['cells']['surface'] > 0 and d['parts'] > 0")" = True ] ||
    fail "$name: report $(cat "$out.json")"
  built=$((built + 1))
done
[ $built -ge 8 ] || fail "only $built examples built"
validate_gltf "glTF validator" "$tmp"/*.glb
validate_cityjson "CityJSON schema" "$tmp"/*.city.json

# The report's counts for the column (Listing 2): six solids (the capital is one boolean's
# result), nothing skipped, one building with one part, named after the DEF.
[ "$(json "$tmp/column.json" "d['cells']")" = "{'not_drawn': 0, 'solid': 6, 'surface': 0}" ] ||
  fail "column cells: $(json "$tmp/column.json" "d['cells']")"
[ "$(json "$tmp/column.json" "d['buildings'], d['parts']")" = "1 1" ] ||
  fail "column buildings and parts: $(json "$tmp/column.json" "d['buildings'], d['parts']")"
[ "$(json "$tmp/portico.json" "d['parts']")" = 15 ] || fail "portico: 10 columns and 5 arches"
grep -q '"columna"' "$tmp/column.city.json" || fail "column.city.json has no columna part"
grep -q 'plasm_path' "$tmp/portico.city.json" || fail "portico.city.json has no plasm_path"

# Cells that cannot be drawn are counted and warned about once.
cat >"$tmp/wire.psm" <<'PSM'
STRUCT:<CUBOID:<1, 1, 1>, SKELETON:1:(CUBOID:<1, 1, 1>)>;
PSM
expect_exit 0 "wire: build" "$insula" build "$tmp/wire.psm" -o "$tmp/wire.obj" \
  --report "$tmp/wire.json"
[ "$(json "$tmp/wire.json" "d['cells']")" = "{'not_drawn': 12, 'solid': 1, 'surface': 0}" ] ||
  fail "wire cells: $(json "$tmp/wire.json" "d['cells']")"
grep -q "warning: 12 cells not drawn" "$tmp/err.txt" || fail "wire: no warning: $(cat "$tmp/err.txt")"

# A failing program: exit 1, the positioned diagnostic, no new file, an old file untouched.
printf 'DEF a = CUBOID:<1, 1, 1>;\na;\nMAP:<S1, S2, S3>:(a - T:1:0.5:a);\n' >"$tmp/bad.psm"
echo "previous content" >"$tmp/keep.obj"
expect_exit 1 "bad program" "$insula" build "$tmp/bad.psm" -o "$tmp/keep.obj" -o "$tmp/new.glb" \
  --report "$tmp/bad.json"
grep -q "bad.psm:3:1: error\[PSM416\]" "$tmp/err.txt" || fail "bad program: $(cat "$tmp/err.txt")"
[ "$(cat "$tmp/keep.obj")" = "previous content" ] || fail "bad program overwrote keep.obj"
[ -e "$tmp/new.glb" ] && fail "bad program wrote new.glb"

# Nothing to draw: PSM420 names the file, no output.
expect_exit 1 "listing 1" "$insula" build "$root/examples/plasm/listing1_definition.psm" \
  -o "$tmp/l1.obj"
grep -q "error\[PSM420\]: nothing to build" "$tmp/err.txt" || fail "listing 1: $(cat "$tmp/err.txt")"
[ -e "$tmp/l1.obj" ] && fail "listing 1 wrote l1.obj"

finish plasm_build
