#!/usr/bin/env bash
# `insula check FILE.cga`: parser + static semantics (docs/cga-language.md, "Static semantics"):
# exact stderr (diagnostics with source line and caret), the summary line, exit codes, -q, and
# every file of the semantic catalog against its `// expect:` lines.
set -u
insula=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
cd "$tmp" || exit 1

# A clean grammar with one warning: warning on stderr, summary on stdout, exit 0.
cat >warn.cga <<'CGA'
attr height = 12
attr unused = 3
PRIORITY 1:
1: Lot ~> extrude(height) Mass
PRIORITY 2:
2: Mass ~> comp(f){ top: Roof | side: Facade }
3: Facade ~> split(y){ 4: Ground | { ~3: Floor }* }
4: Garden ~> Lawn
CGA
"$insula" check warn.cga >out 2>err
code=$?
[ $code -eq 0 ] || fail "warn.cga exits $code"
cat >expected <<'TXT'
warn.cga:2:6: warning[CGA403]: attribute 'unused' is never used
attr unused = 3
     ^~~~~~
warn.cga:8:1: warning[CGA402]: rule '4' is unreachable: 'Garden' is not derived from the start symbol 'Lot'
4: Garden ~> Lawn
^
TXT
diff expected err >/dev/null || { fail "warn.cga stderr"; diff expected err; }
[ "$(cat out)" = "warn.cga: ok: 4 rules (3 reachable), 2 attributes, start 'Lot', 2 warnings" ] ||
  fail "warn.cga summary: $(cat out)"

# -q: errors only, so nothing at all on stderr here.
"$insula" check -q warn.cga >out 2>err
[ $? -eq 0 ] && [ ! -s err ] && [ ! -s out ] || fail "-q prints nothing for a clean grammar"

# --start SYMBOL: reachability from that symbol (rule 1 is now unreachable); a symbol that is
# no rule's predecessor is CGA314 (exit 1, nothing on stdout).
"$insula" check warn.cga --start Mass >out 2>err
[ $? -eq 0 ] || fail "--start Mass exits non-zero"
[ "$(cat out)" = "warn.cga: ok: 4 rules (2 reachable), 2 attributes, start 'Mass', 3 warnings" ] ||
  fail "--start Mass summary: $(cat out)"
grep -qF "warn.cga:4:1: warning[CGA402]: rule '1' is unreachable: 'Lot' is not derived from the start symbol 'Mass'" err ||
  fail "--start Mass: rule 1 reachable? $(cat err)"
"$insula" check -q warn.cga --start Nope >out 2>err
[ $? -eq 1 ] || fail "--start Nope exits 0"
[ -s out ] && fail "--start Nope prints on stdout: $(cat out)"
[ "$(cat err)" = "warn.cga: error[CGA314]: the start symbol 'Nope' is the predecessor of no rule" ] ||
  fail "--start Nope message: $(cat err)"

# Errors: every one at its token, nothing on stdout, exit 1.
cat >bad.cga <<'CGA'
PRIORITY 1:
3: facade ~> BS("X", 2, 3){ tiles | entrance } : 0.5
          ~> BS("X", 3, 2){ entrance | tiles } : 0.4
4: tiles ~> T(1, 0, 0) ε
4: tile ~> CS("edges", 0, 1){ Wall }
CGA
"$insula" check bad.cga >out 2>err
code=$?
[ $code -eq 1 ] || fail "bad.cga exits $code"
[ -s out ] && fail "bad.cga prints on stdout: $(cat out)"
cat >expected <<'TXT'
bad.cga:3:50: error[CGA305]: the probabilities of the 2 parts of the rule sum to 0.9, not 1 (seed 004 §IV.B, constraint 5)
          ~> BS("X", 3, 2){ entrance | tiles } : 0.4
                                                 ^~~
bad.cga:4:24: error[CGA303]: the empty shape has no scope, but the scope rule 'T' is in the same successor (seed 004 §IV.B, constraint 3)
4: tiles ~> T(1, 0, 0) ε
                       ^~
bad.cga:5:1: error[CGA307]: duplicate rule id '4' in priority set 1 (first at line 4)
4: tile ~> CS("edges", 0, 1){ Wall }
^
bad.cga:5:1: warning[CGA402]: rule '4' is unreachable: 'tile' is not derived from the start symbol 'facade'
4: tile ~> CS("edges", 0, 1){ Wall }
^
bad.cga:5:12: error[CGA304]: the component split lists 2 indices but has 1 successor (seed 004 §IV.B, constraint 4)
4: tile ~> CS("edges", 0, 1){ Wall }
           ^~~~~~~~~~~~~~~~~~~~~~~~~
TXT
diff expected err >/dev/null || { fail "bad.cga stderr"; diff expected err; }

# A syntax error stops before the checker.
printf '1: A ~> B : 2 ~> C(\n' >syntax.cga
"$insula" check syntax.cga >out 2>err
[ $? -eq 1 ] || fail "syntax.cga exits 1"
head -1 err | grep -q '^syntax.cga:2:1: error\[CGA1' || { fail "syntax.cga message"; cat err; }
grep -q CGA301 err && fail "the checker must not run after a syntax error"

# The semantic catalog: exit 1 exactly for files with an expected error, and the first line of
# stderr is the first expectation.
count=0
for file in "$root"/tests/data/cga/semantic/*.cga; do
  name=$(basename "$file")
  cp "$file" "$name"
  first=$(head -1 "$name" | sed 's|^// expect: ||')
  "$insula" check "$name" >out 2>err
  code=$?
  if grep -q '^// expect: .*error\[' "$name"; then
    [ $code -eq 1 ] || fail "$name exits $code"
  else
    [ $code -eq 0 ] || fail "$name exits $code"
  fi
  if [ "$first" = nothing ]; then
    [ -s err ] && fail "$name: unexpected stderr $(head -1 err)"
  elif [ "${first#error}" != "$first" ]; then
    [ "$(head -1 err)" = "$name: $first" ] || fail "$name: $(head -1 err)"
  else
    [ "$(head -1 err)" = "$name:$first" ] || fail "$name: $(head -1 err)"
  fi
  count=$((count + 1))
done
[ $count -ge 20 ] || fail "catalog has $count files"

# The corpus: the apartment block checks clean with its summary.
"$insula" check "$root/tests/data/cga/apartment_block.cga" >out 2>err
[ $? -eq 0 ] && [ ! -s err ] || fail "apartment_block.cga: $(cat err)"
grep -qF "ok: 40 rules (40 reachable), 9 attributes, start 'Lot', 0 warnings" out ||
  fail "apartment_block summary: $(cat out)"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all cga check checks passed ($count catalog files)"
