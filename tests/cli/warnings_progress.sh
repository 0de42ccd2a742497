#!/usr/bin/env bash
# Warning caps and progress (issue 12, items 4 and 5): repeated warnings of one code are printed
# ten times, then one "and N more like it (code X)" line, while the report keeps the full count;
# long runs of mass, build --lot (CGA and .bldg) and random show progress on stderr, as plain lines
# when stderr is no terminal and as a bar redrawn in place when it is one (through `script`), and
# nothing with --quiet.
source "$(dirname "$0")/lib/common.sh"

lots() {  # count, properties: a FeatureCollection of 10 x 8 m rectangles on a grid
  awk -v n="$1" -v props="$2" 'BEGIN {
    printf "{\"type\": \"FeatureCollection\", \"features\": ["
    for (i = 0; i < n; i++) {
      x = (i % 40) * 20; y = int(i / 40) * 20
      printf "%s{\"type\": \"Feature\", \"id\": \"lot%d\", \"properties\": {%s}, ", (i ? "," : ""), i, props
      printf "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d]]]}}",
        x, y, x + 14, y, x + 14, y + 10, x, y + 10, x, y
    }
    print "]}"
  }'
}
lots 1000 "" >"$tmp/noheights.geojson"
lots 300 '"height": 6' >"$tmp/lots.geojson"

# 1,000 footprints without heights: 10 warnings and one summary line, the report counts 1,000.
expect_exit 0 "mass without heights" "$insula" mass "$tmp/noheights.geojson" -o "$tmp/m.glb" \
  --report "$tmp/m.json"
[ "$(grep -c warning "$tmp/err.txt")" -eq 10 ] || fail "mass: not 10 warning lines"
grep -c "MAS001" "$tmp/err.txt" | grep -qx 11 || fail "mass: not 11 lines of code MAS001"
grep -qx "insula: and 990 more like it (code MAS001)" "$tmp/err.txt" || fail "mass: no summary line"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.warnings !== 1000 || r.warning_counts.MAS001 !== 1000) {
           console.log(JSON.stringify(r)); process.exit(1); }' "$tmp/m.json" ||
  fail "mass report: full warning count"
expect_exit 0 "mass --quiet" "$insula" mass "$tmp/noheights.geojson" -o "$tmp/m.glb" --quiet
[ -s "$tmp/err.txt" ] && { fail "mass --quiet printed"; cat "$tmp/err.txt"; }

# Unknown roofs: another code, capped on its own.
lots 25 '"height": 5, "roof": "banana"' >"$tmp/domes.geojson"
expect_exit 0 "mass with unknown roofs" "$insula" mass "$tmp/domes.geojson" -o "$tmp/d.glb"
[ "$(grep -c "warning\[MAS003\]" "$tmp/err.txt")" -eq 10 ] || fail "roofs: not 10 warning lines"
grep -qx "insula: and 15 more like it (code MAS003)" "$tmp/err.txt" || fail "roofs: no summary line"

# The reader's own warnings past the 100 it lists (here 150 points among the footprints, GEO017)
# are counted by code all the same: 10 printed, one summary line, the report counts 150, and no
# uncoded "more warnings not listed" line.
awk 'BEGIN {
  printf "{\"type\": \"FeatureCollection\", \"features\": ["
  for (i = 0; i < 150; i++)
    printf "{\"type\": \"Feature\", \"properties\": {}, \"geometry\": {\"type\": \"Point\", \"coordinates\": [%d, 0]}},", i
  print "{\"type\": \"Feature\", \"properties\": {\"height\": 6}, \"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[0,0],[10,0],[10,8],[0,8],[0,0]]]}}]}"
}' >"$tmp/points.geojson"
expect_exit 0 "mass with 150 points" "$insula" mass "$tmp/points.geojson" --crs EPSG:32633 \
  -o "$tmp/p.glb" --report "$tmp/p.json"
[ "$(grep -c "warning\[GEO017\]" "$tmp/err.txt")" -eq 10 ] || fail "points: not 10 warning lines"
grep -qx "insula: and 140 more like it (code GEO017)" "$tmp/err.txt" ||
  { fail "points: no summary line"; cat "$tmp/err.txt"; }
grep -q "not listed" "$tmp/err.txt" && fail "points: the reader's uncoded line was printed"
node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
         if (r.warning_counts.GEO017 !== 150 || "none" in r.warning_counts) {
           console.log(JSON.stringify(r.warning_counts)); process.exit(1); }' "$tmp/p.json" ||
  fail "points report: 150 GEO017"
# The same file with a sliver (an error): the read fails, the error is quoted, and the warnings
# the reader did not list are counted in a note of their code. A graph's create.lots points at
# the error above, not at the first warning (it quoted the first GEO017 as its error before).
sed 's/\]}$/,{"type": "Feature", "properties": {}, "geometry": {"type": "Polygon", "coordinates": [[[0,20],[10,20],[10,20.01],[0,20.01],[0,20]]]}}]}/' \
  "$tmp/points.geojson" >"$tmp/sliver.geojson"
