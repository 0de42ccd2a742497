#!/usr/bin/env bash
# The sanitizer lane (docs/testing.md): the whole suite built with clang, ASan and UBSan
# (scripts/lib/asan.sh) into build-asan/, which also holds the fuzz lane's targets.
set -euo pipefail
cd "$(dirname "$0")/.."
source scripts/lib/asan.sh
configure_asan "$@"
ninja -C $asan_build
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1"
ctest --test-dir $asan_build --output-on-failure -j2
