#!/usr/bin/env bash
# End-to-end test of `insula mass`: outputs on the bundled example, the report, third-party
# validators, exit codes, determinism across thread counts, and no partial output on failure.
source "$(dirname "$0")/lib/common.sh"

example=$root/examples/town.geojson
expect_exit 0 "mass on the example" "$insula" mass "$example" -o "$tmp/t.glb" -o "$tmp/t.obj" \
  -o "$tmp/t.city.json" -o "$tmp/t.svg" -o "$tmp/t.png" --report "$tmp/r.json" --quiet
for f in t.glb t.obj t.mtl t.city.json t.svg t.png r.json; do
  [ -s "$tmp/$f" ] || fail "missing output $f"
done
ls "$tmp" | grep -q tmp- && fail "temporary files left behind"

# The report: six buildings, all watertight, counts and per-stage timings present.
node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const ok = r.buildings === 6 && r.watertight === 6 && r.vertices > 0 && r.triangles > 0 &&
             typeof r.seconds.total === "number" && typeof r.seconds.build === "number" &&
             typeof r.seconds.read === "number" && typeof r.seconds["write glb"] === "number";
  if (!ok) { console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/r.json" || fail "report content"

# Third-party validators.
validate_gltf "glTF validator" "$tmp/t.glb"
validate_cityjson "CityJSON schema" "$tmp/t.city.json"
assimp_info "assimp info obj" "$tmp/t.obj"
assimp_info "assimp info glb" "$tmp/t.glb"

# Every roof type gives six watertight buildings.
for roof in flat shed gable hip pyramid mansard; do
  expect_exit 0 "roof $roof" "$insula" mass "$example" --roof "$roof" -o "$tmp/$roof.obj" \
    --report "$tmp/$roof.json" --quiet
  node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
           if (r.watertight !== 6) { console.log(JSON.stringify(r)); process.exit(1); }' \
    "$tmp/$roof.json" || fail "roof $roof: not all buildings watertight"
done
expect_exit 0 "overhang" "$insula" mass "$example" --overhang 0.6 -o "$tmp/oh.city.json" --report "$tmp/oh.json" --quiet
validate_cityjson "CityJSON with overhang" "$tmp/oh.city.json"

# Picture options: the PNG has the asked size; a cutaway view differs from the closed one.
expect_exit 0 "image size" "$insula" mass "$example" -o "$tmp/small.png" --image-size 320x200 --quiet
node -e 'const b = require("fs").readFileSync(process.argv[1]);
         if (b.readUInt32BE(16) !== 320 || b.readUInt32BE(20) !== 200) process.exit(1);' "$tmp/small.png" ||
  fail "--image-size 320x200 gives a 320x200 PNG"
expect_exit 0 "cutaway" "$insula" mass "$example" -o "$tmp/cut.png" --image-size 320x200 --cut-height 3 --quiet
cmp -s "$tmp/small.png" "$tmp/cut.png" && fail "--cut-height changes the picture"
expect_exit 0 "plan view" "$insula" mass "$example" -o "$tmp/plan.png" --elevation 90 --azimuth 270 --quiet
# OBJ for modelling tools (issue 21): local and Y up by default, the origin beside it; Z up and
# world coordinates on request. The same building's height shows on y, then on z.
expect_exit 0 "obj y up" "$insula" mass "$example" -o "$tmp/up.obj" --quiet
head -1 "$tmp/up.obj" | grep -q "Y up, local coordinates" || fail "obj header: $(head -1 "$tmp/up.obj")"
node -e 'const o = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (o.up !== "y" || o.coordinates !== "local" || o.origin.length !== 3) process.exit(1);' \
  "$tmp/up.origin.json" || fail "obj origin sidecar: $(cat "$tmp/up.origin.json")"
expect_exit 0 "obj world" "$insula" mass "$example" -o "$tmp/world.obj" --obj-world --quiet
head -1 "$tmp/world.obj" | grep -q "Z up, world coordinates" || fail "obj world header"
top() { awk -v c="$2" '/^v /{ if ($c > m) m = $c } END { printf "%.3f", m }' "$1"; }
expect_exit 0 "obj z up" "$insula" mass "$example" -o "$tmp/zup.obj" --up z --quiet
[ "$(top "$tmp/up.obj" 3)" = "$(top "$tmp/zup.obj" 4)" ] ||
  fail "obj up: y top $(top "$tmp/up.obj" 3) vs z top $(top "$tmp/zup.obj" 4)"
expect_exit 2 "bad up axis" "$insula" mass "$example" -o "$tmp/x.obj" --up x
expect_exit 2 "bad image size" "$insula" mass "$example" -o "$tmp/x.png" --image-size 10x10000
expect_exit 2 "bad elevation" "$insula" mass "$example" -o "$tmp/x.png" --elevation 100

# Every face reaches the GLB: its triangle count equals the report's (n - 2 per n-gon face), for
# every roof type with an overhang (skeleton events with coincident nodes once dropped faces).
for roof in gable hip mansard; do
  "$insula" mass "$example" --roof "$roof" --overhang 0.8 -o "$tmp/c.glb" --report "$tmp/c.json" --quiet >/dev/null
  node -e '
    const fs = require("fs");
    const glb = fs.readFileSync(process.argv[1]);
    const gltf = JSON.parse(glb.subarray(20, 20 + glb.readUInt32LE(12)).toString());
    let triangles = 0;
    for (const mesh of gltf.meshes) for (const p of mesh.primitives) triangles += gltf.accessors[p.indices].count / 3;
    const report = JSON.parse(fs.readFileSync(process.argv[2]));
    if (triangles !== report.triangles) { console.log(triangles, report.triangles); process.exit(1); }'     "$tmp/c.glb" "$tmp/c.json" || fail "roof $roof: GLB triangles differ from the report"
done

# Same output whatever the thread count.
# 600 footprints, so the parallel build really splits the work (its grain is 64).
node "$root/bench/make_footprints.mjs" 600 "$tmp/many.geojson"
"$insula" mass "$tmp/many.geojson" --threads 1 -o "$tmp/a.obj" -o "$tmp/a.glb" --quiet >/dev/null
"$insula" mass "$tmp/many.geojson" --threads 2 -o "$tmp/b.obj" -o "$tmp/b.glb" --quiet >/dev/null
cmp -s "$tmp/a.glb" "$tmp/b.glb" || fail "glb differs between 1 and 2 threads"
sed 's/^mtllib .*//' "$tmp/a.obj" >"$tmp/a2" && sed 's/^mtllib .*//' "$tmp/b.obj" >"$tmp/b2"
cmp -s "$tmp/a2" "$tmp/b2" || fail "obj differs between 1 and 2 threads"

# Usage and input errors.
expect_exit 0 "--help" "$insula" --help
expect_exit 0 "--version" "$insula" --version
grep -q "insula 0" "$tmp/out.txt" || fail "--version prints the version"
expect_exit 2 "no verb" "$insula"
expect_exit 2 "unknown flag" "$insula" mass "$example" -o "$tmp/x.obj" --no-such-flag
expect_exit 2 "unknown output format" "$insula" mass "$example" -o "$tmp/x.dwg"
expect_exit 2 "bad roof" "$insula" mass "$example" -o "$tmp/x.obj" --roof banana
expect_exit 1 "missing input" "$insula" mass "$tmp/nope.geojson" -o "$tmp/x.obj"
grep -q "nope.geojson" "$tmp/err.txt" || fail "missing input names the file"
expect_exit 1 "output into a missing directory" "$insula" mass "$example" -o "$tmp/x.obj" \
  -o "$tmp/no/such/dir/x.glb"
[ -e "$tmp/x.obj" ] && fail "failed run left x.obj behind"
[ -e "$tmp/x.mtl" ] && fail "failed run left x.mtl behind"
printf '{"type":"FeatureCollection","features":[' >"$tmp/broken.geojson"
expect_exit 1 "broken JSON" "$insula" mass "$tmp/broken.geojson" -o "$tmp/y.obj"
grep -qE "broken.geojson:1:[0-9]+: error" "$tmp/err.txt" || { fail "broken JSON message"; cat "$tmp/err.txt"; }
[ -e "$tmp/y.obj" ] && fail "failed parse left y.obj behind"

# Numeric flags reject NaN; a failed run keeps the user's earlier files.
expect_exit 2 "NaN pitch" "$insula" mass "$example" -o "$tmp/x.obj" --pitch nan
expect_exit 2 "NaN height" "$insula" mass "$example" -o "$tmp/x.obj" --height nan
expect_exit 2 "NaN cut height" "$insula" mass "$example" -o "$tmp/x.png" --cut-height nan
expect_exit 2 "oversized picture rejected before the build" "$insula" mass "$example" -o "$tmp/x.png" --image-size 8000x8000
echo precious >"$tmp/keep.obj"
echo precious >"$tmp/keep.mtl"
expect_exit 1 "failing second output" "$insula" mass "$example" -o "$tmp/keep.obj" -o "$tmp/no/such/dir/x.glb"
grep -qx precious "$tmp/keep.obj" && grep -qx precious "$tmp/keep.mtl" || fail "a failed run must keep existing files"
expect_exit 0 "overwrite" "$insula" mass "$example" -o "$tmp/keep.obj" --quiet
grep -q "^o " "$tmp/keep.obj" || fail "a successful run replaces the file"
ls "$tmp" | grep -q insula-backup && fail "backup files left behind"

# An invalid footprint (a sliver: 10 m x 0.2 m) is an error naming the feature, where and why, and
# suggesting --keep-going; `check` says the same. --keep-going leaves it out with one positioned
# warning, counted.
printf '%s' '{"type":"FeatureCollection","features":[
  {"type":"Feature","id":"ok","properties":{"height":8},"geometry":{"type":"Polygon","coordinates":[[[30,0],[40,0],[40,10],[30,10],[30,0]]]}},
  {"type":"Feature","id":"thin","properties":{"height":8},"geometry":{"type":"Polygon","coordinates":[[[0,0],[10,0],[10,0.2],[0,0.2],[0,0]]]}}]}' >"$tmp/thin.geojson"
