#!/usr/bin/env bash
# Set-up, build and the whole test suite: unit tests, goldens, validators, layering and formatting.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/setup.sh
./scripts/build.sh
ctest --test-dir build --output-on-failure -j2
