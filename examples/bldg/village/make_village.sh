#!/usr/bin/env bash
# Regenerates the stochastic village (seed 000, §4.3 and Fig. 12): 25 buildings from
# `insula random` (5 each of the convex, L, U, T and H configurations, 3-5 rooms per part) in gen/,
# and village.geojson, a lot per building on a street grid (rows per configuration, 6 m streets),
# whose "bldg" property names the grammar built on it. Two more lots carry no grammar: they get
# the default one, village.bldg.
#   usage: make_village.sh [path/to/insula]      then: insula build village.bldg --lot village.geojson -o village.png
set -eu
insula=${1:-insula}
cd "$(dirname "$0")"
rm -rf gen
for shape in convex L U T H; do
  "$insula" random --count 5 --seed 12 --shape "$shape" --rooms 3-5 -o "gen/$shape" --quiet >/dev/null
  rm -f gen/$shape/*.glb gen/$shape/*.json  # only the grammars are kept
done
{
  echo '{"type": "FeatureCollection", "features": ['
  y=0
  first=1
  for shape in convex L U T H; do
    x=0
    row=0
    for f in gen/$shape/*.bldg; do
      # The generated outline is [(0, 0), (W, 0), (W, H), (0, H)]: the lot keeps its size.
      read -r w h < <(sed -n 2p "$f" | sed -E 's/.*\[\(0, 0\), \(([0-9.]+), 0\), \(([0-9.]+), ([0-9.]+)\).*/\1 \3/')
      id="$shape-$(basename "$f" .bldg | sed 's/building_//')"
      [ $first -eq 1 ] || echo ','
      first=0
      awk -v id="$id" -v f="$f" -v x="$x" -v y="$y" -v w="$w" -v h="$h" 'BEGIN {
        printf "{\"type\": \"Feature\", \"id\": \"%s\", \"properties\": {\"bldg\": \"%s\"}, ", id, f
        printf "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[%g, %g], [%g, %g], [%g, %g], [%g, %g], [%g, %g]]]}}", x, y, x + w, y, x + w, y + h, x, y + h, x, y }'
      x=$(awk -v x="$x" -v w="$w" 'BEGIN { print x + w + 6 }')
      row=$(awk -v r="$row" -v h="$h" 'BEGIN { print (h > r ? h : r) }')
    done
    y=$(awk -v y="$y" -v r="$row" 'BEGIN { print y + r + 6 }')
  done
  # Two houses from the default grammar on a street in front of the first row.
  for k in 1 2; do
    x=$(awk -v k="$k" 'BEGIN { print (k - 1) * 20 }')
    echo ','
    awk -v id="house-$k" -v x="$x" -v y=-16 'BEGIN {
      printf "{\"type\": \"Feature\", \"id\": \"%s\", \"properties\": {}, ", id
      printf "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[%g, %g], [%g, %g], [%g, %g], [%g, %g], [%g, %g]]]}}", x, y, x + 14, y, x + 14, y + 10, x, y + 10, x, y }'
  done
  echo ']}'
} > village.geojson