thin_error='thin.geojson:3:103: error[GEO028]: feature 1 (id "thin"): polygon: a sliver (area 2 m2, width about 0.196 m = 2 * area / perimeter; footprints need at least 1 m2 and 0.5 m)'
expect_exit 1 "invalid footprint" "$insula" mass "$tmp/thin.geojson" -o "$tmp/p.obj"
grep -qF "$thin_error" "$tmp/err.txt" || { fail "invalid footprint: message"; cat "$tmp/err.txt"; }
grep -qF "note: --keep-going skips invalid features, each with a warning" "$tmp/err.txt" ||
  { fail "invalid footprint: --keep-going suggested"; cat "$tmp/err.txt"; }
[ -e "$tmp/p.obj" ] && fail "invalid footprint: nothing written"
expect_exit 1 "check agrees with mass" "$insula" check "$tmp/thin.geojson"
grep -qF "$thin_error" "$tmp/err.txt" || { fail "check: message"; cat "$tmp/err.txt"; }
expect_exit 0 "--keep-going" "$insula" mass "$tmp/thin.geojson" -o "$tmp/p.obj" --keep-going --report "$tmp/p.json"
[ "$(grep -c 'warning\[GEO028\]' "$tmp/err.txt")" = 1 ] || { fail "--keep-going: one warning"; cat "$tmp/err.txt"; }
grep -qF "${thin_error/error/warning}" "$tmp/err.txt" ||
  { fail "--keep-going: positioned warning"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.buildings !== 1 || r.invalid !== 1 || r.invalid_by_code.GEO028 !== 1 || r.failed !== 0 ||
             r.watertight !== 1) {
           console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/p.json" ||
  fail "--keep-going report"
expect_exit 0 "check --keep-going" "$insula" check "$tmp/thin.geojson" --keep-going
grep -qx "$tmp/thin.geojson: ok: 1 footprints, 1 invalid skipped" "$tmp/out.txt" ||
  { fail "check --keep-going summary"; cat "$tmp/out.txt"; }
# A hole touching the outer ring at a vertex (issue 19: it used to stop the file) is repaired
# with one warning, and every roof closes over it.
printf '%s' '{"type":"FeatureCollection","features":[
  {"type":"Feature","id":"ok","properties":{"height":8},"geometry":{"type":"Polygon","coordinates":[[[30,0],[40,0],[40,10],[30,10],[30,0]]]}},
  {"type":"Feature","id":"pinched","properties":{"height":8},"geometry":{"type":"Polygon","coordinates":[[[0,0],[20,0],[20,20],[0,20],[0,0]],[[0,0],[5,5],[5,10],[2,8],[0,0]]]}}]}' >"$tmp/pinched.geojson"
