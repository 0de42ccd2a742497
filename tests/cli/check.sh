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

finish check
