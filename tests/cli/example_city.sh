#!/usr/bin/env bash
# The bundled example city generator (examples/city/make_city.mjs, issue 17 item 7): the same N and
# seed give the same bytes, another seed another city, and `insula mass` builds all 500 buildings
# with no failure, no overlap and no warning (the generator's own checks run for small N: disjoint
# lots, footprints inside their lots, simple counter-clockwise rings).
source "$(dirname "$0")/lib/common.sh"

gen="$root/examples/city/make_city.mjs"
expect_exit 0 "make_city seed 5" node "$gen" 500 "$tmp/a.geojson" --seed 5
expect_exit 0 "make_city seed 5 again" node "$gen" 500 "$tmp/b.geojson" --seed 5
expect_exit 0 "make_city seed 6" node "$gen" 500 "$tmp/c.geojson" --seed 6 --check
cmp -s "$tmp/a.geojson" "$tmp/b.geojson" || fail "the same seed gave different files"
cmp -s "$tmp/a.geojson" "$tmp/c.geojson" && fail "another seed gave the same file"
expect_exit 2 "make_city without arguments" node "$gen"

expect_exit 0 "mass on the city" "$insula" mass "$tmp/a.geojson" -o "$tmp/city.png" -q \
  --report "$tmp/r.json"
node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1], "utf8"));
  const bad = [];
  if (r.buildings !== 500) bad.push(`buildings ${r.buildings}`);
  if (r.watertight !== 500) bad.push(`watertight ${r.watertight}`);
  for (const key of ["failed", "invalid", "overlaps", "warnings"]) if (r[key] !== 0) bad.push(`${key} ${r[key]}`);
  if (r.crs !== "EPSG:32633") bad.push(`crs ${r.crs}`);
  if (bad.length) { console.log(bad.join(", ")); process.exit(1); }' "$tmp/r.json" ||
  fail "report of the city"
[ -s "$tmp/city.png" ] || fail "no PNG"

finish example_city