for roof in flat hip gable mansard; do
  expect_exit 0 "pinched, $roof" "$insula" mass "$tmp/pinched.geojson" -o "$tmp/p.obj" --roof $roof --report "$tmp/p.json"
  grep -qF 'pinched.geojson:3:143: warning[GEO027]: feature 1 (id "pinched"): polygon: rings touch at (0, 0); separated them by moving the touching vertex 0.01 m' "$tmp/err.txt" ||
    { fail "pinched: repair warning"; cat "$tmp/err.txt"; }
  node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
           if (r.buildings !== 2 || r.watertight !== 2 || r.repairs.separated_touching_rings !== 1) {
             console.log(JSON.stringify(r)); process.exit(1);
           }' \
    "$tmp/p.json" || fail "pinched, $roof: 2 watertight buildings, the repair counted in the report"
done
# A bow-tie among good footprints in UTM: skipped, not fatal.
expect_exit 0 "bow-tie with --keep-going" "$insula" mass "$root/tests/data/bad/utm_bowtie.geojson" \
  -o "$tmp/bt.obj" --keep-going --report "$tmp/bt.json"
grep -q 'utm_bowtie.geojson:54:13: warning\[GEO022\]: feature 1 (id "u2")' "$tmp/err.txt" ||
  { fail "bow-tie warning"; cat "$tmp/err.txt"; }
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.buildings !== 1 || r.invalid !== 1 || r.crs !== "EPSG:25832") process.exit(1);' \
  "$tmp/bt.json" || fail "bow-tie report"

