#!/usr/bin/env bash
# `insula check G.graph.json` (graph-format.md §13): the ok summary, diagnostics with carets and
# subgraph notes, exit codes; `insula build` on a graph runs it.
source "$(dirname "$0")/lib/common.sh"

out=$("$insula" check "$root/examples/graph/street_houses.graph.json" 2>&1)
[ $? -eq 0 ] && [ "$out" = "$root/examples/graph/street_houses.graph.json: ok: 3 graphs, 12 nodes, 10 edges, 0 cyclic edges" ] ||
  fail "check street_houses: $out"
for g in "$root"/examples/graph/*.graph.json "$root"/examples/graph/*/*.graph.json; do
  "$insula" check "$g" >/dev/null 2>"$tmp/err" || fail "$(basename "$g") does not check clean: $(cat "$tmp/err")"
  [ -s "$tmp/err" ] && fail "$(basename "$g") has warnings: $(cat "$tmp/err")"
done

# Every example runs clean (no error, no warning, nothing failed or left unprocessed).
for g in "$root"/examples/graph/*.graph.json "$root"/examples/graph/*/*.graph.json; do
  case "$g" in */parts/*) continue ;; esac  # subgraph files: run through their users
  lots=()
  case "$g" in */lots.graph.json) lots=(--lot "$root/examples/cga/district.geojson") ;; esac
  "$insula" build "$g" "${lots[@]}" --report "$tmp/run.json" >/dev/null 2>"$tmp/err" ||
    fail "$(basename "$g") does not run: $(cat "$tmp/err")"
  [ -s "$tmp/err" ] && fail "$(basename "$g") warns when run: $(cat "$tmp/err")"
  node -e 'const g = require(process.argv[1]).graph;
           process.exit(Object.keys(g.failed).length + Object.keys(g.unprocessed).length ? 1 : 0);' \
    "$tmp/run.json" || fail "$(basename "$g"): failed or unprocessed entities"
done

bad=$root/tests/data/graph/bad
"$insula" check "$bad/error_in_subgraph_file.graph.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 1 ] || fail "a graph with an error exits 1"
[ -s "$tmp/out" ] && fail "nothing on stdout for a failed check"
head -1 "$tmp/err" | grep -qF "$bad/parts/broken.graph.json:3:5: error[G021]: shape.extrude: missing required parameter 'height'" ||
  fail "error in a subgraph file: $(cat "$tmp/err")"
# The caret line comes from the subgraph file's own text.
sed -n 2p "$tmp/err" | grep -qF '{ "id": "bad", "type": "shape.extrude" }' || fail "subgraph source line: $(cat "$tmp/err")"
grep -qF "note: in subgraph 'wall' ($bad/parts/broken.graph.json)" "$tmp/err" || fail "subgraph note: $(cat "$tmp/err")"

# Warnings alone: exit 0, the warning on stderr, the summary on stdout.
"$insula" check "$bad/cycle_without_exit.graph.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 0 ] || fail "warnings alone exit 0"
grep -qF "warning[W001]: cycle a -> b -> a has no way out" "$tmp/err" || fail "W001 shown: $(cat "$tmp/err")"
grep -qF "ok: 1 graph, 3 nodes, 3 edges, 1 cyclic edge" "$tmp/out" || fail "summary: $(cat "$tmp/out")"

