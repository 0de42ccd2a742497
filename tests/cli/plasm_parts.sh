#!/usr/bin/env bash
# PLaSM parts in CGA and Lua (issue 13, docs/plasm-language.md "Parts for CGA and Lua"): an asset
# named FILE.psm#EXPRESSION is the expression's polyhedron fitted to the scope; a failing part is
# the front-end's asset error with the PLaSM diagnostic in it.
source "$(dirname "$0")/lib/common.sh"
cd "$tmp" || exit 1

cat >parts.psm <<'PSM'
DEF block (w, h::IsRealPos) = CUBOID:<w, 1, h>;
block:<1, 2>;
PSM
cat >g.cga <<'CGA'
lot: Lot ~> extrude(4) Mass
mass: Mass ~> s(2, 3, 1) i("parts.psm#block:<2, 3>") Block
CGA
expect_exit 0 "cga part" "$insula" build g.cga -o g.obj
# A box of 6 faces, fitted to the 2 x 3 x 1 scope: PLaSM's z (3) is the scope's up, the OBJ's y
# (Y up by default).
[ "$(grep -c '^f' g.obj)" = 6 ] || fail "cga part faces: $(grep -c '^f' g.obj)"
awk '/^v /{ if ($3 > z) z = $3 } END { if (z < 2.999 || z > 3.001) exit 1 }' g.obj ||
  fail "cga part height"

cat >bad.cga <<'CGA'
lot: Lot ~> extrude(4) Mass
mass: Mass ~> i("parts.psm#block:<2, -3>") Block
CGA
expect_exit 0 "cga bad part" "$insula" build bad.cga -o bad.obj
grep -q "asset 'parts.psm#block:<2, -3>': parts.psm#expression:4:1: error\[PSM403\]: 'block': parameter 'h' must satisfy IsRealPos, found -3" \
  "$tmp/err.txt" || fail "cga bad part message: $(cat "$tmp/err.txt")"

cat >p.lua <<'LUA'
local c = component { label = "box", size = { 2, 4, 1 } }
insert(c, "parts.psm#block:<2, 3>")
LUA
expect_exit 0 "lua part" "$insula" build p.lua -o p.obj
[ "$(grep -c '^f' p.obj)" = 6 ] || fail "lua part faces"
# Parts stay inside the asset folders, like OBJ assets.
printf 'local c = component { label = "box", size = { 1, 1, 1 } }\ninsert(c, "../x.psm#1")\n' >esc.lua
expect_exit 1 "lua escaping part" "$insula" build esc.lua -o esc.obj
grep -q "'..' is not allowed in asset names" "$tmp/err.txt" || fail "escape message: $(cat "$tmp/err.txt")"
[ -e esc.obj ] && fail "escaping part wrote esc.obj"

# The bundled example: an arcade of PLaSM columns and arches on a CGA facade.
expect_exit 0 "arcade example" "$insula" build "$root/examples/cga/arcade.cga" \
  --lot "$root/examples/cga/arcade_lot.geojson" -o arcade.glb --report arcade.json
validate_gltf "arcade glb" arcade.glb
grep -q '"Column"' arcade.glb || fail "arcade has no Column parts"

finish plasm_parts
