#!/usr/bin/env bash
# Set-up, build and the whole test suite: unit tests, goldens, validators, layering and formatting;
# then the same suite under AddressSanitizer and UBSan (clang), and every fuzz target for a bounded
# time from the same sanitized build (docs/testing.md: the lanes and how long each takes).
# INSULA_LANES="release asan" (any subset of the three) runs only those.
set -euo pipefail
cd "$(dirname "$0")/.."
lane() {  # name, command...: runs a lane and prints its wall time
  local start=$SECONDS name=$1
  shift
  "$@"
  echo "lane $name: $((SECONDS - start)) s" >&2
}
lanes=${INSULA_LANES:-release asan fuzz}
./scripts/setup.sh
release() { ./scripts/build.sh && ctest --test-dir build --output-on-failure -j2; }
if [[ " $lanes " == *" release "* ]]; then lane release release; fi
if [[ " $lanes " == *" asan "* ]]; then lane asan ./scripts/test_asan.sh; fi
if [[ " $lanes " == *" fuzz "* ]]; then lane fuzz ./scripts/fuzz.sh; fi
