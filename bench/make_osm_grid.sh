#!/usr/bin/env bash
# Writes OUT (.osm.pbf) with COUNT building ways: 10 m x 8 m rectangles on a 15 m grid in Berlin
# (longitude/latitude), tagged building=yes and building:levels=1..5, 4 nodes each. Deterministic.
# Written as OPL by awk, then converted by osmium-tool (Debian osmium-tool).
# Usage: bench/make_osm_grid.sh COUNT OUT.osm.pbf
set -euo pipefail
count=$1
out=$2
opl="${out%.osm.pbf}.opl"
awk -v n="$count" 'BEGIN {
  side = int(sqrt(n)) + 1
  mx = 1 / 67800.0; my = 1 / 111250.0   # degrees per meter at 52.5 degrees north
  for (i = 0; i < n; ++i) {
    x = 13.3 + (i % side) * 15 * mx; y = 52.4 + int(i / side) * 15 * my
    id = 4 * i
    printf "n%d v1 x%.7f y%.7f\n", id + 1, x, y
    printf "n%d v1 x%.7f y%.7f\n", id + 2, x + 10 * mx, y
    printf "n%d v1 x%.7f y%.7f\n", id + 3, x + 10 * mx, y + 8 * my
    printf "n%d v1 x%.7f y%.7f\n", id + 4, x, y + 8 * my
  }
  for (i = 0; i < n; ++i) {
    id = 4 * i
    printf "w%d v1 Tbuilding=yes,building:levels=%d Nn%d,n%d,n%d,n%d,n%d\n", i + 1, i % 5 + 1, id + 1, id + 2, id + 3, id + 4, id + 1
  }
}' >"$opl"
osmium cat -O -o "$out" "$opl"
rm -f "$opl"