for input in "$root/examples/cga/district.cga" "$root/examples/graph/city/lots.graph.json"; do
  what="sliver with $(basename "$input")"
  expect_exit 1 "$what" "$insula" build "$input" --lot "$tmp/sliver.geojson" --crs EPSG:32633 \
    -o "$tmp/s.glb"
  grep -q "sliver.geojson:1:[0-9]*: error\[GEO028\]: feature 151: polygon: a sliver" "$tmp/err.txt" ||
    { fail "$what: the error is not quoted"; cat "$tmp/err.txt"; }
  grep -qx "$tmp/sliver.geojson: note\[GEO017\]: 50 more warnings of this code not listed" \
    "$tmp/err.txt" || { fail "$what: no note of the unlisted warnings"; cat "$tmp/err.txt"; }
  grep -q "not listed (" "$tmp/err.txt" && fail "$what: the reader's option is named"
done
grep -q "error\[G052\]: $tmp/sliver.geojson: the lots could not be read (1 error above) (node 'lots')" \
  "$tmp/err.txt" || { fail "graph sliver: the node's error"; cat "$tmp/err.txt"; }
grep -q "error\[G052\].*warning\[" "$tmp/err.txt" && fail "graph sliver: a warning as the node's error"
# An OpenStreetMap file that is not XML: its line is quoted under the error, for a graph's lots
# as for CGA's (the graph printed no source line before).
printf '<?xml version="1.0"?>\n<osm version="0.6">\n<node id="1" lat="47.1" lon="9.5"/>\n<way id="2"><nd ref="1"/>\n</osm>\n' >"$tmp/broken.osm"
for input in "$root/examples/cga/district.cga" "$root/examples/graph/city/lots.graph.json"; do
  expect_exit 1 "broken XML with $(basename "$input")" "$insula" build "$input" --lot "$tmp/broken.osm" -o "$tmp/s.glb"
  grep -A1 "broken.osm:5:3: error\[OSM001\]: not valid OSM XML" "$tmp/err.txt" | grep -qx "</osm>" ||
    { fail "broken XML with $(basename "$input"): the line is not quoted"; cat "$tmp/err.txt"; }
done

# Progress, not a terminal: plain lines with counts and a rate (every update with interval 0).
export INSULA_PROGRESS_SECONDS=0
progress_lines() {  # noun total: how many plain progress lines err.txt holds
  grep -cE "^insula: [0-9]+ of $2 $1 \([0-9]+%\), [0-9.]+/s$" "$tmp/err.txt"
}
expect_exit 0 "mass progress" "$insula" mass "$tmp/lots.geojson" -o "$tmp/p.glb"
[ "$(progress_lines buildings 300)" -ge 2 ] || { fail "mass: no progress lines"; cat "$tmp/err.txt"; }
grep -q "insula: 300 of 300 buildings" "$tmp/err.txt" || fail "mass: progress never reached 300"
grep -q $'\r' "$tmp/err.txt" && fail "mass: a terminal bar on a non-terminal"
expect_exit 0 "mass progress --quiet" "$insula" mass "$tmp/lots.geojson" -o "$tmp/p.glb" --quiet
[ -s "$tmp/err.txt" ] && fail "mass --quiet: progress printed"

expect_exit 0 "cga --lot progress" "$insula" build "$root/examples/cga/district.cga" --lot "$tmp/lots.geojson" -o "$tmp/c.glb"
[ "$(progress_lines lots 300)" -ge 2 ] || { fail "cga --lot: no progress lines"; cat "$tmp/err.txt"; }
expect_exit 0 "bldg --lot progress" "$insula" build "$root/examples/bldg/village/village.bldg" \
  --lot "$tmp/lots.geojson" -o "$tmp/b.glb"
[ "$(progress_lines buildings 300)" -ge 2 ] || { fail "bldg --lot: no progress lines"; cat "$tmp/err.txt"; }
expect_exit 0 "random progress" "$insula" random --count 20 --seed 1 -o "$tmp/random"
[ "$(progress_lines buildings 20)" -ge 2 ] || { fail "random: no progress lines"; cat "$tmp/err.txt"; }
expect_exit 0 "random --quiet" "$insula" random --count 20 --seed 1 -o "$tmp/random" --quiet
[ -s "$tmp/err.txt" ] && fail "random --quiet: progress printed"

# The default interval (2 s off a terminal) keeps short runs silent.
unset INSULA_PROGRESS_SECONDS
expect_exit 0 "short mass" "$insula" mass "$tmp/lots.geojson" -o "$tmp/p.glb"
[ "$(progress_lines buildings 300)" -eq 0 ] || fail "short mass run printed progress"

# On a terminal: a bar redrawn in place (carriage returns), with counts and a rate.
if command -v script >/dev/null; then
  INSULA_PROGRESS_SECONDS=0 script -qec "'$insula' mass '$tmp/lots.geojson' -o '$tmp/tty.glb' --quiet" \
    /dev/null >"$tmp/tty-quiet.txt"
  grep -q '\[#' "$tmp/tty-quiet.txt" && fail "terminal: a bar with --quiet"
  INSULA_PROGRESS_SECONDS=0 script -qec "'$insula' mass '$tmp/lots.geojson' -o '$tmp/tty.glb'" \
    /dev/null >"$tmp/tty.txt"
  grep -q $'\r\e\[K\[#*\.*\] [0-9]*/300 buildings [0-9.]*/s' "$tmp/tty.txt" ||
    { fail "terminal: no progress bar"; cat -v "$tmp/tty.txt" | head -5; }
  grep -q '\[##############################\] 300/300 buildings' "$tmp/tty.txt" ||
    fail "terminal: the bar does not end full"
else
  echo "note: script(1) missing; terminal progress not tested"
fi

finish warnings_progress
