#!/usr/bin/env bash
# CityJSONSeq output (`.city.jsonl`): `insula mass` on the bundled town and `insula build` on the
# domus example (storeys and rooms as children of one building line), each line validated by
# tools/validate_cityjsonseq.mjs (CityJSON 2.0.2 schema for the header, CityJSONFeature schema for
# the others, vertex indices and ids), the same city objects as the .city.json file; and broken
# files the validator must reject with FILE:LINE messages.
source "$(dirname "$0")/lib/common.sh"

expect_exit 0 "mass to .city.jsonl" "$insula" mass "$root/examples/town.geojson" \
  -o "$tmp/town.city.jsonl" -o "$tmp/town.city.json" --quiet
expect_exit 0 "build to .city.jsonl" "$insula" build "$root/examples/bldg/domus.bldg" \
  -o "$tmp/domus.city.jsonl" --quiet
[ "$(wc -l <"$tmp/town.city.jsonl")" -eq 7 ] || fail "town: expected a header and six lines"

# One validator run for both (compiling the two schemas costs ajv about 8 s of CPU).
if node "$root/tools/validate_cityjsonseq.mjs" "$tmp/town.city.jsonl" "$tmp/domus.city.jsonl" \
  >"$tmp/v.txt" 2>&1; then
  grep -q "town.city.jsonl: valid CityJSONSeq (6 features, 12 city objects" "$tmp/v.txt" ||
    { fail "town: validator summary"; cat "$tmp/v.txt"; }
else
  fail "valid CityJSONSeq files rejected"
  cat "$tmp/v.txt"
fi

# The same city objects and world coordinates as the .city.json writer.
node -e '
  const fs = require("fs");
  const city = JSON.parse(fs.readFileSync(process.argv[1]));
  const lines = fs.readFileSync(process.argv[2], "utf8").trimEnd().split("\n").map(JSON.parse);
  const world = (v, t) => v.map((c, k) => (t.translate[k] + c * t.scale[k]).toFixed(3));
  const points = (g, vertices, t) => JSON.stringify(g.boundaries.flat(Infinity)
      .map((i) => world(vertices[i], t)));
  let count = 0, bad = [];
  for (const feature of lines.slice(1)) {
    for (const [id, object] of Object.entries(feature.CityObjects)) {
      ++count;
      const expected = city.CityObjects[id];
      if (!expected) { bad.push(`${id}: not in the .city.json`); continue; }
      (object.geometry ?? []).forEach((g, i) => {
        if (points(g, feature.vertices, lines[0].transform) !==
            points(expected.geometry[i], city.vertices, city.transform)) bad.push(`${id}: geometry ${i}`);
      });
    }
  }
  if (count !== Object.keys(city.CityObjects).length) bad.push(`${count} city objects`);
  if (bad.length) { console.log(bad.join("\n")); process.exit(1); }' \
  "$tmp/town.city.json" "$tmp/town.city.jsonl" || fail "town: differs from the .city.json"

# domus: one building line holding the building and all its storeys/rooms.
node -e '
  const lines = require("fs").readFileSync(process.argv[1], "utf8").trimEnd().split("\n")
      .map(JSON.parse);
  const f = lines[1];
  const objects = Object.values(f.CityObjects);
  if (lines.length !== 2 || objects.length < 2 || f.CityObjects[f.id].type !== "Building" ||
      !objects.every((o) => o === f.CityObjects[f.id] || (o.parents ?? []).includes(f.id))) {
    console.log(lines.length, JSON.stringify(Object.keys(f.CityObjects)));
    process.exit(1);
  }' "$tmp/domus.city.jsonl" || fail "domus: not one line of a building and its children"

# Broken files: a vertex index past the line's vertices, a feature carrying the header's
# "version", a city object id repeated on another line, a CR LF line end. One run.
sed '3s/"boundaries":\[\[\[\[0,/"boundaries":[[[[999,/' "$tmp/town.city.jsonl" >"$tmp/index.city.jsonl"
cmp -s "$tmp/index.city.jsonl" "$tmp/town.city.jsonl" && fail "index: the edit did not apply"
sed '2s/^{/{"version":"2.0",/' "$tmp/town.city.jsonl" >"$tmp/version.city.jsonl"
{ cat "$tmp/town.city.jsonl"; sed -n 2p "$tmp/town.city.jsonl"; } >"$tmp/duplicate.city.jsonl"
sed '2s/$/\r/' "$tmp/town.city.jsonl" >"$tmp/crlf.city.jsonl"
node "$root/tools/validate_cityjsonseq.mjs" "$tmp/index.city.jsonl" "$tmp/version.city.jsonl" \
  "$tmp/duplicate.city.jsonl" "$tmp/crlf.city.jsonl" >"$tmp/v.txt" 2>&1
status=$?
[ "$status" -eq 1 ] || fail "broken files: validator exit $status, expected 1"
for want in "index.city.jsonl:3: .*vertex index 999 out of range" \
  "version.city.jsonl:2: /: must NOT be valid" \
  "duplicate.city.jsonl:8: city object id \".*\" already used on line 2" \
  "crlf.city.jsonl:2: ends with CR LF"; do
  grep -q "$want" "$tmp/v.txt" || { fail "validator did not report: $want"; cat "$tmp/v.txt"; }
done
grep -q "valid CityJSONSeq" "$tmp/v.txt" && fail "a broken file passed"
expect_exit 2 "validator without files" node "$root/tools/validate_cityjsonseq.mjs"

finish cityjsonseq
