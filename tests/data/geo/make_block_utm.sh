#!/usr/bin/env bash
# Writes block_utm.geojson and block_3857.geojson: block_lonlat.geojson (RFC 7946
# longitude/latitude, as an OSM export gives it) reprojected by PROJ's cs2cs (Debian proj-bin) to
# WGS 84 / UTM zone 33N and to Web Mercator (EPSG:3857, as web map exports give it; its meters are
# 1.64 ground meters at this latitude), each with a "crs" member, millimetre digits. The reader's
# reprojection is checked against them (geojson_reader_test.cc,
# LonLatBlockGivesTheSameBuildingsAsItsUtmVersion, WebMercatorGivesTheSameBuildingsAsLonLat).
# Usage: tests/data/geo/make_block_utm.sh   (from anywhere; rewrites the files next to this script)
set -euo pipefail
cd "$(dirname "$0")"
node -e '
  const doc = JSON.parse(require("fs").readFileSync("block_lonlat.geojson", "utf8"));
  const out = [];
  const walk = (c) => (typeof c[0] === "number" ? out.push(c[0] + " " + c[1]) : c.forEach(walk));
  doc.features.forEach((f) => walk(f.geometry.coordinates));
  console.log(out.join("\n"));' >/tmp/block_lonlat.$$.txt
write() {  # EPSG code, output file
  cs2cs -f %.3f OGC:CRS84 "EPSG:$1" </tmp/block_lonlat.$$.txt >/tmp/block_xy.$$.txt
  node -e '
    const fs = require("fs");
    const doc = JSON.parse(fs.readFileSync("block_lonlat.geojson", "utf8"));
    const xy = fs.readFileSync(process.argv[1], "utf8").trim().split("\n").map((l) => l.split(/\s+/).slice(0, 2).map(Number));
    let next = 0;
    const walk = (c) => (typeof c[0] === "number" ? xy[next++] : c.map(walk));
    doc.features.forEach((f) => { f.geometry.coordinates = walk(f.geometry.coordinates); });
    const out = { type: "FeatureCollection", crs: { type: "name", properties: { name: "urn:ogc:def:crs:EPSG::" + process.argv[2] } },
                  generator: "make_block_utm.sh from block_lonlat.geojson", features: doc.features };
    fs.writeFileSync(process.argv[3], JSON.stringify(out, null, 1) + "\n");' /tmp/block_xy.$$.txt "$1" "$2"
}
write 32633 block_utm.geojson
write 3857 block_3857.geojson
rm -f /tmp/block_lonlat.$$.txt /tmp/block_xy.$$.txt
