#!/usr/bin/env bash
# Dependencies point down only (docs/layers.md): base <- kernel <- shape <- io, lang <- apps.
# Fails when a file includes a header of a layer above its own, or when a front-end (a folder of
# src/lang) includes another front-end.
set -u
root=$2
status=0
check() {  # layer, forbidden include prefixes...
  local layer=$1
  shift
  for forbidden in "$@"; do
    hits=$(grep -rnE "#include \"${forbidden}/" "$root/src/$layer" 2>/dev/null)
    if [ -n "$hits" ]; then
      echo "layer '$layer' must not include '$forbidden/':"
      echo "$hits"
      status=1
    fi
  done
}
check base kernel shape io lang apps
check kernel shape io lang apps
check shape io lang apps
check io lang apps
check lang io apps
for front_end in "$root"/src/lang/*/; do
  name=$(basename "$front_end")
  for other in "$root"/src/lang/*/; do
    [ "$other" = "$front_end" ] || check "lang/$name" "lang/$(basename "$other")"
  done
done
# CGAL stays in at most two translation units, never in a header.
cgal=$(grep -rlE '#include <CGAL/' "$root/src" | sort)
count=$(echo "$cgal" | grep -c . || true)
if [ "$count" -gt 2 ] || echo "$cgal" | grep -qE '\.h$'; then
  echo "CGAL must stay in at most two .cc files, found:"
  echo "$cgal"
  status=1
fi
# kernel does no file I/O (fopencookie, a FILE* over callbacks that Qhull writes to, is none).
if grep -rnE '#include <fstream>|fopen\(|std::(i|o)?fstream|std::filesystem' "$root/src/kernel"; then
  echo "kernel must not do file I/O"
  status=1
fi
exit $status
