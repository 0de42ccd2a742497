#!/usr/bin/env bash
# The fuzz lane (docs/testing.md): builds every libFuzzer target with clang into build-fuzz/ and
# runs each from its corpus (fuzz/corpus/<name> plus the examples and test catalogs) for FUZZ_SECONDS seconds
# (60 by default). New inputs go to build-fuzz/corpus/<name>, never into the repository; a crash,
# a leak, a timeout or a contract violation leaves its input in build-fuzz/crashes/ and fails the
# run. `scripts/fuzz.sh lua obj` runs only those targets.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-60}
all=(geojson cga bldg lua obj xml)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")

# -O1: the instrumented layers include CGAL's translation units, and the fuzzers gain little
# from -O2 while the build would take longer (docs/testing.md, "Lanes").
CC=clang CXX=clang++ cmake -S . -B build-fuzz -G Ninja -DINSULA_FUZZ=ON -DINSULA_TESTS=OFF \
  -DINSULA_BENCH=OFF -DINSULA_TCMALLOC=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only -DNDEBUG" ${FUZZ_CMAKE_ARGS:-} >/dev/null
ninja -C build-fuzz "${targets[@]/%/_fuzz}"

seeds() {  # the read-only seed folders of target $1
  case $1 in
    geojson) echo fuzz/corpus/geojson tests/data/bad ;;
    cga) echo fuzz/corpus/cga tests/data/cga ;;
    bldg) echo fuzz/corpus/bldg tests/data/bldg ;;
    lua) echo fuzz/corpus/lua examples/lua tests/data/lua ;;
    obj) echo fuzz/corpus/obj examples/lua/assets tests/data/assets ;;
    xml) echo fuzz/corpus/xml tests/data/cga/transform ;;
  esac
}

mkdir -p build-fuzz/crashes
status=0
for t in "${targets[@]}"; do
  work=build-fuzz/corpus/$t
  mkdir -p "$work"
  dict=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
  # shellcheck disable=SC2046
  if build-fuzz/fuzz/${t}_fuzz -max_total_time="$seconds" -timeout=20 -rss_limit_mb=3072 \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="build-fuzz/crashes/$t-" "${dict[@]}" \
    "$work" $(seeds "$t") >"build-fuzz/$t.log" 2>&1; then
    echo "fuzz $t: $(grep -E '^stat::number_of_executed_units' "build-fuzz/$t.log" | awk '{print $2}') runs in ${seconds} s, $(grep -oE 'cov: [0-9]+' "build-fuzz/$t.log" | tail -1), clean"
  else
    echo "fuzz $t: FAILED (build-fuzz/$t.log, input in build-fuzz/crashes/)" >&2
    grep -E 'ERROR|_fuzz:|SUMMARY|Test unit written' "build-fuzz/$t.log" | head -20 >&2
    status=1
  fi
done
exit $status
