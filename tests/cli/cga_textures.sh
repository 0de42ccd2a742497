#!/usr/bin/env bash
# CityEngine's texturing in a rule file (issue 20 item 3; docs/operations-cityengine.md, "Texture
# coordinates"): setupProjection / projectUV / texture on a façade with a checkerboard PNG made
# here give a Khronos-valid GLB with the image embedded as it is and TEXCOORD_0 spanning one
# repeat per texture width, an OBJ with vt and map_Kd (the image copied beside it), a PNG view and
# a three.js rendering in Debian's chromium that show the checker, the uv transforms' effects,
# and one AST101 warning for a missing texture while the model is still made.
source "$(dirname "$0")/lib/common.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }

mkdir -p "$tmp/project/rules" "$tmp/project/assets/images"
# An 8 x 8 checkerboard PNG, 4 x 4 pixel squares of green and blue.
python3 - "$tmp/project/assets/images/checker.png" <<'EOF2'
import struct, sys, zlib
w = h = 8
rows = b"".join(b"\0" + b"".join(bytes((0, 200, 0)) if ((x // 4) + (y // 4)) % 2 == 0
                                 else bytes((0, 0, 220)) for x in range(w)) for y in range(h))
def chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))
png = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0)) +
       chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b""))
open(sys.argv[1], "wb").write(png)
EOF2

# A 10 x 8 m lot extruded 6 m: the front façade (10 x 6 m) textured 2 m x 3 m per repeat; the
# other walls red with a colour map (set, as texture() does) that does not exist; a roof without
# texture.
cat >"$tmp/project/rules/facade.cga" <<'EOF2'
version "2023.0"
@StartRule
Lot --> extrude(6) comp(f) { front : Facade | side : Wall | top : Roof. }
Facade --> setupProjection(0, scope.xy, 2, 3) projectUV(0) texture("images/checker.png") Bricks.
Wall --> color("#ff0000") setupProjection(0, scope.xy, '1, '1) projectUV(0) set(material.colormap, "images/missing.png") Painted.
EOF2
cat >"$tmp/lot.geojson" <<'EOF2'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [10, 0], [10, 8], [0, 8], [0, 0]]]}}]}
EOF2
mkdir -p "$tmp/out" "$tmp/lua"
"$insula" check "$tmp/project/rules/facade.cga" >"$tmp/check.txt" 2>&1 ||
  fail "check: $(cat "$tmp/check.txt")"
grep -q "CGA903" "$tmp/check.txt" && fail "texturing operations are no longer skipped: $(cat "$tmp/check.txt")"
"$insula" build "$tmp/project/rules/facade.cga" --lot "$tmp/lot.geojson" -o "$tmp/out/facade.glb" \
  -o "$tmp/out/facade.obj" -o "$tmp/out/facade.png" --report "$tmp/report.json" \
  2>"$tmp/err" >/dev/null || fail "build: $(cat "$tmp/err")"
[ "$(grep -c 'AST101' "$tmp/err")" = 1 ] || fail "one AST101 warning: $(cat "$tmp/err")"
grep -q "facade.cga: warning\[AST101\]: texture 'images/missing.png': not found (looked in .*/project/rules/images/missing.png, .*/project/assets/images/missing.png, .*); its faces show their colour only" "$tmp/err" ||
  fail "AST101 text: $(cat "$tmp/err")"
[ "$(json "$tmp/report.json" 'list(d["missing_textures"])')" = "['images/missing.png']" ] ||
  fail "report missing_textures: $(json "$tmp/report.json" 'd.get("missing_textures")')"
validate_gltf "textured façade GLB" "$tmp/out/facade.glb"
# A node and mesh per part (--gltf-nodes element), to read the Bricks part's own coordinates.
"$insula" build "$tmp/project/rules/facade.cga" --lot "$tmp/lot.geojson" --gltf-nodes element \
  -o "$tmp/out/facade_parts.glb" -q 2>"$tmp/err" >/dev/null || fail "build parts: $(cat "$tmp/err")"
validate_gltf "textured façade GLB, node per part" "$tmp/out/facade_parts.glb"

