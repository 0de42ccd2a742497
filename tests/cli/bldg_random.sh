#!/usr/bin/env bash
# `insula random` (seed 000, §4.3): a grammar, a GLB and a report per building; the same seed gives
# the same bytes (also with another thread count and in another folder); rebuilding a written
# grammar with `insula build` gives the same GLB; every room reachable; bad options are usage
# errors that write nothing.
source "$(dirname "$0")/lib/common.sh"

"$insula" random --count 4 --seed 11 --shape L --rooms 3-5 -o "$tmp/a" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 0 ] || { fail "random exits 0"; cat "$tmp/err"; }
grep -q "4 buildings (0 failed)" "$tmp/out" && [ "$(wc -l <"$tmp/out")" -eq 1 ] ||
  fail "one summary line: $(cat "$tmp/out")"
for i in 0 1 2 3; do
  for ext in bldg glb json; do
    [ -s "$tmp/a/building_00$i.$ext" ] || fail "building_00$i.$ext written"
  done
done
[ "$(ls "$tmp/a" | wc -l)" -eq 12 ] || fail "exactly 12 files: $(ls "$tmp/a")"

"$insula" random --count 4 --seed 11 --shape L --rooms 3-5 --threads 1 -q -o "$tmp/b" >"$tmp/out" 2>&1
[ -s "$tmp/out" ] && fail "-q prints nothing: $(cat "$tmp/out")"
for f in "$tmp"/a/*; do
  cmp -s "$f" "$tmp/b/$(basename "$f")" || fail "same seed, same bytes: $(basename "$f")"
done
"$insula" random --count 4 --seed 12 --shape L --rooms 3-5 -q -o "$tmp/c" >/dev/null 2>&1
cmp -s "$tmp/a/building_000.bldg" "$tmp/c/building_000.bldg" && fail "another seed, another building"

# The grammar is the building: check it, rebuild it, get the same GLB.
"$insula" check "$tmp/a/building_001.bldg" >/dev/null 2>&1 || fail "written grammar checks"
"$insula" build "$tmp/a/building_001.bldg" -o "$tmp/rebuilt.glb" >/dev/null 2>&1 || fail "rebuild"
cmp -s "$tmp/rebuilt.glb" "$tmp/a/building_001.glb" || fail "rebuilt GLB equals the generated one"

# Reports: rooms, one entrance, nothing unreachable, no timings.
python3 - "$tmp/a" <<'P' || fail "reports"
import json, sys, glob
for path in sorted(glob.glob(sys.argv[1] + "/*.json")):
    r = json.load(open(path))
    assert r["rooms"], path
    assert len(r["entrances"]) == 1, path
    assert r["unreachable_rooms"] == [], (path, r["unreachable_rooms"])
    assert "seconds" not in r, path
    assert r["random"]["shape"] == "L", path
    assert r["vertices"] > 0 and r["triangles"] > 0, path
P

# Every shape, a room list, fixed parts.
for shape in convex U T H; do
  "$insula" random --count 2 --seed 3 --shape $shape -q -o "$tmp/$shape" >/dev/null 2>"$tmp/err" ||
    { fail "shape $shape"; cat "$tmp/err"; }
done
grep -c "buildingpart(Flat, 0)" "$tmp/H/building_000.bldg" | grep -qx 2 || fail "H has two disposable parts"
"$insula" random --count 1 --seed 5 --shape U --parts 4 --room-list "atrium,kitchen,bedroom,bedroom,bath,study,dining room" -q -o "$tmp/list" >/dev/null 2>"$tmp/err" ||
  { fail "room list"; cat "$tmp/err"; }
grep -q 'room("dining room"' "$tmp/list/building_000.bldg" || fail "room list type kept"
[ "$(grep -c -- '-> buildingpart(HipGlued' "$tmp/list/building_000.bldg")" -eq 4 ] || fail "4 parts"
grep -q "entrance(atrium1, 1.2)" "$tmp/list/building_000.bldg" || fail "entrance on the public room"

# Usage errors: exit 2, nothing written.
for bad in "--shape Z" "--rooms 7-3" "--rooms x" "--count 0" "--parts 99"; do
  # shellcheck disable=SC2086
  "$insula" random $bad -o "$tmp/bad" >/dev/null 2>&1
  code=$?
  [ "$code" -eq 2 ] || fail "random $bad: exit $code"
  [ -e "$tmp/bad" ] && fail "random $bad wrote $tmp/bad"
done
touch "$tmp/file"
"$insula" random --count 1 -o "$tmp/file" >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] && grep -q "cannot create the output folder" "$tmp/err" || fail "output is a file"

finish bldg_random
