#!/usr/bin/env bash
# `insula check FILE.bldg`: the rules' moderator (seed 000, §3.3) from the command line: summaries
# of good grammars, the exact first diagnostic and exit 1 for bad ones, nothing on stdout then.
source "$(dirname "$0")/lib/common.sh"

out=$("$insula" check "$root/tests/data/bldg/casa.bldg" 2>&1)
[ $? -eq 0 ] && [ "$out" = "$root/tests/data/bldg/casa.bldg: ok: building 'Casa': 2 parts (1 disposable), 2 floors, 4 rooms, 3 transitions" ] ||
  fail "check casa.bldg: $out"
out=$("$insula" check "$root/tests/data/bldg/domus.bldg" 2>&1)
[ $? -eq 0 ] && echo "$out" | grep -qF "ok: building 'Domus': 4 parts, 4 floors, 13 rooms, 11 transitions" ||
  fail "check domus.bldg: $out"
out=$("$insula" check "$root/tests/data/bldg/lot.bldg" 2>&1)
[ $? -eq 0 ] && echo "$out" | grep -qF "outline from lots.geojson feature 'lot-7'" || fail "check lot.bldg: $out"
out=$("$insula" check -q "$root/tests/data/bldg/two_storey.bldg" 2>&1)
[ $? -eq 0 ] && [ -z "$out" ] || fail "check -q prints nothing: $out"

"$insula" check "$root/tests/data/bldg/bad/cycle.bldg" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "bad grammar exits 1"
head -1 "$tmp/err" | grep -qF "cycle.bldg:5:21: error[BLD213]: cycle: 'a' is among its own successors (through 'c')" ||
  { fail "bad grammar message"; cat "$tmp/err"; }
sed -n 2,3p "$tmp/err" | tr -d '\n' | grep -qF 'c -> divisions() : {a}                    ^' ||
  { fail "source line and caret"; cat "$tmp/err"; }
[ -s "$tmp/out" ] && fail "nothing on stdout for a failed check"

# A warning alone does not fail the check; -q hides it.
cat >"$tmp/warn.bldg" <<'G'
b -> building(x, [(0,0),(8,0),(8,4),(0,4)]) : {p, q, d}
p -> buildingpart(Flat, 2) : {f}
f -> floor() : {r}
r -> room(hall, big, 0, 0, true)
q -> buildingpart(Flat, 0) : {g}
g -> floor() : {s}
s -> room(void, small)
d -> door(r, s)
G
"$insula" check "$tmp/warn.bldg" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 0 ] && grep -qF "warn.bldg:8:1: warning[BLD240]" "$tmp/err" || fail "warning: $(cat "$tmp/err")"
"$insula" check -q "$tmp/warn.bldg" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 0 ] && [ ! -s "$tmp/err" ] || fail "-q hides warnings"

for bad in "$root"/tests/data/bldg/bad/*.bldg; do
  timeout 20 "$insula" check "$bad" >/dev/null 2>"$tmp/err"
  code=$?
  [ "$code" -eq 1 ] || fail "$(basename "$bad"): exit $code"
  grep -q "^.*$(basename "$bad"):[0-9]*:[0-9]*: error\[BLD[0-9]*\]: " "$tmp/err" ||
    fail "$(basename "$bad"): no positioned diagnostic"
done

"$insula" check "$tmp/missing.bldg" 2>"$tmp/err"
[ $? -eq 1 ] && grep -q "missing.bldg: error: cannot read file" "$tmp/err" || fail "missing file"
printf '\xff\xfe\x00garbage' >"$tmp/binary.bldg"
timeout 20 "$insula" check "$tmp/binary.bldg" >/dev/null 2>&1
[ $? -eq 1 ] || fail "binary input exits 1"

finish bldg_check
