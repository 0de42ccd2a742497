#!/usr/bin/env bash
# The command line as a new user meets it (issue 12, items 7 and 11): `build/insula` made by the
# build, the nearest verb suggested for a typo, the system's reason for an unreadable input, Lua
# assets found beside the program, --rooms and --room-list refused together, random's batch
# report with timings, and the documented village example built without warnings.
source "$(dirname "$0")/lib/common.sh"

# The build puts a link to the binary at the top of the build tree (README: build/insula).
top=$(cd "$(dirname "$insula")/../../.." && pwd)
[ -x "$top/insula" ] && "$top/insula" --version | grep -q "^insula " || fail "no build/insula"

# A mistyped verb names the nearest one.
expect_exit 2 "typo" "$insula" masss x
grep -q "insula: unknown command 'masss'; did you mean 'mass'?" "$tmp/err.txt" ||
  fail "typo: $(cat "$tmp/err.txt")"
expect_exit 2 "unknown verb" "$insula" frobnicate
grep -q "did you mean" "$tmp/err.txt" && fail "a far-off word got a suggestion"
grep -q "commands: mass, check, build, transform, random" "$tmp/err.txt" || fail "verbs not listed"

# A missing or unreadable input says why.
expect_exit 1 "missing mass input" "$insula" mass "$tmp/none.geojson" -o "$tmp/x.glb"
grep -qx "$tmp/none.geojson: error: cannot read file: No such file or directory" "$tmp/err.txt" ||
  fail "missing input: $(cat "$tmp/err.txt")"
expect_exit 1 "missing cga" "$insula" build "$tmp/none.cga" -o "$tmp/x.glb"
grep -q "cannot read file: No such file or directory" "$tmp/err.txt" || fail "missing cga"
mkdir -p "$tmp/dir.geojson"
expect_exit 1 "directory input" "$insula" check "$tmp/dir.geojson"
grep -q "cannot read file: Is a directory" "$tmp/err.txt" || fail "directory: $(cat "$tmp/err.txt")"
if [ "$(id -u)" -ne 0 ]; then
  echo '{}' >"$tmp/locked.geojson"
  chmod 000 "$tmp/locked.geojson"
  expect_exit 1 "unreadable input" "$insula" check "$tmp/locked.geojson"
  grep -q "cannot read file: Permission denied" "$tmp/err.txt" || fail "unreadable input"
fi

# Lua assets: the program's folder and its assets/ folder, as the README runs the hotel.
program=$(cd "$(dirname "$insula")" && pwd)/$(basename "$insula")
(cd "$tmp" && "$program" build "$root/examples/lua/hotel.lua" -o hotel.glb -q >/dev/null 2>"$tmp/err.txt") ||
  { fail "hotel without --assets"; cat "$tmp/err.txt"; }
[ -s "$tmp/hotel.glb" ] || fail "hotel.glb not written"

# random: --rooms with --room-list is a usage error; --report gives the batch's timings.
expect_exit 2 "rooms and room list" "$insula" random --rooms 3-5 --room-list kitchen,bedroom -o "$tmp/r"
grep -qE -- "--room-list excludes --rooms|--rooms excludes --room-list" "$tmp/err.txt" || fail "rooms/room-list: $(cat "$tmp/err.txt")"
[ -e "$tmp/r" ] && fail "rooms/room-list: output folder made"
expect_exit 0 "random report" "$insula" random --count 3 --seed 2 -o "$tmp/r" --report "$tmp/r.json" -q
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         const s = r.seconds || {};
         if (r.count !== 3 || r.failed !== 0 || !(s.total > 0) || !(s.generate > 0) || !(s.build > 0)) {
           console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/r.json" ||
  fail "random report: counts and timings"

# The documented village example (docs/bldg-building.md) builds without a warning.
village=$root/examples/bldg/village
expect_exit 0 "village" "$insula" build "$village/village.bldg" --lot "$village/village.geojson" \
  -o "$tmp/village.glb"
grep -q "warning" "$tmp/err.txt" && { fail "village: warnings"; head -20 "$tmp/err.txt"; }

# Its cause: generated grammars asked for windows the floor plan cannot place. Every room of a
# generated grammar now asks only for what fits, so rebuilding any of them warns about no window.
for shape in convex L U T H; do
  expect_exit 0 "random $shape" "$insula" random --count 8 --seed 12 --shape $shape --rooms 3-5 \
    -o "$tmp/gen-$shape" -q
  for grammar in "$tmp/gen-$shape"/*.bldg; do
    "$insula" build "$grammar" 2>&1 >/dev/null | grep "window(s)" && fail "$grammar: window warning"
  done
done

finish command_line
