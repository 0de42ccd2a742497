#!/usr/bin/env bash
# The Lua bad-input catalog tests/data/lua/bad/*.lua through `insula build` (docs/testing.md):
# each program's exact first diagnostic (syntax, runtime errors, the sandbox, bad operation
# arguments, every limit, with small limits so that the limit programs stop in milliseconds),
# exit 1, nothing on stdout and no output file. `insula check` (compile only) agrees on the syntax
# errors. INSULA_UPDATE_GOLDEN=1 prints the table below for the current diagnostics.
source "$(dirname "$0")/lib/common.sh"
bad=$root/tests/data/lua/bad
limits=(--set limit_instructions=2000000 --set limit_memory_mb=16 --set limit_depth=60
  --set limit_components=1000)
expected=$(
  cat <<'E'
asset_without_folders	asset_without_folders.lua:1:13: error[LUA003]: in componentFromFile: asset 'no_such_asset' not found in the asset folders
binary	binary.lua:1:1: error[LUA001]: unexpected symbol near '<\255>'
bowtie_polygon	bowtie_polygon.lua:1:1: error[LUA003]: in component: polygon: footprint has zero area
component_limit	component_limit.lua:5:22: error[LUA104]: in component: component limit of 1000 reached
depth_limit	depth_limit.lua:1:1: error[LUA103]: call depth limit of 60 reached
double_equals	double_equals.lua:1:1: error[LUA001]: unexpected symbol near '='
error_call	error_call.lua:1:1: error[LUA002]: no lot given
instruction_limit	instruction_limit.lua:1:1: error[LUA101]: instruction limit of 2000000 reached
memory_limit	memory_limit.lua:2:1: error[LUA102]: memory limit of 16 MB reached
misspelled_binding	misspelled_binding.lua:4:3: error[LUA002]: attempt to call a nil value (global 'splt')
negative_size	negative_size.lua:1:1: error[LUA003]: in component: argument 2: sizes must be >= 0
pcall_limit	pcall_limit.lua:2:1: error[LUA101]: instruction limit of 2000000 reached
query_syntax	query_syntax.lua:2:10: error[LUA003]: in query: expected a label or '(', found end of query (column 10 of "floor and")
sandbox_bytecode	sandbox_bytecode.lua:2:1: error[LUA002]: load: binary chunks are not allowed (mode 't' only)
sandbox_dofile	sandbox_dofile.lua:1:1: error[LUA002]: attempt to call a nil value (global 'dofile')
sandbox_io	sandbox_io.lua:2:1: error[LUA002]: attempt to index a nil value (global 'io')
sandbox_os	sandbox_os.lua:1:1: error[LUA002]: attempt to index a nil value (global 'os')
sandbox_require	sandbox_require.lua:1:1: error[LUA002]: attempt to call a nil value (global 'require')
sandbox_string_dump	sandbox_string_dump.lua:1:1: error[LUA002]: attempt to call a nil value (field 'dump')
size_two_numbers	size_two_numbers.lua:1:1: error[LUA003]: in component: argument 2: expected {x, y, z}: entry z is not a finite number
split_bad_axis	split_bad_axis.lua:3:3: error[LUA003]: in split: argument 2: expected an axis (x, y or z), got 'W'
split_piece_without_size	split_piece_without_size.lua:3:3: error[LUA003]: in split: argument 4: a piece needs exactly one of abs, rel or frac
split_string_not_component	split_string_not_component.lua:1:1: error[LUA003]: in split: argument 1: expected a component or a list of components, got string
unclosed_function	unclosed_function.lua:4:1: error[LUA001]: 'end' expected (to close 'function' at line 2) near <eof>
E
)

cd "$bad" || exit 1
listed=0
for program in *.lua; do
  stem=${program%.lua}
  rm -f "$tmp/out.glb"
  timeout 60 "$insula" build "$program" -o "$tmp/out.glb" -q "${limits[@]}" >"$tmp/out" 2>"$tmp/err"
  code=$?
  got=$(head -1 "$tmp/err")
  if [ -n "${INSULA_UPDATE_GOLDEN:-}" ]; then
    printf '%s\t%s\n' "$stem" "$got"
    continue
  fi
  want=$(printf '%s\n' "$expected" | awk -F'\t' -v s="$stem" '$1 == s { print $2 }')
  [ -n "$want" ] || { fail "$stem: add its expected diagnostic"; continue; }
  listed=$((listed + 1))
  [ "$code" -eq 1 ] || fail "$stem: exit $code, expected 1"
  [ "$got" = "$want" ] || fail "$stem: got '$got', expected '$want'"
  [ -s "$tmp/out" ] && fail "$stem: printed on stdout"
  [ -e "$tmp/out.glb" ] && fail "$stem: wrote an output file"
done
[ "$listed" -eq "$(printf '%s\n' "$expected" | wc -l)" ] || fail "a listed program is missing"

for stem in unclosed_function double_equals binary; do
  "$insula" check "$stem.lua" >/dev/null 2>"$tmp/err"
  code=$?
  want=$(printf '%s\n' "$expected" | awk -F'\t' -v s="$stem" '$1 == s { print $2 }')
  [ "$code" -eq 1 ] && [ "$(head -1 "$tmp/err")" = "$want" ] ||
    fail "check $stem: exit $code, $(head -1 "$tmp/err")"
done

finish lua_bad
