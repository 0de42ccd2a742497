#!/usr/bin/env bash
# 3D Tiles output (`-o DIR/tileset.json`, docs/formats.md "3D Tiles"): the bundled town (projected)
# and the OpenStreetMap town (longitude/latitude) written as tilesets and opened the way users open
# them (tools/check_tileset.mjs: structure, Khronos validator per tile, loaders.gl traversal,
# CesiumJS in headless Chromium: every feature loaded, placed where the input lies); the streamed
# job (only tilesets out) and the whole-scene job (with another output) write the same bytes,
# whatever the thread count; a failing run leaves the user's earlier tileset as it was.
source "$(dirname "$0")/lib/common.sh"

check_tileset() {  # description, tileset.json, checker options...
  local what=$1
  shift
  node "$root/tools/check_tileset.mjs" "$@" >"$tmp/c.txt" 2>&1 || { fail "$what"; cat "$tmp/c.txt"; }
}

# The folder is made; the town (EPSG:32633) lies at 14.3869 E, 49.0063 N.
expect_exit 0 "town to 3D Tiles" "$insula" mass "$root/examples/town.geojson" \
  -o "$tmp/town/tileset.json" --quiet
[ -f "$tmp/town/tiles/0-0-0.glb" ] || fail "town: no tile file"
# OpenStreetMap in longitude/latitude: 17 parts of 15 buildings (a church of three parts...).
expect_exit 0 "OSM town to 3D Tiles" "$insula" mass "$root/examples/osm/town.osm" \
  -o "$tmp/osm/tileset.json" --quiet
# The tile-by-tile job reports what the whole-scene job does (counts, warnings, every building).
expect_exit 0 "OSM town, tiles only, report" "$insula" mass "$root/examples/osm/town.osm" \
  -o "$tmp/osm1/tileset.json" --report "$tmp/osm1.json" --report-buildings --quiet
expect_exit 0 "OSM town, tiles and GLB, report" "$insula" mass "$root/examples/osm/town.osm" \
  -o "$tmp/osm2/tileset.json" -o "$tmp/osm2.glb" --report "$tmp/osm2.json" --report-buildings \
  --quiet
node -e '
  const fs = require("fs");
  const keep = (f) => { const r = JSON.parse(fs.readFileSync(f)); delete r.seconds;
                        delete r.stages; delete r.tiles_by_rank; return JSON.stringify(r); };
  if (keep(process.argv[1]) !== keep(process.argv[2])) {
    console.log(keep(process.argv[1])); console.log(keep(process.argv[2])); process.exit(1);
  }' "$tmp/osm1.json" "$tmp/osm2.json" || fail "OSM town: the two jobs report differently"
grep -q '"buildings": 15,' "$tmp/osm1.json" || fail "OSM town: 15 buildings in the report"
diff -r "$tmp/osm/tiles" "$tmp/osm1/tiles" >/dev/null || fail "OSM town: tiles differ between runs"
check_tileset "OSM town opens in CesiumJS and loaders.gl" "$tmp/osm/tileset.json" \
  --expect-features 17 --lonlat 11.3945,47.2655 --tolerance-m 50
grep -q '"building_id":"relation/3001"' "$tmp/c.txt" || fail "OSM town: picked feature's building"
# The building's id does not take the place of OpenStreetMap's own building tag.
grep -q '"building":"apartments"' "$tmp/c.txt" || fail "OSM town: picked feature's building tag"

# A town on the antimeridian (Fiji, lon/lat on both sides of 180 degrees): regions are narrow and
# cross it (west > east), not bands around the globe that no viewer refines (both loaded none).
node "$root/examples/city/make_city.mjs" 600 "$tmp/fiji.geojson" --crs EPSG:32760 \
  --origin 820287.93,8173373.04 >/dev/null
expect_exit 0 "Fiji, on the antimeridian" "$insula" mass "$tmp/fiji.geojson" --tile-faces 3000 \
  -o "$tmp/fiji/tileset.json" --quiet
node -e '
  const t = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const r = t.root.boundingVolume.region;
  const width = ((r[2] - r[0]) % (2 * Math.PI) + 2 * Math.PI) % (2 * Math.PI);
  if (!(r[0] > r[2]) || width > 1e-3) { console.log(JSON.stringify(r)); process.exit(1); }
' "$tmp/fiji/tileset.json" || fail "Fiji: the root region does not cross the antimeridian narrowly"
check_tileset "Fiji opens in CesiumJS and loaders.gl" "$tmp/fiji/tileset.json" \
  --expect-features 600 --lonlat 180,-16.5 --tolerance-m 1000

