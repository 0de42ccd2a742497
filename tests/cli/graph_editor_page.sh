#!/usr/bin/env bash
# The studio's graph editor in headless chromium (tests/web/graph_editor.mjs; issue 16): seed 003's
# Fig. 4 built by hand, counts on its ports, a refused connection, undo, copy and paste, the saved
# file run by `insula build` with the same counts, the bundled city graph drawn, the city's
# edit-to-counts time on about 1,000 lots.
source "$(dirname "$0")/lib/common.sh"

[ -f "$root/web/dist/studio.js" ] || { fail "web/dist/studio.js missing (scripts/setup.sh builds it)"; finish graph_editor_page; }
node "$root/tests/web/graph_editor.mjs" "$insula" "$root" "$tmp" >"$tmp/page.txt" 2>&1 ||
  fail "the graph editor: $(cat "$tmp/page.txt")"
grep -E 'edit to port counts|latency is measured' "$tmp/page.txt"
finish graph_editor_page
