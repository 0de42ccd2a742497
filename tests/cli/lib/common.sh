# Prologue of the end-to-end CLI tests, sourced by tests/cli/<name>.sh (it lives in a subfolder
# so ctest, which registers tests/cli/*.sh, does not run it by itself):
#   source "$(dirname "$0")/lib/common.sh"   # with the script's arguments: <insula> <repo-root>
# It sets insula, root and tmp (a temporary folder removed on exit), counts failures, and wraps
# the third-party validators; a script ends with `finish <name>`.
set -u
insula=$1
root=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
failures=0

fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

expect_exit() {  # code, description, command...: stdout and stderr go to $tmp/out.txt, err.txt
  local want=$1 what=$2
  shift 2
  "$@" >"$tmp/out.txt" 2>"$tmp/err.txt"
  local got=$?
  [ "$got" -eq "$want" ] || { fail "$what: exit $got, expected $want"; cat "$tmp/err.txt"; }
}

# Third-party validators: description, files. A failure counts and shows the validator's output.
validate_gltf() {
  local what=$1
  shift
  node "$root/tools/validate_gltf.mjs" "$@" >"$tmp/v.txt" 2>&1 || { fail "$what"; cat "$tmp/v.txt"; }
}
validate_cityjson() {
  local what=$1
  shift
  node "$root/tools/validate_cityjson.mjs" "$@" >"$tmp/v.txt" 2>&1 || { fail "$what"; cat "$tmp/v.txt"; }
}
assimp_info() {  # description, one OBJ or glTF file
  assimp info "$2" >"$tmp/v.txt" 2>&1 || { fail "$1"; tail -5 "$tmp/v.txt"; }
}

finish() {  # name: the summary line and the exit status (1 when anything failed)
  if [ "$failures" -gt 0 ]; then
    echo "$1: $failures failure(s)"
    exit 1
  fi
  echo "$1: all passed"
  exit 0
}