# Many tiles: 2,500 generated footprints split into tiles of at most 8,000 faces.
node "$root/bench/make_footprints.mjs" 2500 "$tmp/grid.geojson" >/dev/null
for threads in 1 2; do
  expect_exit 0 "grid, $threads thread(s)" "$insula" mass "$tmp/grid.geojson" --crs EPSG:32633 \
    --tile-faces 8000 --threads "$threads" -o "$tmp/grid$threads/tileset.json" --quiet
done
diff -r "$tmp/grid1" "$tmp/grid2" >/dev/null || fail "grid: tiles differ between 1 and 2 threads"
# With a GLB beside it the whole scene is built first: the same tiles.
expect_exit 0 "grid with a GLB" "$insula" mass "$tmp/grid.geojson" --crs EPSG:32633 \
  --tile-faces 8000 -o "$tmp/gridw/tileset.json" -o "$tmp/grid.glb" --quiet
diff -r "$tmp/grid1" "$tmp/gridw" >/dev/null || fail "grid: streamed and whole-scene tiles differ"
leaves=$(ls "$tmp/grid1/tiles" | wc -l)
[ "$leaves" -ge 4 ] || fail "grid: $leaves tiles, expected several"
check_tileset "grid opens in CesiumJS and loaders.gl" "$tmp/grid1/tileset.json" \
  --expect-features 2500

# A building without a CRS cannot be placed: exit 1, the earlier tileset untouched.
cp -r "$tmp/grid1" "$tmp/keep"
echo "mine" >"$tmp/keep/tiles/notes.txt"
cp -r "$tmp/keep" "$tmp/keep.before"
expect_exit 1 "no CRS" "$insula" build "$root/examples/bldg/domus.bldg" \
  -o "$tmp/keep/tileset.json" --quiet
grep -q "no coordinate reference system" "$tmp/err.txt" || { fail "no CRS: message"; cat "$tmp/err.txt"; }
diff -r "$tmp/keep" "$tmp/keep.before" >/dev/null || fail "no CRS: the earlier tileset changed"
ls "$tmp" | grep -q "insula-backup" && fail "no CRS: a backup was left behind"
# A run killed midway (kill -9: no handler runs) leaves the earlier tileset as it was: the tiles
# are written into tiles.insula-partial and renamed into place only at the end.
node "$root/bench/make_footprints.mjs" 60000 "$tmp/big.geojson" >/dev/null
# The run is stopped (SIGSTOP) as soon as a staged tile shows up and killed only if it is still
# staging: a run that committed between the poll and the stop (about 0.7 s of tiles are left when
# the first shows up) proves nothing, so it is run again from the earlier tileset, up to 3 times.
killed_while_staging() {
  "$insula" mass "$tmp/big.geojson" --crs EPSG:32633 --tile-faces 8000 \
    -o "$tmp/keep/tileset.json" --quiet >/dev/null 2>&1 &
  pid=$!
  for _ in $(seq 1800); do  # up to 90 s: the sanitized build is slow
    compgen -G "$tmp/keep/tiles.insula-partial/*.glb" >/dev/null && break
    sleep 0.05
  done
  kill -STOP "$pid" 2>/dev/null
  local staging=no
  [ -d "$tmp/keep/tiles.insula-partial" ] && staging=yes
  kill -9 "$pid" 2>/dev/null
  wait "$pid" 2>/dev/null
  [ $staging = yes ]
}
killed=no
for _ in 1 2 3; do
  killed_while_staging && { killed=yes; break; }
  rm -rf "$tmp/keep"
  cp -r "$tmp/keep.before" "$tmp/keep"
done
[ $killed = yes ] || fail "killed run: the run committed before it was stopped, 3 times"
diff -r -x tiles.insula-partial "$tmp/keep" "$tmp/keep.before" >/dev/null ||
  fail "killed run: the earlier tileset changed"
# The next run clears what the killed one left.
expect_exit 0 "after a killed run" "$insula" mass "$root/examples/town.geojson" \
  -o "$tmp/keep/tileset.json" --quiet
[ -e "$tmp/keep/tiles.insula-partial" ] && fail "after a killed run: the staging folder is left"
[ -f "$tmp/keep/tiles/0-0-0.glb" ] || fail "after a killed run: no tiles"
# The folder's parent must exist.
expect_exit 1 "missing parent folder" "$insula" mass "$root/examples/town.geojson" \
  -o "$tmp/no/such/tileset.json" --quiet

finish tileset
