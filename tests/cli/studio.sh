#!/usr/bin/env bash
# The studio's server (issue 15; docs/studio.md), through its HTTP API on a copy of the examples:
# every request without the token is refused, and so is every path leading out of the folder
# (`..`, absolute, a symbolic link out); files are listed, read and saved (atomically, nothing
# left beside them); a mistake typed into a CGA file comes back as a diagnostic at its
# line:column under the file's own name; the fixed text builds into a GLB the Khronos validator
# passes, with the run's report; a newer build of the same file cancels the one it supersedes;
# SIGINT or SIGTERM stops the server.
source "$(dirname "$0")/lib/common.sh"

cp -r "$root/examples/cga" "$tmp/work"
ln -s /etc "$tmp/work/outside"
"$insula" studio "$tmp/work" >"$tmp/studio.out" 2>"$tmp/studio.err" &
server=$!
for _ in $(seq 50); do grep -q '^insula studio: http' "$tmp/studio.out" && break; sleep 0.1; done
url=$(grep -o 'http://127.0.0.1:[0-9]*/?token=[0-9a-f]*' "$tmp/studio.out")
[ -n "$url" ] || { fail "no URL printed: $(cat "$tmp/studio.out" "$tmp/studio.err")"; kill $server; finish studio; }
base=${url%/?token=*}
token=${url#*token=}
[ ${#token} -eq 32 ] || fail "the token is not 32 hex digits: $token"
status() { tail -n 1; }

# The token: every request without it (API and page alike) gets 403, a wrong one too.
for path in /api/files "/api/file?path=building.cga" /; do
  code=$(curl -s -o /dev/null -w '%{http_code}' "$base$path")
  [ "$code" = 403 ] || fail "$path without the token: $code"
done
code=$(curl -s -o /dev/null -w '%{http_code}' -H "X-Insula-Token: 0123" "$base/api/files")
[ "$code" = 403 ] || fail "a wrong token: $code"
code=$(curl -s -o /dev/null -w '%{http_code}' -H "X-Insula-Token: $token" "$base/api/files")
[ "$code" = 200 ] || fail "the token as a header: $code"

q() {  # the URL of an API path (with or without a query) with the token
  if [[ $1 == *\?* ]]; then echo "$base$1&token=$token"; else echo "$base$1?token=$token"; fi
}
get() { curl -s -w '\n%{http_code}' "$(q "$1")"; }

# Paths leading out of the folder.
for bad in "../studio.out" "/etc/passwd" "outside/passwd" "a/../../x"; do
  code=$(get "/api/file?path=$bad" | status)
  [ "$code" = 403 ] || fail "path $bad: $code, expected 403"
done
code=$(curl -s -o /dev/null -w '%{http_code}' -X PUT --data-binary x "$(q "/api/file?path=../evil.cga")")
[ "$code" = 403 ] || fail "saving outside: $code"
[ -e "$tmp/evil.cga" ] && fail "a file was written outside the folder"

# Found by review: the folder itself, a NUL cutting the name short, a huge model number, an
# exports/ link leading out, a file name that is not UTF-8.
code=$(curl -s -o /dev/null -w '%{http_code}' -X POST --data-binary x "$(q "/api/check?path=.")")
[ "$code" = 403 ] || fail "checking the folder itself: $code"
ls -A "$tmp" | grep -q '^\.studio' && fail "a draft was written beside the folder"
code=$(curl -s -o /dev/null -w '%{http_code}' -X PUT --data-binary x "$(q "/api/file?path=.bashrc%00.cga")")
[ "$code" = 403 ] || fail "a NUL in the path: $code"
[ -e "$tmp/work/.bashrc" ] && fail "a NUL in the path wrote .bashrc"
code=$(curl -s -o /dev/null -w '%{http_code}' "$(q "/api/model/99999999999999999999999.glb")")
[ "$code" = 404 ] || fail "a huge model number: $code"
mkdir "$tmp/outside_exports"
ln -s "$tmp/outside_exports" "$tmp/work/exports"
code=$(curl -s -o /dev/null -w '%{http_code}' -X POST --data-binary @"$tmp/work/building.cga" \
  "$(q "/api/export?path=building.cga&format=obj")")
[ "$code" = 403 ] || fail "exporting through a link out: $code"
[ -z "$(ls -A "$tmp/outside_exports")" ] || fail "an export was written outside the folder"
rm "$tmp/work/exports"
printf 'x' >"$tmp/work/$(printf '\xff').cga"
code=$(curl -s -o /dev/null -w '%{http_code}' "$(q "/api/files")")
[ "$code" = 200 ] || fail "a file name that is not UTF-8 breaks the list: $code"
rm "$tmp/work/$(printf '\xff').cga"

# Listing and reading.
curl -s -o "$tmp/files.json" "$(q "/api/files")"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const paths = r.files.map((f) => f.path);
  for (const p of ["building.cga", "district.cga", "building_lot.geojson"]) {
    if (!paths.includes(p)) { console.log("missing", p, paths); process.exit(1); }
  }
  if (paths.some((p) => p.startsWith("outside"))) { console.log("listed a link out"); process.exit(1); }
' "$tmp/files.json" || fail "the file list"
curl -s -o "$tmp/read.cga" "$(q "/api/file?path=building.cga")"
cmp -s "$tmp/read.cga" "$tmp/work/building.cga" || fail "reading building.cga"

# A mistake as the user types it: the diagnostic at its line and column, under the file's name.
sed 's/split("y")/split("q")/' "$tmp/work/building.cga" >"$tmp/bad.cga"
line=$(grep -n 'split("q")' "$tmp/bad.cga" | head -n 1 | cut -d: -f1)
curl -s -X POST --data-binary @"$tmp/bad.cga" "$(q "/api/check?path=building.cga")" >"$tmp/check.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const d = r.diagnostics[0];
  if (r.exit !== 1 || !d || d.file !== "building.cga" || d.line !== Number(process.argv[2]) ||
      d.severity !== "error" || d.code !== "CGA308" || !/split axis "q"/.test(d.message) ||
      r.output.includes(".studio-")) {
    console.log(JSON.stringify(r)); process.exit(1);
  }' "$tmp/check.json" "$line" || fail "the check of a mistake"
ls -A "$tmp/work" | grep -q '^\.studio' && fail "a draft was left in the folder"

# The fixed text builds: a valid GLB and the run's report.
curl -s -X POST --data-binary @"$tmp/work/building.cga" \
  "$(q "/api/build?path=building.cga&lot=building_lot.geojson&seed=3")" >"$tmp/build.json"
model=$(node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (r.exit !== 0 || !r.report || r.report.lots !== 1 || r.report.terminals < 100 ||
      r.report.seed !== 3) { console.error(JSON.stringify(r).slice(0, 400)); process.exit(1); }
  console.log(r.model);' "$tmp/build.json") || fail "the build"
curl -s -o "$tmp/model.glb" "$(q "$model")"
validate_gltf "the studio's model" "$tmp/model.glb"

# Saving: atomic, the new text in place, nothing left beside it.
printf '// saved by the studio\n' | cat - "$tmp/work/building.cga" >"$tmp/new.cga"
code=$(curl -s -o /dev/null -w '%{http_code}' -X PUT --data-binary @"$tmp/new.cga" "$(q "/api/file?path=building.cga")")
[ "$code" = 200 ] || fail "saving: $code"
cmp -s "$tmp/new.cga" "$tmp/work/building.cga" || fail "the saved text"
ls -A "$tmp/work" | grep -q 'studio-.*\.tmp' && fail "a temporary file was left"

# Export: the current text's result into the folder's exports/ (an OBJ with its .mtl and origin);
# a footprint file shows (and exports) its mass model.
curl -s -X POST --data-binary @"$tmp/work/building.cga" \
  "$(q "/api/export?path=building.cga&format=obj&lot=building_lot.geojson")" >"$tmp/export.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!r.ok || JSON.stringify(r.files) !==
      JSON.stringify(["exports/building.mtl", "exports/building.obj", "exports/building.origin.json"])) {
    console.log(JSON.stringify(r).slice(0, 400)); process.exit(1);
  }' "$tmp/export.json" || fail "the OBJ export"
grep -q '^o ' "$tmp/work/exports/building.obj" || fail "the exported OBJ has no object"
code=$(curl -s -o /dev/null -w '%{http_code}' -X POST --data-binary x "$(q "/api/export?path=building.cga&format=exe")")
[ "$code" = 400 ] || fail "an unknown export format: $code"
curl -s -X POST --data-binary @"$tmp/work/district.geojson" "$(q "/api/build?path=district.geojson")" >"$tmp/mass.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!r.ok || r.report.buildings !== 12 || !r.model) { console.log(JSON.stringify(r).slice(0, 400)); process.exit(1); }
' "$tmp/mass.json" || fail "the mass model of a footprint file"

# A stochastic building: its grammar and model; options that are not understood are refused.
curl -s -X POST --data "" "$(q "/api/random?seed=7&shape=T&rooms=2-4")" >"$tmp/random.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!r.ok || !/-> building\(/.test(r.bldg) || !r.model) { console.log(JSON.stringify(r).slice(0, 300)); process.exit(1); }
' "$tmp/random.json" || fail "a random building"
code=$(curl -s -o /dev/null -w "%{http_code}" -X POST --data "" "$(q "/api/random?shape=Z;rm")")
[ "$code" = 400 ] || fail "a random shape not understood: $code"

# The drawing tool's reading of a .bldg (the parser's tree: nested containers, holes, the
# file's own transitions), and a text that does not parse comes back with its diagnostic.
curl -s -X POST --data-binary @"$root/examples/bldg/two_storey.bldg" "$(q "/api/drawing?path=two_storey.bldg")" >"$tmp/drawing.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const b = r.building, part = b && b.parts.children[0];
  const ok = r.ok && b.name === "Two-storey house" && b.outline.length === 4 && part.kind === "part" &&
    part.floors.length === 2 && part.floors[0].children[0].kind === "divisions" &&
    part.floors[0].children[0].children.map((c) => c.symbol).join() === "hall,kitchen" &&
    b.transitions.some((t) => t.kind === "stair");
  if (!ok) { console.log(JSON.stringify(r).slice(0, 400)); process.exit(1); }
' "$tmp/drawing.json" || fail "the drawing of two_storey.bldg"
printf 'h -> building("C", [(0,0), (20,0), (20,20), (0,20)], [(8,8), (12,8), (12,12), (8,12)]) : {p}\np -> buildingpart(Flat, 1) : {f}\nf -> floor() : {r}\nr -> room(hall, small)\n' |
  curl -s -X POST --data-binary @- "$(q "/api/drawing?path=court.bldg")" >"$tmp/court.json"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  if (!r.ok || r.building.holes.length !== 1 || r.building.holes[0].length !== 4) { console.log(JSON.stringify(r)); process.exit(1); }
' "$tmp/court.json" || fail "the drawing of a building with a courtyard"
printf 'h -> building("C", [(0,0)]) : {}\n' | curl -s -X POST --data-binary @- "$(q "/api/drawing?path=bad.bldg")" >"$tmp/bad_drawing.json"
grep -q '"ok":false' "$tmp/bad_drawing.json" && grep -q 'bad.bldg:1:20: error\[BLD206\]' "$tmp/bad_drawing.json" ||
  fail "a drawing that does not parse: $(cat "$tmp/bad_drawing.json")"

# A newer build of the same file cancels the one in flight.
node "$root/examples/city/make_city.mjs" 3000 "$tmp/work/city.geojson" >/dev/null
curl -s -X POST --data-binary @"$tmp/work/district.cga" \
  "$(q "/api/build?path=district.cga&lot=city.geojson")" >"$tmp/first.json" &
first=$!
sleep 0.5
curl -s -X POST --data-binary @"$tmp/work/district.cga" \
  "$(q "/api/build?path=district.cga&lot=building_lot.geojson")" >"$tmp/second.json"
wait $first
node -e 'const [a, b] = process.argv.slice(1).map((f) => JSON.parse(require("fs").readFileSync(f)));
  if (!a.cancelled || a.ok || b.cancelled || !b.ok) {
    console.log(JSON.stringify(a).slice(0, 300), JSON.stringify(b).slice(0, 300)); process.exit(1);
  }' "$tmp/first.json" "$tmp/second.json" || fail "the superseded build was not cancelled"

# (A script's background job ignores SIGINT, so SIGTERM, which the server takes alike.)
kill -TERM $server
for _ in $(seq 50); do kill -0 $server 2>/dev/null || break; sleep 0.1; done
kill -0 $server 2>/dev/null && { fail "the server did not stop on SIGTERM"; kill -9 $server; }
finish studio
