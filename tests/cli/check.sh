#!/usr/bin/env bash
# `insula check`: parse-only verification of footprints and grammars, exit codes and messages.
source "$(dirname "$0")/lib/common.sh"

out=$("$insula" check "$root/examples/town.geojson" 2>&1)
[ $? -eq 0 ] && [ "$out" = "$root/examples/town.geojson: ok: 6 footprints, in EPSG:32633" ] || fail "check town.geojson: $out"
out=$("$insula" check "$root/tests/data/cga/apartment_block.cga" 2>&1)
[ $? -eq 0 ] && echo "$out" | grep -q "ok: 40 rules" || fail "check apartment_block.cga: $out"

"$insula" check "$root/tests/data/cga/bad/assign_in_condition.cga" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "bad grammar exits 1"
head -1 "$tmp/err" | grep -qF "assign_in_condition.cga:1:17: error[CGA101]: expected '==' to compare, found '='" ||
  { fail "bad grammar message"; cat "$tmp/err"; }
[ -s "$tmp/out" ] && fail "nothing on stdout for a failed check"

for bad in "$root"/tests/data/cga/bad/*.cga "$root"/tests/data/bad/*.geojson; do
  timeout 20 "$insula" check "$bad" >/dev/null 2>"$tmp/err"
  code=$?
  [ "$code" -le 1 ] || fail "$(basename "$bad"): exit $code"
done

"$insula" check "$tmp/missing.cga" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q "missing.cga: error: cannot read file" "$tmp/err" || fail "missing file"
"$insula" check "$root/README.md" 2>/dev/null
[ $? -eq 2 ] || fail "unknown input type is a usage error"

# Newline-delimited GeoJSON (RFC 8142 GeoJSONSeq, Microsoft's building footprints): the town's
# features one per line, the second after a record separator and a blank line, read by check,
# mass and build --lot as the FeatureCollection is (--crs for a sequence has no crs member).
node -e 'const fc = JSON.parse(require("fs").readFileSync(process.argv[1]));
  process.stdout.write(fc.features.map((f, i) => (i === 1 ? "\n\x1e" : "") + JSON.stringify(f)).join("\n") + "\n");' \
  "$root/examples/town.geojson" >"$tmp/town.geojsonl"
out=$("$insula" check "$tmp/town.geojsonl" --crs EPSG:32633 2>&1)
[ $? -eq 0 ] && [ "$out" = "$tmp/town.geojsonl: ok: 6 footprints, in EPSG:32633" ] || fail "check town.geojsonl: $out"
# Both OBJs under one name, in folders of their own: the file names the .mtl it uses.
mkdir -p "$tmp/seq" "$tmp/fc"
expect_exit 0 "mass town.geojsonl" "$insula" mass "$tmp/town.geojsonl" --crs EPSG:32633 -o "$tmp/seq/town.obj" -q
expect_exit 0 "mass town.geojson" "$insula" mass "$root/examples/town.geojson" -o "$tmp/fc/town.obj" -q
cmp -s "$tmp/seq/town.obj" "$tmp/fc/town.obj" || fail "mass: a sequence builds what its FeatureCollection builds"
expect_exit 0 "build --lot town.geojsonl" "$insula" build "$root/bench/lots.cga" --lot "$tmp/town.geojsonl" \
  --crs EPSG:32633 --report "$tmp/lots.json" -q
grep -q '"lots": 6' "$tmp/lots.json" || fail "build --lot town.geojsonl: 6 lots"
cp "$tmp/town.geojsonl" "$tmp/bad.ndjson"
echo '[1, 2]' >>"$tmp/bad.ndjson"
"$insula" check "$tmp/bad.ndjson" --crs EPSG:32633 >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] && grep -qF "bad.ndjson:8:1: error[GEO015]: feature 6: line 8 of the GeoJSON sequence is an array; expected a Feature object" "$tmp/err" ||
  { fail "check: a line that is not a Feature"; cat "$tmp/err"; }

finish check
