#!/usr/bin/env bash
# GPU instancing (`--gltf-instancing gpu`, docs/formats.md "glTF"): building.cga's balcony slabs
# and railings are placed as EXT_mesh_gpu_instancing instances, and CesiumJS in headless Chromium
# draws them and picks each as a feature of the property table (tools/check_gltf_instances.mjs:
# the instances must carry EXT_instance_features ids, which CesiumJS reads on a node), plain and
# meshopt-compressed. The GLBs also pass the Khronos validator.
source "$(dirname "$0")/lib/common.sh"

for variant in plain compressed; do
  options=()
  [ "$variant" = compressed ] && options=(--compress)
  expect_exit 0 "building.cga with GPU instances, $variant" "$insula" build \
    "$root/examples/cga/building.cga" --lot "$root/examples/cga/building_lot.geojson" \
    -o "$tmp/$variant.glb" --gltf-instancing gpu "${options[@]}" --quiet
  validate_gltf "GPU-instanced building, $variant" "$tmp/$variant.glb"
  node "$root/tools/check_gltf_instances.mjs" "$tmp/$variant.glb" >"$tmp/c.txt" 2>&1 ||
    { fail "GPU instances in CesiumJS, $variant"; cat "$tmp/c.txt"; }
  for part in Slab Railing; do
    grep -q "\"picked_instances\":\[[^]]*\"$part\"" "$tmp/c.txt" ||
      { fail "$part instances picked as features, $variant"; cat "$tmp/c.txt"; }
  done
done

finish gpu_instances
