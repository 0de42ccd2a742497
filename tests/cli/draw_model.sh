#!/usr/bin/env bash
# The studio drawing tool's model (tests/web/draw_model.mjs; issue 15): trees of parts and rooms,
# holes and a disposable part written as .bldg and built by the command line.
source "$(dirname "$0")/lib/common.sh"

node "$root/tests/web/draw_model.mjs" "$insula" "$tmp" >"$tmp/draw.txt" 2>&1 ||
  fail "the drawing model: $(cat "$tmp/draw.txt")"
finish draw_model
