#!/usr/bin/env bash
# The studio's page in headless chromium (tests/web/studio.mjs; issue 15): open, build, a mistake
# underlined at its line, the fix shown, a pick, a save, the district's edit-to-view time.
source "$(dirname "$0")/lib/common.sh"

[ -f "$root/web/dist/studio.js" ] || { fail "web/dist/studio.js missing (scripts/setup.sh builds it)"; finish studio_page; }
node "$root/tests/web/studio.mjs" "$insula" "$root" "$tmp" >"$tmp/page.txt" 2>&1 ||
  fail "the studio page: $(cat "$tmp/page.txt")"
grep 'edit to view' "$tmp/page.txt"
finish studio_page
