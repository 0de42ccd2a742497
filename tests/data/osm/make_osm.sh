#!/usr/bin/env bash
# Writes the .osm test files of this folder from a table of nodes in WGS 84 / UTM zone 33N
# meters (offsets from E 390000, N 5820000, in Berlin), converted to longitude/latitude by PROJ's
# cs2cs (Debian proj-bin) with 9 decimals (0.1 mm): the footprints' areas in UTM are then known
# exactly (osm_reader_test.cc). Usage: tests/data/osm/make_osm.sh (rewrites the files beside it).
set -euo pipefail
cd "$(dirname "$0")"
# id  east  north
nodes="
1 0 0
2 20 0
3 20 10
4 0 10
5 2 2
6 10 2
7 10 8
8 2 8
11 50 0
12 80 0
13 80 30
14 50 30
15 60 10
16 70 10
17 70 20
18 60 20
21 100 0
22 110 0
23 110 20
24 100 20
"
node_xml() {  # node ids...
  for id in "$@"; do
    echo "$nodes" | awk -v id="$id" '$1 == id { print 390000 + $2, 5820000 + $3, 0, $1 }'
  done | cs2cs -f %.9f EPSG:32633 OGC:CRS84 |
    awk '{ printf "  <node id=\"%s\" version=\"1\" lat=\"%s\" lon=\"%s\"/>\n", $4, $2, $1 }'
}
way() {  # id "tags k=v;k=v" node ids...
  local id=$1 tags=$2
  shift 2
  echo "  <way id=\"$id\" version=\"1\">"
  for n in "$@"; do echo "    <nd ref=\"$n\"/>"; done
  tag_xml "$tags"
  echo "  </way>"
}
tag_xml() {
  local IFS=';'
  for kv in $1; do
    [ -n "$kv" ] && echo "    <tag k=\"${kv%%=*}\" v=\"${kv#*=}\"/>"
  done
  return 0
}
multipolygon() {  # id "tags" role:way...
  local id=$1 tags=$2
  shift 2
  echo "  <relation id=\"$id\" version=\"1\">"
  for m in "$@"; do echo "    <member type=\"way\" ref=\"${m#*:}\" role=\"${m%%:*}\"/>"; done
  tag_xml "type=multipolygon;$tags"
  echo "  </relation>"
}
osm() {  # file, then the body on stdin
  {
    echo '<?xml version="1.0" encoding="UTF-8"?>'
    echo '<osm version="0.6" generator="tests/data/osm/make_osm.sh">'
    cat
    echo '</osm>'
  } >"$1"
}

# A building way (20 m x 10 m, S3DB tags), a building:part inside it (8 m x 6 m), a multipolygon
# with a courtyard (30 m x 30 m less 10 m x 10 m), a multipolygon whose outer ring is two ways
# (10 m x 20 m), and a road that is not a building.
{
  node_xml 1 2 3 4 5 6 7 8 11 12 13 14 15 16 17 18 21 22 23 24
  way 101 "building=yes;height=12;building:levels=4;roof:shape=gabled;roof:height=3;name=Haus Eins" 1 2 3 4 1
  way 111 "" 11 12 13 14 11
  way 112 "" 15 16 17 18 15
  way 113 "" 21 22 23
  way 114 "" 23 24 21
  way 121 "building:part=yes;min_height=5;height=10;building:colour=#aa3333" 5 6 7 8 5
  way 191 "highway=residential" 1 11
  multipolygon 201 "building=apartments;roof:shape=flat" outer:111 inner:112
  multipolygon 202 "building=yes" outer:113 outer:114
} | osm buildings.osm

# Broken: a building way with a node that is not in the file (and one good building).
{
  node_xml 1 2 3 4
  way 101 "building=yes" 1 2 3 4 1
  way 102 "building=yes" 1 2 999 1
} | osm missing_node.osm

# Broken: a multipolygon whose outer ring does not close (and one good building).
{
  node_xml 1 2 3 4 21 22 23 24
  way 101 "building=yes" 1 2 3 4 1
  way 115 "" 21 22 23 24
  multipolygon 203 "building=yes" outer:115
} | osm unclosed_multipolygon.osm

# Broken: a building way that does not end where it starts (and one good building).
{
  node_xml 1 2 3 4 21 22 23
  way 101 "building=yes" 1 2 3 4 1
  way 104 "building=house" 21 22 23
} | osm open_way.osm
