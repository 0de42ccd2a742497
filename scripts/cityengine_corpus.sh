#!/usr/bin/env bash
# Runs Insula over a folder of CityEngine rule files (docs/cga-cityengine.md, "Corpus"):
# `insula check` on every .cga, and `insula build` on a 20 x 15 m lot for those that pass and
# have a rule to start from, the GLB checked by the Khronos validator. Prints one line per file
# (PASS/FAIL, the first error) to FILE.tsv next to the counts, files of equal content once.
#   scripts/cityengine_corpus.sh DIR [OUT.tsv]
set -u
dir=${1:?usage: cityengine_corpus.sh DIR [OUT.tsv]}
out=${2:-cityengine_corpus.tsv}
root=$(cd "$(dirname "$0")/.." && pwd)
insula=${INSULA:-$root/build/src/apps/cli/insula}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/lot.geojson" <<'JSON'
{"type": "FeatureCollection", "features": [{"type": "Feature", "properties": {},
 "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [20, 0], [20, 15], [0, 15], [0, 0]]]}}]}
JSON
: >"$out"
declare -A seen
files=0 distinct=0 checked=0 startable=0 built=0
while IFS= read -r -d '' f; do
  files=$((files + 1))
  sum=$(sha1sum <"$f" | cut -c1-16)
  [ -n "${seen[$sum]:-}" ] && continue
  seen[$sum]=1
  distinct=$((distinct + 1))
  if ! timeout 60 "$insula" check "$f" >"$tmp/out" 2>"$tmp/err"; then
    printf 'CHECK-FAIL\t%s\t%s\n' "$f" "$(grep -m1 'error' "$tmp/err")" >>"$out"
    continue
  fi
  checked=$((checked + 1))
  if grep -q "start ''" "$tmp/out"; then
    printf 'LIBRARY\t%s\n' "$f" >>"$out"
    continue
  fi
  startable=$((startable + 1))
  rm -f "$tmp/m.glb"
  if timeout 120 "$insula" build "$f" --lot "$tmp/lot.geojson" -o "$tmp/m.glb" -q \
    >/dev/null 2>"$tmp/err" && [ -s "$tmp/m.glb" ] &&
    node "$root/tools/validate_gltf.mjs" "$tmp/m.glb" >/dev/null 2>&1; then
    built=$((built + 1))
    printf 'BUILT\t%s\n' "$f" >>"$out"
  else
    printf 'BUILD-FAIL\t%s\t%s\n' "$f" "$(grep -m1 'error' "$tmp/err")" >>"$out"
  fi
done < <(find "$dir" -name '*.cga' -print0 | sort -z)
echo "files $files, distinct $distinct: check passes $checked, with a start rule $startable, built a valid GLB $built"
