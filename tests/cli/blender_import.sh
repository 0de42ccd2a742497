#!/usr/bin/env bash
# Opens Insula's OBJ and GLB in Blender (headless, Debian's blender) as a user would (issue 21):
# both stand upright (Blender is Z up: the tallest building's height on Z, the footprints on X and
# Y), every building arrives as an object of its name, with its materials and, from the GLB, its
# attributes as custom properties (the parts too with --gltf-nodes element).
source "$(dirname "$0")/lib/common.sh"

example=$root/examples/town.geojson
expect_exit 0 "mass on the example" "$insula" mass "$example" -o "$tmp/town.obj" -o "$tmp/town.glb" \
  --obj-world -o "$tmp/world.obj" --report "$tmp/r.json" --quiet
# The default OBJ (local, Y up); world.obj is the GIS form (Z up), imported here to show that
# Blender then lays it on its back, as the OBJ convention says it must.
"$insula" mass "$example" -o "$tmp/town.obj" --quiet >/dev/null || fail "default obj"

imported() {  # model: the importer's one-line JSON summary
  blender -b --factory-startup --python "$root/tools/blender_import.py" -- "$1" 2>&1 |
    sed -n 's/^IMPORTED //p'
}
check() {  # what, model, node script on the summary (argv[1]); exit 0 when as expected
  local summary
  summary=$(imported "$2")
  [ -n "$summary" ] || { fail "$1: Blender did not import it"; return; }
  node -e "$3" "$summary" || fail "$1: $summary"
}

# town.geojson: its buildings are up to 9 m tall (heights 7, 8, 9 m; roofs may add).
upright='const s = JSON.parse(process.argv[1]);
  const size = [0, 1, 2].map((k) => s.max[k] - s.min[k]);
  if (!(size[2] >= 9 && size[2] < 30)) process.exit(1);      // height on Blender Z
  if (!(size[0] > 30 && size[1] > 30)) process.exit(1);       // the town spread on X and Y
  if (Math.abs(s.min[2]) > 0.01) process.exit(1);             // standing on the ground
  if (s.objects.length < 3 || s.materials < 1) process.exit(1);'
check "OBJ upright in Blender" "$tmp/town.obj" "$upright"
check "GLB upright in Blender" "$tmp/town.glb" "$upright"
# One object per building, named by its id, its attributes as custom properties.
check "GLB buildings with their attributes" "$tmp/town.glb" 'const s = JSON.parse(process.argv[1]);
  const house = s.properties["L-house"];
  if (!house || house.name !== "L-shaped house" || house.year !== 1910 || house.roof !== "hip") process.exit(1);
  if (Object.keys(s.properties).length !== s.objects.length) process.exit(1);'
# A node per part: each part an object with its kind.
"$insula" mass "$example" -o "$tmp/parts.glb" --gltf-nodes element --quiet >/dev/null ||
  fail "mass --gltf-nodes element"
check "GLB parts with their kind" "$tmp/parts.glb" 'const s = JSON.parse(process.argv[1]);
  const kinds = Object.values(s.properties).map((p) => p.kind);
  if (kinds.length < 3 || !kinds.every((k) => k === "BuildingPart")) process.exit(1);'
# Blender 3.4 does not read EXT_meshopt_compression: it says so instead of importing garbage.
"$insula" mass "$example" -o "$tmp/packed.glb" --compress --quiet >/dev/null || fail "mass --compress"
blender -b --factory-startup --python "$root/tools/blender_import.py" -- "$tmp/packed.glb" \
  >"$tmp/packed.txt" 2>&1
grep -q "EXT_meshopt_compression is not available" "$tmp/packed.txt" ||
  fail "Blender on a compressed GLB: $(grep -m3 -i error "$tmp/packed.txt")"
# The GIS form is Z up by design: Blender's Y-up reading lays it on its side (height on Y).
check "world OBJ is Z up" "$tmp/world.obj" 'const s = JSON.parse(process.argv[1]);
  if (!(s.max[1] - s.min[1] >= 9 && s.max[1] - s.min[1] < 30)) process.exit(1);'

# Each front-end's example: the OBJ and the GLB open upright with the same extents (1 mm) and the
# same materials.
same='const [a, b] = process.argv.slice(1).map((t) => JSON.parse(t));
  for (let k = 0; k < 3; ++k) {
    if (Math.abs(a.min[k] - b.min[k]) > 1e-3 || Math.abs(a.max[k] - b.max[k]) > 1e-3) process.exit(1);
  }
  if (!(a.max[2] - a.min[2] > 2 && a.min[2] > -1) || a.materials !== b.materials) process.exit(1);'
for input in "cga/building.cga --lot $root/examples/cga/building_lot.geojson" bldg/domus.bldg \
  lua/hotel.lua plasm/portico.psm; do
  name=$(basename "${input%% *}")
  # shellcheck disable=SC2086 # the CGA entry carries its --lot argument
  "$insula" build $root/examples/$input -o "$tmp/$name.obj" -o "$tmp/$name.glb" -q >/dev/null ||
    { fail "$name: build"; continue; }
  obj=$(imported "$tmp/$name.obj")
  glb=$(imported "$tmp/$name.glb")
  node -e "$same" "$obj" "$glb" || fail "$name in Blender: OBJ $obj / GLB $glb"
done

finish blender_import