for f in "$bad"/*.graph.json; do
  timeout 20 "$insula" check "$f" >/dev/null 2>"$tmp/err"
  code=$?
  [ "$code" -le 1 ] || fail "$(basename "$f"): exit $code"
  grep -q "error\[\|warning\[" "$tmp/err" || fail "$(basename "$f"): no diagnostic"
done

# A subgraph file reached through a symbolic link out of the graph's folder is refused.
mkdir -p "$tmp/g" "$tmp/elsewhere"
printf '{ "format": "insula-graph", "version": 1, "nodes": [] }\n' >"$tmp/elsewhere/x.graph.json"
ln -s "$tmp/elsewhere" "$tmp/g/link"
printf '{ "format": "insula-graph", "version": 1, "nodes": [ { "id": "s", "type": "subgraph", "graph": "link/x.graph.json" } ] }\n' >"$tmp/g/top.graph.json"
"$insula" check "$tmp/g/top.graph.json" >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] && grep -qF "error[G031]: cannot read subgraph 'link/x.graph.json': it leads outside the graph's folder" "$tmp/err" ||
  fail "symbolic link out of the folder: $(cat "$tmp/err")"

"$insula" build "$root/examples/graph/footprint_tiles.graph.json" -o "$tmp/tiles.obj" \
  --report "$tmp/tiles.json" >"$tmp/out" 2>"$tmp/err"
[ $? -eq 0 ] || fail "build of a graph exits 0: $(cat "$tmp/err")"
[ -s "$tmp/tiles.obj" ] || fail "build of a graph writes the OBJ"
node -e '
  const g = require(process.argv[1]).graph;
  const ok = g.leaves["faces.rest"].count === 5 && g.leaves["floors.out"].count === 4 &&
    g.entities.length === 9 && g.node_runs.floors.rounds === 1;
  process.exit(ok ? 0 : 1);' "$tmp/tiles.json" || fail "report: $(head -c 400 "$tmp/tiles.json")"

# --probe NODE: what left that node's output ports instead of the results (the studio's graph
# editor shows them for the selected node); as many entities as the run counted on its ports.
fig4=$root/examples/graph/paper/fig4_stairway.graph.json
"$insula" build "$fig4" --report "$tmp/fig4.json" -q || fail "fig4 runs"
houses=$root/examples/graph/street_houses.graph.json
"$insula" build "$houses" --report "$tmp/houses.json" -q || fail "street_houses runs"
probe() {  # graph, whole-run report, node path
  "$insula" build "$1" --probe "$3" -o "$tmp/probe.glb" --report "$tmp/probe.json" -q >/dev/null 2>"$tmp/err" ||
    { fail "--probe $3: $(cat "$tmp/err")"; return; }
  validate_gltf "--probe $3 GLB" "$tmp/probe.glb"
  node -e 'const whole = require(process.argv[1]).graph.ports, probe = require(process.argv[2]);
           const node = process.argv[3];
           const made = Object.entries(whole).filter(([k]) => k.startsWith(node + ".")).reduce((s, [, n]) => s + n, 0);
           const ports = new Set(probe.graph.entities.map((e) => e.port.slice(0, e.port.lastIndexOf("."))));
           process.exit(made > 0 && probe.results === made && probe.buildings > 0 && ports.size === 1 && ports.has(node) ? 0 : 1);' \
    "$2" "$tmp/probe.json" "$3" || fail "--probe $3: $(head -c 300 "$tmp/probe.json")"
}
probe "$fig4" "$tmp/fig4.json" copies
probe "$fig4" "$tmp/fig4.json" solid
probe "$houses" "$tmp/houses.json" low/mass  # inside a file subgraph
probe "$houses" "$tmp/houses.json" signs/board  # inside an inline one
# --report-entities N: the first N result records (the studio's 1,000), the counts whole.
"$insula" build "$fig4" --report "$tmp/few.json" --report-entities 3 -q || fail "--report-entities runs"
node -e 'const r = require(process.argv[1]);
         process.exit(r.results === 17 && r.graph.entities.length === 3 && r.graph.entities_listed === 3 &&
                      r.graph.leaves["stone.out"].count === 17 ? 0 : 1);' "$tmp/few.json" ||
  fail "--report-entities 3: $(head -c 300 "$tmp/few.json")"
expect_exit 2 "--probe of a node the graph lacks" "$insula" build "$fig4" --probe nowhere -o "$tmp/p.glb"
grep -qF "insula: --probe: the graph has no node 'nowhere'" "$tmp/err.txt" || fail "unknown probe message: $(cat "$tmp/err.txt")"
expect_exit 2 "--lot for a graph without create.lots" "$insula" build \
  "$root/examples/graph/footprint_tiles.graph.json" --lot "$root/examples/cga/district.geojson" \
  -o "$tmp/lots.glb"
grep -q "has no create.lots node that reads the --lot file" "$tmp/err.txt" ||
  fail "--lot for a graph without create.lots: $(cat "$tmp/err.txt")"
expect_exit 2 "--probe of a CGA file" "$insula" build "$root/examples/cga/district.cga" --probe x -o "$tmp/p.glb"
grep -qF "insula: --probe: only a graph (.graph.json) has nodes to probe" "$tmp/err.txt" || fail "CGA probe message: $(cat "$tmp/err.txt")"
[ -e "$tmp/p.glb" ] && fail "a refused probe wrote its output"

finish graph_check
