#!/usr/bin/env bash
# `insula check FILE.psm` (docs/plasm-language.md): every example passes with its summary line,
# a bad program gets its exact diagnostic with the source line and caret and exit 1, -q keeps
# errors, and `insula build FILE.psm` stops at the same diagnostics before writing anything.
set -u
insula=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

count=0
for f in "$root"/examples/plasm/*.psm; do
  out=$("$insula" check "$f" 2>&1) || fail "$f: $out"
  case $out in *": ok: "*" function"*", "*" value"*", "*" expression"*) ;; *) fail "$f summary: $out" ;; esac
  count=$((count + 1))
done
[ $count -ge 8 ] || fail "only $count examples"
[ "$("$insula" check "$root/examples/plasm/column.psm")" = \
  "$root/examples/plasm/column.psm: ok: 1 function, 0 values, 1 expression" ] || fail "column summary"

cd "$tmp" || exit 1
# The paper's Listing 2 as printed uses d/2 for dm/2: the checker names the parameter.
cat >column.psm <<'PSM'
DEF columna (dm,h,h_base::isReal) = torus_bot
WHERE
    torus_bot = (JOIN~TORUS:<dm/12,d/2>):<8,24>
END;
PSM
"$insula" check column.psm >out 2>err
code=$?
[ $code -eq 1 ] || fail "column.psm exits $code"
[ -s out ] && fail "column.psm wrote to stdout: $(cat out)"
cat >expected <<'TXT'
column.psm:3:36: error[PSM301]: unknown name 'd'; did you mean 'dm'?
    torus_bot = (JOIN~TORUS:<dm/12,d/2>):<8,24>
                                   ^
TXT
diff expected err >/dev/null || { fail "column.psm stderr"; diff expected err; }
"$insula" check -q column.psm 2>err >/dev/null
[ "$(head -1 err)" = "column.psm:3:36: error[PSM301]: unknown name 'd'; did you mean 'dm'?" ] ||
  fail "-q drops the error: $(cat err)"

# A syntax error is reported by the parser and the checker does not run.
printf 'DEF a = 1 +;\nDEF b = nowhere;\n' >syntax.psm
"$insula" check -q syntax.psm 2>err
code=$?
[ $code -eq 1 ] || fail "syntax.psm exits $code"
[ "$(cat err | grep -c error)" = 1 ] || fail "syntax.psm: $(cat err)"

# build runs the same checks first: the checker's error, exit 1, nothing written.
"$insula" build column.psm -o out.obj >out 2>err
code=$?
[ $code -eq 1 ] || fail "build exits $code"
[ "$(head -1 err)" = "column.psm:3:36: error[PSM301]: unknown name 'd'; did you mean 'dm'?" ] ||
  fail "build message: $(cat err)"
[ -e out.obj ] && fail "build wrote out.obj"

[ $failures -eq 0 ] && echo "plasm_check: ok"
exit $((failures > 0))