# Longitude/latitude (RFC 7946, an OSM-like block) is built in its UTM zone: the same buildings
# as the same block in UTM meters (tests/data/geo/make_block_utm.sh), CRS in report and CityJSON.
geo=$root/tests/data/geo
expect_exit 0 "lon/lat block" "$insula" mass "$geo/block_lonlat.geojson" -o "$tmp/ll.city.json" \
  --report "$tmp/ll.json" --quiet
expect_exit 0 "UTM block" "$insula" mass "$geo/block_utm.geojson" -o "$tmp/utm.city.json" --report "$tmp/utm.json" --quiet
node -e '
  const fs = require("fs");
  const ll = JSON.parse(fs.readFileSync(process.argv[1])), utm = JSON.parse(fs.readFileSync(process.argv[2]));
  const city = JSON.parse(fs.readFileSync(process.argv[3]));
  const same = ["buildings", "parts", "vertices", "faces", "triangles", "watertight"].every((k) => ll[k] === utm[k]);
  if (!same || ll.buildings !== 9 || ll.crs !== "EPSG:32633" || ll.reprojected_from !== "OGC:CRS84" ||
      utm.crs !== "EPSG:32633" || city.metadata.referenceSystem !== "https://www.opengis.net/def/crs/EPSG/0/32633") {
    console.log(JSON.stringify([ll, utm, city.metadata])); process.exit(1);
  }' "$tmp/ll.json" "$tmp/utm.json" "$tmp/ll.city.json" || fail "lon/lat block: not the same buildings as UTM"
validate_cityjson "CityJSON from lon/lat" "$tmp/ll.city.json"
# Building by building (CityJSON): the same ground area within 0.5 % and the same height within
# 1 cm. Vertices are not compared one by one: a near-square gable (way/1009) may pick the other
# ridge when its corners move by a millimetre.
node -e '
  const fs = require("fs");
  const measure = (file) => {
    const c = JSON.parse(fs.readFileSync(file)), t = c.transform, out = {};
    const at = (i) => c.vertices[i].map((v, k) => v * t.scale[k] + t.translate[k]);
    for (const [id, o] of Object.entries(c.CityObjects)) {
      for (const g of o.geometry || []) {
        const m = out[o.parents ? o.parents[0] : id] ??= { ground: 0, top: -1e9 };
        g.boundaries.forEach((shell, s) => shell.forEach((surface, f) => {
          const ring = surface[0].map(at);
          ring.forEach((p) => { m.top = Math.max(m.top, p[2]); });
          const sem = g.semantics.surfaces[g.semantics.values[s][f]];
          if (sem.type !== "GroundSurface") return;
          let a = 0;
          for (let i = 0; i < ring.length; i++) {
            const p = ring[i], q = ring[(i + 1) % ring.length];
            a += p[0] * q[1] - q[0] * p[1];
          }
          m.ground += Math.abs(a) / 2;
        }));
      }
    }
    return out;
  };
  const a = measure(process.argv[1]), b = measure(process.argv[2]);
  const ids = Object.keys(a);
  if (ids.length !== 9 || ids.join() !== Object.keys(b).join()) { console.log(ids, Object.keys(b)); process.exit(1); }
  for (const id of ids) {
    if (!(Math.abs(a[id].ground - b[id].ground) <= 0.005 * b[id].ground && b[id].ground > 1 &&
          Math.abs(a[id].top - b[id].top) <= 0.01)) { console.log(id, a[id], b[id]); process.exit(1); }
  }' "$tmp/ll.city.json" "$tmp/utm.city.json" || fail "lon/lat block: buildings differ from the UTM run"
