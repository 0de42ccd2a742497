#!/usr/bin/env bash
# GPU instancing (`--gltf-instancing gpu`, docs/formats.md "glTF"): building.cga's balcony slabs
# and railings are placed as EXT_mesh_gpu_instancing instances, and CesiumJS in headless Chromium
# draws them and picks each as a feature of the property table (tools/check_gltf_instances.mjs:
# the instances must carry EXT_instance_features ids, which CesiumJS reads on a node). The GLB
# also passes the Khronos validator.
source "$(dirname "$0")/lib/common.sh"

expect_exit 0 "building.cga with GPU instances" "$insula" build \
  "$root/examples/cga/building.cga" --lot "$root/examples/cga/building_lot.geojson" \
  -o "$tmp/building.glb" --gltf-instancing gpu --quiet
validate_gltf "GPU-instanced building" "$tmp/building.glb"
node "$root/tools/check_gltf_instances.mjs" "$tmp/building.glb" >"$tmp/c.txt" 2>&1 ||
  { fail "GPU instances in CesiumJS"; cat "$tmp/c.txt"; }
for part in Slab Railing; do
  grep -q "\"picked_instances\":\[[^]]*\"$part\"" "$tmp/c.txt" ||
    { fail "$part instances picked as features"; cat "$tmp/c.txt"; }
done

finish gpu_instances
