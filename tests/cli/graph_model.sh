#!/usr/bin/env bash
# The graph editor's document model (tests/web/graph_model.mjs; issue 16): encapsulation keeps
# crossing edges' fields and the run's result, the layout survives cycles.
source "$(dirname "$0")/lib/common.sh"

node "$root/tests/web/graph_model.mjs" "$insula" "$tmp" >"$tmp/graph.txt" 2>&1 ||
  fail "the graph model: $(cat "$tmp/graph.txt")"
finish graph_model
