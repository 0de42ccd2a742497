#!/usr/bin/env bash
# The city example (examples/graph/city) on a 3 x 3 street grid: byte-identical GLB and OBJ for
# one and two threads (graph-format.md §9.8), a valid glTF, and the report's counts derived by
# hand: four 60 x 50 blocks halved three times (3000 -> 1500 -> 750 -> 375 m2, x, y, x) give
# 4 x 2 lots each, 32 lots in all.
source "$(dirname "$0")/lib/common.sh"

city=$root/examples/graph/city/city.graph.json
# Same file names in two folders: the OBJ names its MTL file.
for n in 1 2; do
  mkdir -p "$tmp/t$n"
  expect_exit 0 "city with $n thread(s)" "$insula" build "$city" --set columns=3 --set rows=3 \
    --threads "$n" -o "$tmp/t$n/city.glb" -o "$tmp/t$n/city.obj" --report "$tmp/r$n.json" --quiet
done
for f in city.glb city.obj city.mtl; do
  [ -s "$tmp/t1/$f" ] || fail "missing output $f"
  cmp -s "$tmp/t1/$f" "$tmp/t2/$f" || fail "$f differs between 1 and 2 threads"
done
validate_gltf "glTF validator on the city" "$tmp/t1/city.glb"

# Leaves: one road surface; per lot a pavement ring, a hip roof and 4 walls. A lot's wall faces
# a street unless a neighbour stands in front of it: in a block of 4 x 2 lots every lot shows
# its long outer wall and the 4 corner lots a side wall too, 12 per block, 48 shop walls; the
# other 80 are plain. One lamp post per street edge: 2 x 3 + 3 x 2 = 12, each with a light; the
# 9 crossings are blocked. The cycle checks 1 + 2 + 4 + 8 = 15 pieces per block and halves 7 of them.
node -e '
  const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
  const g = r.graph;
  const want = { "asphalt.out": 1, "paving.out": 32, "plain.out": 80, "shops.out": 48,
                 "steel.out": 12, "tiles.out": 32, "glow.out": 12 };
  const bad = [];
  for (const [port, n] of Object.entries(want)) {
    const type = port === "glow.out" ? "light" : "shape";
    if (!g.leaves[port] || g.leaves[port].count !== n || g.leaves[port].types[type] !== n)
      bad.push(port + " " + JSON.stringify(g.leaves[port]) + ", expected " + n);
  }
  if (Object.keys(g.leaves).length !== 7) bad.push("leaves " + Object.keys(g.leaves));
  if (g.blocked["pieces.vertices"] !== 9) bad.push("blocked " + JSON.stringify(g.blocked));
  if (Object.keys(g.failed).length || Object.keys(g.unprocessed).length)
    bad.push("failed or unprocessed " + JSON.stringify([g.failed, g.unprocessed]));
  const runs = (id) => g.node_runs[id].rounds;
  if (runs("small") !== 60 || runs("longer") !== 28 || runs("halve_x") !== 20 || runs("halve_y") !== 8)
    bad.push("cycle rounds " + [runs("small"), runs("longer"), runs("halve_x"), runs("halve_y")]);
  if (g.node_runs.number.executions !== 1 || runs("mass") !== 32 || runs("shops") !== 48)
    bad.push("node runs " + JSON.stringify(g.node_runs));
  if (g.entities.length !== 217) bad.push("result entities " + g.entities.length);
  const floors = new Set(g.entities.filter((e) => e.port === "tiles.out").map((e) => e.attributes.building));
  if (floors.size !== 32) bad.push("buildings numbered " + floors.size);
  if (bad.length) { console.log(bad.join("\n")); process.exit(1); }' "$tmp/r1.json" ||
  fail "city report"
cmp -s <(node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
                  delete r.seconds; delete r.threads;
                  for (const n of Object.values(r.graph.node_runs)) delete n.seconds;
                  console.log(JSON.stringify(r))' "$tmp/r1.json") \
  <(node -e 'const r = JSON.parse(require("fs").readFileSync(process.argv[1]));
             delete r.seconds; delete r.threads;
             for (const n of Object.values(r.graph.node_runs)) delete n.seconds;
             console.log(JSON.stringify(r))' "$tmp/r2.json") ||
  fail "reports differ between 1 and 2 threads (beyond timings)"

finish graph_city
