#!/usr/bin/env bash
# The sanitizer lane (docs/testing.md): builds into build-asan/ with AddressSanitizer and
# UndefinedBehaviorSanitizer at -O1 (CGAL's translation units dominate the build; -O0 would make
# the suite several times slower, -O2 the build) and runs the whole suite under them. Any report
# fails the run; tools/sanitizers/*.supp name the few reports that are CGAL's own, each with why.
set -euo pipefail
cd "$(dirname "$0")/.."
supp="$PWD/tools/sanitizers"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g -DNDEBUG" -DINSULA_SANITIZE=ON -DINSULA_BENCH=OFF \
  "$@" >/dev/null
ninja -C build-asan
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
export LSAN_OPTIONS="suppressions=$supp/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:suppressions=$supp/ubsan.supp"
ctest --test-dir build-asan --output-on-failure -j2
