#!/usr/bin/env bash
# `insula transform` (seed 004 §IV, §VII): every grammar of tests/data/cga to each format, JSON
# outputs validated against docs/cga-model.schema.json with ajv, XMI and XML well-formed
# (xmllint), DOT rendered when graphviz is installed, the BuildingGen round trip, the Fig. 15
# checks, bad input (exit 1, no file, earlier file kept) and usage errors (exit 2).
set -u
insula=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
data=$root/tests/data/cga

# ---- every grammar, every format ----
json_files=()
transformed=0
for grammar in "$data"/*.cga "$data"/transform/*.cga; do
  stem=$(basename "$grammar" .cga)
  if ! "$insula" check -q "$grammar" >/dev/null 2>&1; then
    # A grammar the checker rejects is not transformed: exit 1 and no file.
    "$insula" transform "$grammar" --to json -o "$tmp/$stem.rejected.json" -q 2>/dev/null
    [ $? -eq 1 ] && [ ! -e "$tmp/$stem.rejected.json" ] || fail "$stem: rejected grammar transformed"
    continue
  fi
  transformed=$((transformed + 1))
  for to in json graph-json xmi dot cga; do
    "$insula" transform "$grammar" --to "$to" -o "$tmp/$stem.out.$to" -q 2>"$tmp/err" ||
      { fail "$stem --to $to"; cat "$tmp/err"; }
  done
  cp "$tmp/$stem.out.json" "$tmp/$stem.model.json"
  cp "$tmp/$stem.out.graph-json" "$tmp/$stem.graph.json"
  json_files+=("$tmp/$stem.model.json" "$tmp/$stem.graph.json")
  grep -q '"format": "insula-cga-model"' "$tmp/$stem.model.json" || fail "$stem: model format"
  xmllint --noout "$tmp/$stem.out.xmi" || fail "$stem: XMI not well-formed"
  grep -q '<cga:ShapeGrammar xmi:version="2.0"' "$tmp/$stem.out.xmi" || fail "$stem: XMI root"
  head -1 "$tmp/$stem.out.dot" | grep -q '^digraph derivation {$' || fail "$stem: DOT header"
  if command -v dot >/dev/null 2>&1; then
    dot -Tsvg "$tmp/$stem.out.dot" -o "$tmp/$stem.svg" || fail "$stem: dot cannot render"
  fi
  # The printed grammar is a grammar again, and printing it is a fixed point.
  cp "$tmp/$stem.out.cga" "$tmp/$stem.printed.cga"
  "$insula" transform "$tmp/$stem.printed.cga" --to cga -o "$tmp/$stem.again.cga" -q ||
    fail "$stem: printed grammar does not transform"
  cmp -s "$tmp/$stem.printed.cga" "$tmp/$stem.again.cga" || fail "$stem: printing is not a fixed point"
done
[ "$transformed" -ge 3 ] || fail "only $transformed grammars passed the checker"
if command -v node >/dev/null 2>&1 && [ -d "$root/tools/node_modules/ajv" ]; then
  # The committed goldens of the library tests too.
  json_files+=("$data/transform/paper_fig13.json" "$data/transform/paper_fig13.graph.json")
  node "$root/tools/validate_json_schema.mjs" "$root/docs/cga-model.schema.json" "${json_files[@]}" \
    >"$tmp/ajv" || { fail "JSON schema validation"; grep -v ': valid$' "$tmp/ajv" | head -20; }
else
  echo "note: node or ajv missing, JSON schema validation skipped"
fi

# ---- BuildingGen XML: cga -> xml -> cga -> xml ----
"$insula" transform "$data/transform/fig16_facade.cga" --to xml -o "$tmp/fig16.xml" -q ||
  fail "fig16 to xml"
xmllint --noout "$tmp/fig16.xml" || fail "BuildingGen XML not well-formed"
cmp -s "$tmp/fig16.xml" "$data/transform/fig16_facade.xml" || fail "fig16 XML differs from golden"
"$insula" transform "$tmp/fig16.xml" --to cga -o "$tmp/fig16.back.cga" -q || fail "xml to cga"
cmp -s "$tmp/fig16.back.cga" "$data/transform/fig16_facade.back.cga" || fail "read-back grammar"
"$insula" transform "$tmp/fig16.back.cga" --to xml -o "$tmp/fig16.again.xml" -q ||
  fail "read-back grammar to xml"
cmp -s "$tmp/fig16.xml" "$tmp/fig16.again.xml" || fail "xml -> cga -> xml is not the same XML"

# ---- Fig. 15 check rules: errors at the token, exit 1, no file, an earlier file kept ----
echo keep >"$tmp/kept.xml"
"$insula" transform "$data/transform/bad_buildinggen/scope_rule.cga" --to xml -o "$tmp/kept.xml" \
  >/dev/null 2>"$tmp/err"
[ $? -eq 1 ] || fail "check rule violation exits 1"
grep -qF "scope_rule.cga:4:11: error[CGA503]: scope rules are not acceptable in BuildingGen XML ('T')" \
  "$tmp/err" || { fail "CGA503 message"; cat "$tmp/err"; }
[ "$(cat "$tmp/kept.xml")" = keep ] || fail "failed transform replaced the earlier file"
"$insula" transform "$data/transform/bad_buildinggen/no_facade.cga" --to xml -o "$tmp/nf.xml" 2>"$tmp/err"
[ $? -eq 1 ] && [ ! -e "$tmp/nf.xml" ] || fail "no Facade: exit 1, no file"
grep -qF "no_facade.cga:1:1: error[CGA502]: the default Facade shape is not defined" "$tmp/err" ||
  { fail "CGA502 message"; cat "$tmp/err"; }

# ---- bad input ----
"$insula" transform "$data/transform/bad_xml/undefined_shape.xml" --to cga -o "$tmp/u.cga" 2>"$tmp/err"
[ $? -eq 1 ] && [ ! -e "$tmp/u.cga" ] || fail "bad XML: exit 1, no file"
grep -qF "undefined_shape.xml:4:46: error[CGA529]: shape 'Door' is neither the predecessor" "$tmp/err" ||
  { fail "CGA529 message"; cat "$tmp/err"; }
for bad in "$data"/transform/bad_xml/*.xml; do
  timeout 20 "$insula" transform "$bad" --to cga -o "$tmp/bad.cga" 2>/dev/null
  [ $? -eq 1 ] && [ ! -e "$tmp/bad.cga" ] || fail "$(basename "$bad"): exit 1 without output"
done
"$insula" transform "$data/bad/missing_arrow.cga" --to json -o "$tmp/m.json" 2>"$tmp/err"
[ $? -eq 1 ] && [ ! -e "$tmp/m.json" ] || fail "parse error: exit 1, no file"
grep -q "missing_arrow.cga:[0-9]*:[0-9]*: error\[CGA" "$tmp/err" || fail "parse error message"
"$insula" transform "$tmp/missing.cga" --to json 2>"$tmp/err"
[ $? -eq 1 ] && grep -q "missing.cga: error: cannot read file" "$tmp/err" || fail "missing file"

# ---- stdout and usage errors ----
"$insula" transform "$data/paper_fig13.cga" --to dot 2>/dev/null | head -1 | grep -q '^digraph' ||
  fail "DOT on stdout"
"$insula" transform "$tmp/fig16.xml" --to json >/dev/null 2>&1
[ $? -eq 2 ] || fail "xml input to json is a usage error"
"$insula" transform "$data/paper_fig13.cga" --to svg >/dev/null 2>&1
[ $? -eq 2 ] || fail "unknown --to is a usage error"
"$insula" transform "$root/README.md" --to json >/dev/null 2>&1
[ $? -eq 2 ] || fail "unknown input type is a usage error"

[ "$failures" -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
echo "all transform checks passed ($transformed grammars)"
