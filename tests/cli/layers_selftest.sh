#!/usr/bin/env bash
# tests/cli/layers.sh fails on a front-end including another front-end, on an include pointing up
# and on a kernel opening a file, and passes a tree without them: run on small trees built here.
set -u
root=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*"; exit 1; }

make_tree() {  # a minimal tree whose front-ends include only shape/
  rm -rf "$work/src"
  mkdir -p "$work/src/base" "$work/src/kernel" "$work/src/shape" "$work/src/io" \
    "$work/src/lang/cga" "$work/src/lang/lua" "$work/src/lang/plasm" "$work/src/apps/cli"
  echo '#include "shape/shape.h"' > "$work/src/lang/cga/a.cc"
  echo '#include "shape/shape.h"' > "$work/src/lang/lua/b.cc"
  echo '#include "lang/lua/b.h"' > "$work/src/apps/cli/main.cc"
}

make_tree
out=$(bash "$root/tests/cli/layers.sh" unused "$work") || fail "clean tree rejected: $out"

make_tree
echo '#include "lang/cga/ast.h"' >> "$work/src/lang/lua/b.cc"
out=$(bash "$root/tests/cli/layers.sh" unused "$work") && fail "lua including cga passed"
echo "$out" | grep -q "layer 'lang/lua' must not include 'lang/cga/'" || fail "message: $out"
echo "$out" | grep -q "src/lang/lua/b.cc:2:" || fail "no file:line in: $out"

make_tree
echo '#include "lang/lua/b.h"' > "$work/src/lang/plasm/p.h"
out=$(bash "$root/tests/cli/layers.sh" unused "$work") && fail "plasm including lua passed"
echo "$out" | grep -q "layer 'lang/plasm' must not include 'lang/lua/'" || fail "message: $out"

make_tree
echo '#include "io/output.h"' > "$work/src/shape/s.cc"
out=$(bash "$root/tests/cli/layers.sh" unused "$work") && fail "shape including io passed"
echo "$out" | grep -q "layer 'shape' must not include 'io/'" || fail "message: $out"

make_tree
echo 'FILE* f = fopen("k.txt", "w");' > "$work/src/kernel/k.cc"
out=$(bash "$root/tests/cli/layers.sh" unused "$work") && fail "kernel opening a file passed"
echo "$out" | grep -q "kernel must not do file I/O" || fail "message: $out"

make_tree
echo 'FILE* f = fopencookie(nullptr, "w", discard);' > "$work/src/kernel/k.cc"
out=$(bash "$root/tests/cli/layers.sh" unused "$work") || fail "kernel with an in-memory stream rejected: $out"

# The real tree passes.
bash "$root/tests/cli/layers.sh" unused "$root" > /dev/null || fail "the source tree fails layers.sh"
echo ok
