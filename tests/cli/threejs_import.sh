#!/usr/bin/env bash
# Opens Insula's OBJ and GLB with three.js (OBJLoader + MTLLoader, GLTFLoader) in headless
# Chromium, as a web viewer would (issue 21): each front-end's example stands upright (three.js is
# Y up), the OBJ and the GLB give the same bounding box (1 mm) and draw something on screen; so
# does the GLB written with --compress (EXT_meshopt_compression) and --gltf-instancing gpu
# (EXT_mesh_gpu_instancing: the hotel's furniture).
source "$(dirname "$0")/lib/common.sh"

opened() {  # model, screenshot: the browser's one-line JSON
  node "$root/tools/render_gltf_browser.mjs" "$1" "$2" 2>&1 | tail -1
}
same='const [a, b] = process.argv.slice(1).map((t) => JSON.parse(t));
  if (a.error || b.error) process.exit(1);
  for (let k = 0; k < 3; ++k) {
    if (Math.abs(a.min[k] - b.min[k]) > 1e-3 || Math.abs(a.max[k] - b.max[k]) > 1e-3) process.exit(1);
  }
  const height = a.max[1] - a.min[1];
  if (!(height > 2 && height < 60 && a.min[1] > -1)) process.exit(1);  // upright: height on Y
  const drawn = (r) => r.width * r.height - r.counts.background;
  if (drawn(a) < 1000 || drawn(b) < 1000) process.exit(1);'

"$insula" mass "$root/examples/town.geojson" -o "$tmp/town.obj" -o "$tmp/town.glb" --quiet \
  >/dev/null || fail "town: mass"
for input in "cga/building.cga --lot $root/examples/cga/building_lot.geojson" bldg/domus.bldg \
  lua/hotel.lua plasm/portico.psm town; do
  name=$(basename "${input%% *}")
  if [ "$name" != town ]; then
    # shellcheck disable=SC2086 # the CGA entry carries its --lot argument
    "$insula" build $root/examples/$input -o "$tmp/$name.obj" -o "$tmp/$name.glb" -q >/dev/null ||
      { fail "$name: build"; continue; }
    # shellcheck disable=SC2086
    "$insula" build $root/examples/$input -o "$tmp/$name.packed.glb" --compress \
      --gltf-instancing gpu -q >/dev/null || { fail "$name: build --compress"; continue; }
  else
    "$insula" mass "$root/examples/town.geojson" -o "$tmp/town.packed.glb" --compress --quiet \
      >/dev/null || fail "town: mass --compress"
  fi
  validate_gltf "$name --compress --gltf-instancing gpu" "$tmp/$name.packed.glb"
  obj=$(opened "$tmp/$name.obj" "$tmp/$name.obj.png")
  glb=$(opened "$tmp/$name.glb" "$tmp/$name.glb.png")
  packed=$(opened "$tmp/$name.packed.glb" "$tmp/$name.packed.glb.png")
  node -e "$same" "$obj" "$glb" || fail "$name in three.js: OBJ $obj / GLB $glb"
  node -e "$same" "$obj" "$packed" || fail "$name in three.js: OBJ $obj / compressed GLB $packed"
done

finish threejs_import