# The GLB: the PNG embedded byte for byte, a repeating sampler, the façade's material textured
# (white: CityEngine's colour under a texture), the red walls untextured; TEXCOORD_0 of the
# façade spans u 0..5 (10 m at 2 m) and v 0..2 (6 m at 3 m; glTF's v runs down: 1 - v).
python3 - "$tmp/out/facade_parts.glb" "$tmp/project/assets/images/checker.png" >"$tmp/glb.txt" 2>&1 <<'EOF2' ||
import json, struct, sys
data = open(sys.argv[1], "rb").read()
n = struct.unpack_from("<I", data, 12)[0]
gltf = json.loads(data[20:20 + n])
binary = data[20 + n + 8:]
def view(i):
    v = gltf["bufferViews"][i]
    o = v.get("byteOffset", 0)
    return binary[o:o + v["byteLength"]]
assert len(gltf["images"]) == 1, gltf["images"]
image = gltf["images"][0]
assert image["mimeType"] == "image/png", image
assert view(image["bufferView"]) == open(sys.argv[2], "rb").read(), "embedded bytes differ"
assert gltf["samplers"] == [{"magFilter": 9729, "minFilter": 9987, "wrapS": 10497, "wrapT": 10497}], gltf["samplers"]
textured = [m for m in gltf["materials"] if "baseColorTexture" in m["pbrMetallicRoughness"]]
assert len(textured) == 1 and textured[0]["pbrMetallicRoughness"]["baseColorFactor"] == [1, 1, 1, 1], textured
red = [m for m in gltf["materials"] if m["pbrMetallicRoughness"]["baseColorFactor"][:3] == [1, 0, 0]]
assert len(red) == 1 and "baseColorTexture" not in red[0]["pbrMetallicRoughness"], gltf["materials"]
mesh = next(m for m in gltf["meshes"] if m["name"] == "Bricks")
attributes = mesh["primitives"][0]["attributes"]
accessor = gltf["accessors"][attributes["TEXCOORD_0"]]
v = gltf["bufferViews"][accessor["bufferView"]]
start = v.get("byteOffset", 0) + accessor.get("byteOffset", 0)
uv = struct.unpack_from("<%df" % (2 * accessor["count"]), binary, start)
us, vs = uv[0::2], uv[1::2]
print("u %.3f %.3f v %.3f %.3f" % (min(us), max(us), min(vs), max(vs)))
EOF2
  fail "GLB: $(cat "$tmp/glb.txt")"
[ "$(cat "$tmp/glb.txt")" = "u 0.000 5.000 v -1.000 1.000" ] || fail "GLB texture coordinates: $(cat "$tmp/glb.txt")"

# The OBJ: vt per vertex of the textured parts, faces v/vt, map_Kd naming the copied image.
grep -q '^map_Kd checker.png$' "$tmp/out/facade.mtl" || fail "map_Kd: $(cat "$tmp/out/facade.mtl")"
cmp -s "$tmp/out/checker.png" "$tmp/project/assets/images/checker.png" || fail "image copied beside the OBJ"
python3 - "$tmp/out/facade.obj" >"$tmp/obj.txt" 2>&1 <<'EOF2' || fail "OBJ: $(cat "$tmp/obj.txt")"
import sys
vt, group, ranges = [], None, {}
for line in open(sys.argv[1]):
    f = line.split()
    if not f: continue
    if f[0] == "vt": vt.append((float(f[1]), float(f[2])))
    elif f[0] == "g": group = f[1].split(".")[1]
    elif f[0] == "f":
        for corner in f[1:]:
            parts = corner.split("/")
            if len(parts) == 2:
                u, v = vt[int(parts[1]) - 1]
                r = ranges.setdefault(group, [u, u, v, v])
                r[:] = [min(r[0], u), max(r[1], u), min(r[2], v), max(r[3], v)]
