#!/usr/bin/env bash
# The fuzz lane (docs/testing.md): builds the libFuzzer targets in the sanitizer lane's build
# (build-asan/: clang, ASan, UBSan, coverage; scripts/test_asan.sh configures it the same way) and
# runs each from its corpus (fuzz/corpus/<name> plus the examples and test catalogs) for
# FUZZ_SECONDS seconds (15 by default). New inputs go to build-asan/fuzz-corpus/<name>, never into
# the repository; a crash, a leak, a timeout or a contract violation leaves its input in
# build-asan/crashes/ and fails the run. `scripts/fuzz.sh lua obj` runs only those targets.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${FUZZ_SECONDS:-15}
# A fixed seed by default: CI's short runs take the same path each time (so a red run is a
# change of ours, reproducible here); FUZZ_SEED=0 lets libFuzzer pick one, for longer hunts.
seed=${FUZZ_SEED:-1}
all=(geojson cga bldg lua obj xml plasm graph)
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all[@]}")

source scripts/lib/asan.sh
build=$asan_build
configure_asan ${FUZZ_CMAKE_ARGS:-}
ninja -C $build "${targets[@]/%/_fuzz}"
export ASAN_OPTIONS="detect_leaks=1:strict_string_checks=1"

seeds() {  # the read-only seed folders of target $1
  case $1 in
    geojson) echo fuzz/corpus/geojson tests/data/bad ;;
    cga) echo fuzz/corpus/cga tests/data/cga ;;
    bldg) echo fuzz/corpus/bldg tests/data/bldg ;;
    lua) echo fuzz/corpus/lua examples/lua tests/data/lua ;;
    obj) echo fuzz/corpus/obj examples/lua/assets tests/data/assets ;;
    xml) echo fuzz/corpus/xml tests/data/cga/transform ;;
    plasm) echo examples/plasm tests/data/plasm ;;
    graph) echo examples/graph tests/data/graph ;;
  esac
}

mkdir -p $build/crashes
status=0
for t in "${targets[@]}"; do
  work=$build/fuzz-corpus/$t
  mkdir -p "$work"
  dict=()
  [ -f "fuzz/$t.dict" ] && dict=(-dict="fuzz/$t.dict")
  # shellcheck disable=SC2046
  if $build/fuzz/${t}_fuzz -max_total_time="$seconds" -timeout=20 -rss_limit_mb=3072 -seed="$seed" \
    -max_len=16384 -print_final_stats=1 -artifact_prefix="$build/crashes/$t-" "${dict[@]}" \
    "$work" $(seeds "$t") >"$build/$t.log" 2>&1; then
    echo "fuzz $t: $(grep -E '^stat::number_of_executed_units' "$build/$t.log" | awk '{print $2}') runs in ${seconds} s, $(grep -oE 'cov: [0-9]+' "$build/$t.log" | tail -1), clean"
  else
    echo "fuzz $t: FAILED ($build/$t.log, input in $build/crashes/)" >&2
    grep -E 'ERROR|_fuzz:|SUMMARY|Test unit written' "$build/$t.log" | head -20 >&2
    status=1
  fi
done
exit $status
