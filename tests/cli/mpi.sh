#!/usr/bin/env bash
# Many processes (docs/cluster.md): `mpirun -n N insula mass|build ... -o DIR/tileset.json` shares the
# tiles among the ranks through a work queue and writes the same bytes as one process, for 1, 2 and
# 3 ranks and any thread count; the leader alone prints, its progress counting every rank's
# buildings; an error stops every rank with exit 1 and leaves the user's earlier tileset as it was.
# Runs on this 2-core machine with --oversubscribe.
source "$(dirname "$0")/lib/common.sh"

command -v mpirun >/dev/null || { fail "mpirun missing (scripts/setup.sh installs openmpi-bin)"; finish mpi; }
if ! ldd "$insula" | grep -q libmpi; then
  # The sanitized build (scripts/test_asan.sh) leaves MPI out on purpose; the release build has it.
  [ "${INSULA_NO_MPI_EXPECTED:-0}" = 1 ] && { echo "mpi: skipped (sanitized build, no MPI)"; finish mpi; }
  fail "insula was built without MPI (libopenmpi-dev)"
  finish mpi
fi
# OpenMPI refuses root unless told; CI may run as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
mpi() { mpirun --oversubscribe -n "$@"; }

node "$root/bench/make_footprints.mjs" 3000 "$tmp/grid.geojson" >/dev/null
expect_exit 0 "one process" "$insula" mass "$tmp/grid.geojson" --crs EPSG:32633 \
  --tile-faces 6000 -o "$tmp/one/tileset.json" --report "$tmp/one.json" --quiet
leaves=$(ls "$tmp/one/tiles" | wc -l)
[ "$leaves" -ge 6 ] || fail "expected several tiles, got $leaves"
for ranks in 1 2 3; do
  for threads in 1 2; do
    expect_exit 0 "$ranks ranks, $threads threads" mpi "$ranks" -x INSULA_PROGRESS_SECONDS=0 \
      "$insula" mass "$tmp/grid.geojson" --crs EPSG:32633 --tile-faces 6000 --threads "$threads" \
      -o "$tmp/r$ranks-$threads/tileset.json" --report "$tmp/r$ranks-$threads.json"
    diff -r "$tmp/one" "$tmp/r$ranks-$threads" >/dev/null ||
      fail "$ranks ranks, $threads threads: the tileset differs from one process's"
    # One line per output on stdout, from the leader only.
    [ "$(grep -c tileset.json "$tmp/out.txt")" -eq 1 ] || { fail "$ranks ranks: stdout"; cat "$tmp/out.txt"; }
    # The leader's progress counts every rank's buildings, to the last.
    grep "of 3000 buildings" "$tmp/err.txt" | tail -n 1 | grep -q "^insula: 3000 of 3000 buildings (100%)" ||
      { fail "$ranks ranks, $threads threads: progress"; tail -n 3 "$tmp/err.txt"; }
  done
done
grep -q '"buildings": 3000,' "$tmp/r3-2.json" || fail "3 ranks: the report counts every building"
# Every rank took tiles from the queue (three ranks, at least six tiles).
node -e '
  const r = require(process.argv[1]);
  if (r.ranks !== 3 || r.tiles_by_rank.length !== 3 || r.tiles_by_rank.some((n) => n === 0) ||
      r.tiles_by_rank.reduce((a, b) => a + b) !== Number(process.argv[2])) {
    console.log(JSON.stringify(r.tiles_by_rank)); process.exit(1);
  }' "$tmp/r3-1.json" "$leaves" || fail "3 ranks: tiles not shared among the ranks"

# `insula build` of a CGA city shares its tiles (and its CityJSONSeq lines) too: the same bytes as
# one process.
node "$root/examples/city/make_city.mjs" 120 "$tmp/lots.geojson" >/dev/null
expect_exit 0 "CGA city, one process" "$insula" build "$root/examples/cga/district.cga" \
  --lot "$tmp/lots.geojson" --tile-faces 20000 --tile-blocks 60 -o "$tmp/cga1/tileset.json" \
  -o "$tmp/cga1.city.jsonl" --quiet
for ranks in 2 3; do
  expect_exit 0 "CGA city, $ranks ranks" mpi "$ranks" "$insula" build \
    "$root/examples/cga/district.cga" --lot "$tmp/lots.geojson" --tile-faces 20000 --tile-blocks 60 \
    -o "$tmp/cga$ranks/tileset.json" -o "$tmp/cga$ranks.city.jsonl" --report "$tmp/cga$ranks.json"
  diff -r "$tmp/cga1" "$tmp/cga$ranks" >/dev/null ||
    fail "CGA city, $ranks ranks: the tileset differs from one process's"
  cmp -s "$tmp/cga1.city.jsonl" "$tmp/cga$ranks.city.jsonl" ||
    fail "CGA city, $ranks ranks: the CityJSONSeq differs from one process's"
  [ "$(grep -c "tileset.json\|city.jsonl" "$tmp/out.txt")" -eq 2 ] ||
    { fail "CGA, $ranks ranks: stdout"; cat "$tmp/out.txt"; }
done
grep -q '"ranks": 3,' "$tmp/cga3.json" || fail "CGA city, 3 ranks: the report's ranks"
# A per-lot graph likewise (graph_tiles.h).
lots_graph="$root/examples/graph/city/lots.graph.json"
expect_exit 0 "graph city, one process" "$insula" build "$lots_graph" --lot "$tmp/lots.geojson" \
  --tile-faces 20000 -o "$tmp/g1/tileset.json" -o "$tmp/g1.city.jsonl" -q
expect_exit 0 "graph city, 2 ranks" mpi 2 "$insula" build "$lots_graph" --lot "$tmp/lots.geojson" \
  --tile-faces 20000 -o "$tmp/g2/tileset.json" -o "$tmp/g2.city.jsonl" -q
diff -r "$tmp/g1" "$tmp/g2" >/dev/null || fail "graph city, 2 ranks: the tileset differs from one process's"
cmp -s "$tmp/g1.city.jsonl" "$tmp/g2.city.jsonl" || fail "graph city, 2 ranks: the CityJSONSeq differs"
# A .bldg village likewise.
village="$root/examples/bldg/village"
expect_exit 0 "village, one process" "$insula" build "$village/village.bldg" \
  --lot "$village/village.geojson" --crs EPSG:3857 --tile-faces 20000 -o "$tmp/v1/tileset.json" -q
expect_exit 0 "village, 2 ranks" mpi 2 "$insula" build "$village/village.bldg" \
  --lot "$village/village.geojson" --crs EPSG:3857 --tile-faces 20000 -o "$tmp/v2/tileset.json" -q
diff -r "$tmp/v1" "$tmp/v2" >/dev/null || fail "village, 2 ranks: the tileset differs from one process's"

# An error: no CRS to place the tiles; every rank stops, exit 1, the earlier tileset kept.
cp -r "$tmp/one" "$tmp/keep"
sed 's/"crs"/"not_crs"/' "$root/examples/town.geojson" >"$tmp/nocrs.geojson"
expect_exit 1 "no CRS under mpirun" mpi 3 "$insula" mass "$tmp/nocrs.geojson" \
  -o "$tmp/keep/tileset.json" --quiet
grep -q "no coordinate reference system" "$tmp/err.txt" || { fail "no CRS: message"; cat "$tmp/err.txt"; }
diff -r "$tmp/one" "$tmp/keep" >/dev/null || fail "no CRS: the earlier tileset changed"

finish mpi