expect_exit 2 "--out-crs must be projected" "$insula" mass "$geo/block_lonlat.geojson" -o "$tmp/x.obj" --out-crs EPSG:4326
grep -q "is geographic (degrees); name a projected CRS in meters" "$tmp/err.txt" || { fail "--out-crs EPSG:4326 message"; cat "$tmp/err.txt"; }
expect_exit 2 "--out-crs must be in ground meters" "$insula" mass "$geo/block_lonlat.geojson" -o "$tmp/x.obj" --out-crs EPSG:3857
grep -q "is a Mercator projection" "$tmp/err.txt" || { fail "--out-crs EPSG:3857 message"; cat "$tmp/err.txt"; }
expect_exit 2 "--crs must be known" "$insula" mass "$geo/block_lonlat.geojson" -o "$tmp/x.obj" --crs EPSG:999999
# Web Mercator is reprojected to UTM (areas: geojson_reader_test.cc), and the CityJSON says so.
expect_exit 0 "Web Mercator block" "$insula" mass "$geo/block_3857.geojson" -o "$tmp/wm.city.json" --quiet
node -e '
  const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (c.metadata.referenceSystem !== "https://www.opengis.net/def/crs/EPSG/0/32633") {
    console.log(c.metadata.referenceSystem); process.exit(1);
  }' \
  "$tmp/wm.city.json" || fail "Web Mercator block: not built in UTM 33N"
printf '%s' '{"type":"Polygon","coordinates":[[[500000,5400000],[500020,5400000],[500020,5400015],[500000,5400015],[500000,5400000]]]}' >"$tmp/nocrs.geojson"
expect_exit 0 "--crs states the CRS of meters" "$insula" mass "$tmp/nocrs.geojson" -o "$tmp/c.city.json" --crs EPSG:25832 --quiet
node -e 'const c = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (c.metadata.referenceSystem !== "https://www.opengis.net/def/crs/EPSG/0/25832") process.exit(1);' \
  "$tmp/c.city.json" || fail "--crs: referenceSystem"

# Every file of the bad-input catalog: exit 1 (error) or 0 (repaired with a warning), never a crash.
for bad in "$root"/tests/data/bad/*.geojson; do
  timeout 20 "$insula" mass "$bad" -o "$tmp/bad.obj" --quiet >/dev/null 2>"$tmp/err.txt"
  code=$?
  case $code in
    0) ;;
    1) grep -q "$(basename "$bad")" "$tmp/err.txt" || fail "$(basename "$bad"): message does not name the file" ;;
    *) fail "$(basename "$bad"): exit $code" ;;
  esac
done

# Party walls (docs/kernel-roofs.md): two terraced houses a and b share the wall x = 8 and a lower
# garage c leans on b. No eave reaches across a shared wall into a neighbour as tall; b's eave
# passes over the garage's roof; every other edge overhangs.
expect_exit 0 "terrace with overhang" "$insula" mass "$root/tests/data/geo/terrace.geojson" \
  --overhang 0.5 -o "$tmp/terrace.city.json" --quiet
validate_cityjson "terrace CityJSON" "$tmp/terrace.city.json"
node -e '
  const cj = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const [sx, sy] = cj.transform.scale, [tx, ty] = cj.transform.translate;
  const xs = {};
  for (const [id, o] of Object.entries(cj.CityObjects)) {
    if (!o.geometry) continue;
    const v = new Set(JSON.stringify(o.geometry[0].boundaries).match(/\d+/g).map(Number));
    const x = [...v].map((i) => cj.vertices[i][0] * sx + tx - 500000);
    xs[id.split("-")[0]] = [Math.min(...x), Math.max(...x)];
  }
  const near = (a, b) => Math.abs(a - b) < 1e-3;
  const want = { a: [-0.5, 8], b: [8, 16.5], c: [16, 20.5] };
  for (const [id, [lo, hi]] of Object.entries(want)) {
    if (!xs[id] || !near(xs[id][0], lo) || !near(xs[id][1], hi)) {
      console.log(JSON.stringify(xs)); process.exit(1);
    }
  }' "$tmp/terrace.city.json" || fail "terrace: eaves stop at the party walls"

# --height-unit: the terrace's heights read as feet (house a: 9 ft = 2.7432 m of wall).
expect_exit 0 "heights in feet" "$insula" mass "$root/tests/data/geo/terrace.geojson" \
  --height-unit ft -o "$tmp/feet.obj" --report "$tmp/feet.json" --report-buildings --quiet
node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const a = r.buildings_made.find((b) => b.id === "a");
  process.exit(a && Math.abs(a.eave_height - 2.7432) < 1e-9 ? 0 : 1);
  ' "$tmp/feet.json" || fail "--height-unit ft: 9 ft of wall"

finish mass
