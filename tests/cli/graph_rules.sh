#!/usr/bin/env bash
# Rule nodes (docs/graph-executor.md, "Rule nodes"): one graph runs a CGA rule file, a .bldg
# grammar, a Lua program and a PLaSM expression on its lots (examples/graph/rules); a broken rule
# file stops the run with its own diagnostic and writes nothing.
source "$(dirname "$0")/lib/common.sh"

ex=$root/examples/graph/rules
"$insula" build "$ex/rules.graph.json" -o "$tmp/rules.obj" --report "$tmp/rules.json" >/dev/null 2>"$tmp/err" ||
  fail "rules graph builds: $(cat "$tmp/err")"
[ -s "$tmp/err" ] && fail "rules graph has warnings: $(cat "$tmp/err")"
node -e '
  const g = require(process.argv[1]).graph;
  const by = Object.fromEntries(g.entities.map(e => [e.port, e]));
  const problems = [];
  for (const port of ["shop.out", "house.out", "lua_house.out", "column.out"])
    if (!by[port]) problems.push("no entity at " + port);
  // CGA: a 12 x 10 lot extruded 7 m; four merged parts (plaster, glass, sign board, roof).
  if (by["shop.out"] && (by["shop.out"].parts !== 4 || Math.abs(by["shop.out"].volume - 840) > 1e-6))
    problems.push("cga: " + JSON.stringify(by["shop.out"]));
  // .bldg: the two-storey house on the lot (walls, slabs, stair, roof: several parts).
  if (by["house.out"] && !(by["house.out"].parts >= 8)) problems.push("bldg: " + by["house.out"].parts);
  // Lua: params.height is the graph attribute (10 m), on the lot inset by 1.5 m: 9 x 7 x 10 walls.
  if (by["lua_house.out"] && by["lua_house.out"].attributes.height !== 10)
    problems.push("lua height: " + JSON.stringify(by["lua_house.out"].attributes));
  if (Object.keys(g.failed).length) problems.push("failed: " + JSON.stringify(g.failed));
  if (problems.length) { console.error(problems.join("\n")); process.exit(1); }' "$tmp/rules.json" ||
  fail "rules report"
[ -s "$tmp/rules.obj" ] || fail "rules OBJ written"

# A rule file with a syntax error: its diagnostic, exit 1, no output.
mkdir -p "$tmp/bad"
cp "$ex/rules.graph.json" "$ex/two_storey.bldg" "$ex/house.lua" "$ex/column.psm" "$tmp/bad/"
printf 'PRIORITY 1:\nlot: Lot ~> extrude(\n' >"$tmp/bad/shop.cga"
"$insula" build "$tmp/bad/rules.graph.json" -o "$tmp/bad/out.obj" >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] || fail "a broken rule file exits 1"
grep -qF "$tmp/bad/shop.cga:3:1: error[" "$tmp/err" || fail "the CGA diagnostic: $(cat "$tmp/err")"
grep -qF "error[G052]" "$tmp/err" || fail "the run stops at the rule node: $(cat "$tmp/err")"
[ -e "$tmp/bad/out.obj" ] && fail "nothing written after a broken rule file"

# A rule file outside the graph's folder is refused like an asset.
sed 's|"file": "shop.cga"|"file": "../shop.cga"|' "$ex/rules.graph.json" >"$tmp/bad/rules.graph.json"
"$insula" build "$tmp/bad/rules.graph.json" -o "$tmp/bad/out.obj" >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] && grep -qF "cannot read rule file '../shop.cga'" "$tmp/err" ||
  fail "rule file outside the folder: $(cat "$tmp/err")"
finish graph_rules
