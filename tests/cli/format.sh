#!/usr/bin/env bash
# Every C++ source follows .clang-format.
set -u
root=$2
cd "$root" || exit 1
command -v clang-format >/dev/null || { echo "clang-format not installed"; exit 1; }
bad=$(git ls-files --cached --others --exclude-standard -- '*.h' '*.cc' | while read -r f; do
  [ -f "$f" ] && ! clang-format --dry-run -Werror "$f" >/dev/null 2>&1 && echo "$f"
done)
if [ -n "$bad" ]; then
  echo "not formatted (run clang-format -i):"
  echo "$bad"
  exit 1
fi
