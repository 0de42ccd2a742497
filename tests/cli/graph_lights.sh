#!/usr/bin/env bash
# Lights and textures of a graph end to end (graph-format.md §11): a box with a light at its top
# centre and a text texture on its front face, built to GLB and glTF; the Khronos validator accepts
# both with KHR_lights_punctual and the embedded PNG, and the report lists the light entity.
source "$(dirname "$0")/lib/common.sh"

json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

cat >"$tmp/sign.graph.json" <<'JSON'
{ "format": "insula-graph", "version": 1,
  "nodes": [
    { "id": "lot", "type": "create.rectangle", "params": { "width": 10, "depth": 20 } },
    { "id": "mass", "type": "shape.extrude", "params": { "height": 30 } },
    { "id": "lamp", "type": "light.create",
      "params": { "position": "= vec(sx()/2, sy(), sz()/2)", "intensity": 400, "range": 25 } },
    { "id": "faces", "type": "shape.comp",
      "augment": [ { "faces": "front", "out": "front" }, { "faces": "all", "out": "rest" } ] },
    { "id": "sign", "type": "texture.text",
      "params": { "text": "HOTEL", "name": "hotel", "width": 128, "height": 64, "size": 16 } },
    { "id": "paint", "type": "shape.set_texture" } ],
  "edges": [ "lot.out -> mass.in", "mass.out -> lamp.in", "mass.out -> faces.in",
             "faces.front -> paint.in", "sign.out -> paint.texture" ] }
JSON

expect_exit 0 "build the sign" "$insula" build "$tmp/sign.graph.json" -o "$tmp/sign.glb" -o "$tmp/sign.gltf" \
  --report "$tmp/r.json"
[ -s "$tmp/err.txt" ] && fail "build warnings: $(cat "$tmp/err.txt")"
validate_gltf "glTF validator on the lit, textured box" "$tmp/sign.glb" "$tmp/sign.gltf"
grep -q "0 errors, 0 warnings" "$tmp/v.txt" || fail "validator summary: $(cat "$tmp/v.txt")"

# The light: its record in the report, top centre of the box (x 0..10, y 0..20, z 0..30).
light=$(json "$tmp/r.json" "[{k: v for k, v in e.items() if k != 'id'} for e in d['graph']['entities'] if e['type'] == 'light']")
[ "$light" = "[{'attributes': {}, 'intensity': 400.0, 'kind': 'point', 'port': 'lamp.out', 'position': [5.0, 10.0, 30.0], 'type': 'light'}]" ] ||
  fail "light record: $light"
[ "$(json "$tmp/r.json" "d['graph']['leaves']['lamp.out']")" = "{'count': 1, 'types': {'light': 1}}" ] ||
  fail "light leaf: $(json "$tmp/r.json" "d['graph']['leaves']")"

# The glTF: the light at the Y-up position with its range, the texture on the front face's material.
python3 - "$tmp/sign.gltf" >"$tmp/g.txt" 2>&1 <<'PY' || fail "glTF content: $(cat "$tmp/g.txt")"
import json, sys
d = json.load(open(sys.argv[1]))
assert "KHR_lights_punctual" in d["extensionsUsed"], d.get("extensionsUsed")
lights = d["extensions"]["KHR_lights_punctual"]["lights"]
assert lights == [{"color": [1.0, 1.0, 0.8], "intensity": 400.0, "name": "lamp.out#0",
                   "range": 25.0, "type": "point"}], lights
node = [n for n in d["nodes"] if "extensions" in n]
assert len(node) == 1 and node[0]["translation"] == [5.0, 30.0, -10.0], node
assert d["nodes"].index(node[0]) in d["scenes"][0]["nodes"]
assert [i["name"] for i in d["images"]] == ["hotel"] and d["images"][0]["mimeType"] == "image/png"
assert d["textures"] == [{"sampler": 0, "source": 0}] and len(d["samplers"]) == 1
textured = [i for i, m in enumerate(d["materials"])
            if "baseColorTexture" in m["pbrMetallicRoughness"]]
assert [d["materials"][i]["name"] for i in textured] == ["texture_hotel"], d["materials"]
# One primitive shows the image, with texture coordinates (which the mesh's other primitives
# share with it).
shown = [p for m in d["meshes"] for p in m["primitives"] if p["material"] == textured[0]]
assert len(shown) == 1 and "TEXCOORD_0" in shown[0]["attributes"], shown
PY

# Other writers ignore lights and images: the OBJ still has the six faces of the box.
expect_exit 0 "build OBJ" "$insula" build "$tmp/sign.graph.json" -o "$tmp/sign.obj"
[ "$(grep -c '^f ' "$tmp/sign.obj")" -eq 6 ] || fail "OBJ faces: $(grep -c '^f ' "$tmp/sign.obj")"

# The paper's Fig. 10 (examples/graph/paper): six houses, a lamp above each door, a numbered
# plate beside it: six lights and six images in a GLB the validator accepts.
fig10=$root/examples/graph/paper/fig10_lamps_and_signs.graph.json
"$insula" build "$fig10" -o "$tmp/fig10.glb" --report "$tmp/fig10.json" >/dev/null 2>"$tmp/err" ||
  fail "fig10 builds: $(cat "$tmp/err")"
validate_gltf "glTF validator on Fig. 10" "$tmp/fig10.glb"
grep -q "0 errors, 0 warnings" "$tmp/v.txt" || fail "fig10 validator summary: $(cat "$tmp/v.txt")"
node -e '
  const r = require(process.argv[1]);
  const textures = r.graph.entities.filter(e => e.port === "signed.out").length;
  process.exit(r.lights === 6 && textures === 6 ? 0 : 1);' "$tmp/fig10.json" ||
  fail "fig10 report: lights and signed plates"

finish graph_lights