for g in sorted(ranges): print(g, " ".join("%.3f" % x for x in ranges[g]))
EOF2
[ "$(cat "$tmp/obj.txt")" = "Bricks 0.000 5.000 0.000 2.000
Painted 0.000 1.000 0.000 1.000" ] || fail "OBJ texture coordinates: $(cat "$tmp/obj.txt")"
assimp_info "textured OBJ" "$tmp/out/facade.obj"

# Pixels the checker's green and blue dominate, and red ones (the walls keep their colour).
count_colours() {
  python3 - "$1" <<'EOF2'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
pos, idat, w, h, kind = 8, b"", 0, 0, 0
while pos < len(data):
    n = struct.unpack_from(">I", data, pos)[0]
    k = data[pos + 4:pos + 8]
    body = data[pos + 8:pos + 8 + n]
    if k == b"IHDR": w, h, depth, kind = struct.unpack_from(">IIBB", body)
    if k == b"IDAT": idat += body
    pos += 12 + n
bpp = {2: 3, 6: 4}[kind]
raw, rows, prev = zlib.decompress(idat), [], bytearray(w * bpp)
for y in range(h):
    f, line = raw[y * (w * bpp + 1)], bytearray(raw[y * (w * bpp + 1) + 1:(y + 1) * (w * bpp + 1)])
    for i in range(len(line)):
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        p = [0, a, b, (a + b) // 2, a + b - c][f] if f < 4 else 0
        if f == 4:
            pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
            p = a if pa <= pb and pa <= pc else b if pb <= pc else c
        line[i] = (line[i] + p) & 255
    rows.append(line)
    prev = line
green = blue = red = 0
for line in rows:
    for x in range(w):
        r, g, b = line[x * bpp:x * bpp + 3]
        green += g > 60 and g > 2 * r and g > 1.5 * b
        blue += b > 60 and b > 2 * r and b > 1.5 * g
        red += r > 60 and r > 2 * g and r > 2 * b
print(green, blue, red)
EOF2
}
read -r green blue red < <(count_colours "$tmp/out/facade.png")
[ "${green:-0}" -gt 2000 ] && [ "${blue:-0}" -gt 2000 ] && [ "${red:-0}" -gt 2000 ] ||
  fail "PNG view: green $green, blue $blue, red $red pixels"

# three.js in Debian's chromium (playwright-core, SwiftShader): the façade from the front shows
# the checker.
node "$root/tools/render_gltf_browser.mjs" "$tmp/out/facade.glb" "$tmp/browser.png" >"$tmp/browser.json" 2>&1 ||
  fail "browser render: $(cat "$tmp/browser.json")"
json "$tmp/browser.json" 'd["counts"]["green"] > 10000 and d["counts"]["blue"] > 10000 and d["textured_meshes"] == 1' |
  grep -q True || fail "browser render shows the texture: $(cat "$tmp/browser.json")"
if [ -n "${INSULA_KEEP_RENDERS:-}" ]; then
  cp "$tmp/browser.png" "$tmp/out/facade.png" "$INSULA_KEEP_RENDERS/"
fi

# The uv transforms through the CGA front-end: the façade's vt range after each.
uv_range() {  # successor after projectUV(0) on the 10 x 6 m façade -> "umin umax vmin vmax"
  printf 'version "2023.0"\nLot --> extrude(6) comp(f) { front : F | side : NIL | top : NIL | bottom : NIL }\nF --> setupProjection(0, scope.xy, 2, 3) projectUV(0) %s texture("images/checker.png") T.\n' "$1" \
    >"$tmp/project/rules/uv.cga"
  "$insula" build "$tmp/project/rules/uv.cga" --lot "$tmp/lot.geojson" -o "$tmp/uv.obj" -q 2>"$tmp/uv.err" >/dev/null ||
    { echo "build failed: $(cat "$tmp/uv.err")"; return; }
  python3 -c "
import sys
vt=[list(map(float,l.split()[1:3])) for l in open(sys.argv[1]) if l.startswith('vt ')]
print(' '.join('%.3f' % f(c[i] for c in vt) for i in range(2) for f in (min, max)) if vt else 'none')" "$tmp/uv.obj"
}
check_uv() {
  local got
  got=$(uv_range "$1")
  [ "$got" = "$2" ] || fail "$1: texture coordinates $got, expected $2"
}
check_uv "" "0.000 5.000 0.000 2.000"
check_uv "translateUV(0, 0.5, 1)" "0.500 5.500 1.000 3.000"
check_uv "scaleUV(0, 2, 0.5)" "0.000 10.000 0.000 1.000"
check_uv "rotateUV(0, 90)" "-2.000 0.000 0.000 5.000"
check_uv "tileUV(0, 2.5, 0)" "0.000 4.000 0.000 2.000"
check_uv "tileUV(0, ~3, '0.5)" "0.000 3.000 0.000 2.000"
check_uv "translateUV(0, 3, 3) normalizeUV(0, uv, separatePerFace)" "0.000 1.000 0.000 1.000"
check_uv "normalizeUV(0, uvUniform, collectiveAllFaces)" "0.000 1.000 0.000 0.400"
check_uv "deleteUV(0)" "none"
check_uv "deleteUV(0) projectUV(0)" "0.000 5.000 0.000 2.000"

# The same operations from Lua (one registry): a 10 x 6 m front face textured from the asset
# folder, 2 m x 3 m per repeat.
cat >"$tmp/facade.lua" <<'EOF2'
local box = component { size = { 10, 6, 8 }, label = "box" }
local front = comp(box, "faces", "front")
local textured = texture(front, "images/checker.png")
projectUV(setupProjection(textured, 0, "scope.xy", 2, 3), 0)
EOF2
"$insula" build "$tmp/facade.lua" --assets "$tmp/project/assets" -o "$tmp/lua/facade.obj" -q \
  2>"$tmp/lua.err" >/dev/null || fail "Lua build: $(cat "$tmp/lua.err")"
grep -q '^map_Kd checker.png$' "$tmp/lua/facade.mtl" || fail "Lua map_Kd: $(cat "$tmp/lua/facade.mtl")"
[ "$(python3 -c "
import sys
vt=[list(map(float,l.split()[1:3])) for l in open(sys.argv[1]) if l.startswith('vt ')]
print(' '.join('%.3f' % f(c[i] for c in vt) for i in range(2) for f in (min, max)) if vt else 'none')" "$tmp/lua/facade.obj")" = "0.000 5.000 0.000 2.000" ] ||
  fail "Lua texture coordinates: $(grep '^vt' "$tmp/lua/facade.obj" | head -4)"

# A graph's CGA rule node (examples/graph/rules with its shop replaced): the model placed on the
# graph's lot keeps its texture coordinates (the façade: u 0..2 at '0.5, v 0..1 at '1) and the
# image beside the rule file is written with the OBJ.
mkdir -p "$tmp/graph/out"
cp "$root"/examples/graph/rules/* "$tmp/graph/"
cp "$tmp/project/assets/images/checker.png" "$tmp/graph/"
cat >"$tmp/graph/shop.cga" <<'EOF2'
version "2023.0"
attr height = 7
attr shop_color = "#7b2d26"
@StartRule
Lot --> extrude(height) comp(f) { front : Front | side : Wall. | top : Roof. }
Front --> setupProjection(0, scope.xy, '0.5, '1) projectUV(0) texture("checker.png") Bricks.
EOF2
"$insula" build "$tmp/graph/rules.graph.json" -o "$tmp/graph/out/rules.obj" -q 2>"$tmp/graph.err" >/dev/null ||
  fail "graph build: $(cat "$tmp/graph.err")"
grep -q '^map_Kd checker.png$' "$tmp/graph/out/rules.mtl" || fail "graph map_Kd"
python3 - "$tmp/graph/out/rules.obj" >"$tmp/graph.txt" 2>&1 <<'EOF2' || fail "graph OBJ: $(cat "$tmp/graph.txt")"
import sys
vt, bricks = [], []
for line in open(sys.argv[1]):
    f = line.split()
    if f and f[0] == "vt": vt.append((float(f[1]), float(f[2])))
    if f and f[0] == "g": group = f[1]
    if f and f[0] == "f" and ".Bricks." in "." + group + ".":
        bricks += [vt[int(c.split("/")[1]) - 1] for c in f[1:] if "/" in c]
print(" ".join("%.3f" % g(c[i] for c in bricks) for i in range(2) for g in (min, max)) if bricks else "none")
EOF2
[ "$(cat "$tmp/graph.txt")" = "0.000 2.000 0.000 1.000" ] || fail "graph texture coordinates: $(cat "$tmp/graph.txt")"

finish cga_textures
