#!/usr/bin/env bash
# SIGINT and SIGTERM during `insula mass`, `build --lot` and `random` (issue 12, item 1): the
# output transaction is rolled back, so the user's earlier files are back with their content, no
# `*.insula-backup` and no `*.tmp-NNNN` is left, and the exit code is 130 / 143. The signals are
# real (kill) and sent mid-run: after the first progress line (INSULA_PROGRESS_SECONDS=0 prints
# every update), and, for the writing stage and its renames, at a spread of delays where either
# outcome is allowed but nothing in between.
source "$(dirname "$0")/lib/common.sh"
set -m  # background jobs keep SIGINT (a shell without job control ignores it in them)
export INSULA_PROGRESS_SECONDS=0

# 20,000 L-shaped footprints (concave: the straight-skeleton path, a few seconds of work); 5,000
# in the sanitizer lane, where each takes about four times as long.
count=$([ -n "${INSULA_SANITIZED:-}" ] && echo 5000 || echo 20000)
awk -v count="$count" 'BEGIN {
  printf "{\"type\": \"FeatureCollection\", \"features\": ["
  for (i = 0; i < count; i++) {
    x = (i % 150) * 30; y = int(i / 150) * 30
    printf "%s{\"type\": \"Feature\", \"id\": \"f%d\", \"properties\": {\"height\": 9}, ", (i ? "," : ""), i
    printf "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d]]]}}",
      x, y, x + 20, y, x + 20, y + 8, x + 9, y + 8, x + 9, y + 17, x, y + 17, x, y
  }
  print "]}"
}' >"$tmp/city.geojson"

old_files() {  # dir: the user's earlier outputs, with known content
  mkdir -p "$1"
  for f in out.glb out.obj out.mtl out.origin.json out.city.json report.json; do echo "old $f" >"$1/$f"; done
}
kept_old() {  # dir: every earlier file back with its content, nothing else in the folder
  local f
  for f in out.glb out.obj out.mtl out.origin.json out.city.json report.json; do
    [ "$(cat "$1/$f" 2>/dev/null)" = "old $f" ] || { echo "$f not restored"; return 1; }
  done
  [ "$(ls -A "$1" | wc -l)" -eq 6 ] || { echo "extra files:"; ls -A "$1"; return 1; }
}
all_new() {  # dir: every output replaced, no backup or temporary
  local f
  for f in out.glb out.obj out.mtl out.origin.json out.city.json report.json; do
    [ -s "$1/$f" ] && ! echo "old $f" | cmp -s - "$1/$f" || { echo "$f not new"; return 1; }
  done
  [ "$(ls -A "$1" | wc -l)" -eq 6 ] || { echo "extra files:"; ls -A "$1"; return 1; }
}
mass_in() {  # dir: the mass run in the background, stderr to dir.err
  "$insula" mass "$tmp/city.geojson" --roof gable -o "$1/out.glb" -o "$1/out.obj" \
    -o "$1/out.city.json" --report "$1/report.json" >/dev/null 2>"$1.err" &
  pid=$!
}

# The signal is sent by the reader of the run's stderr as soon as the progress line arrives, not
# by polling a file: a 20,000-footprint run builds in about 0.5 s, and a 0.1 s poll of a loaded CI
# machine once saw the line only after the run had finished (exit 0, new files).
signal_mid_run() {  # what, signal, expected exit, err file, progress pattern, command...
  local what=$1 signal=$2 want=$3 err=$4 pattern=$5 line sent=
  shift 5
  rm -f "$tmp/stderr.fifo"
  mkfifo "$tmp/stderr.fifo"
  : >"$err"
  "$@" >/dev/null 2>"$tmp/stderr.fifo" &
  pid=$!
  while IFS= read -r line; do
    printf '%s\n' "$line" >>"$err"
    if [ -z "$sent" ] && [[ $line == *"$pattern"* ]]; then
      kill -"$signal" $pid
      sent=yes
    fi
  done <"$tmp/stderr.fifo"
  wait $pid
  code=$?
  [ -n "$sent" ] || fail "$what: no progress line"
  [ $code -eq "$want" ] || { fail "$what SIG$signal: exit $code, expected $want"; cat "$err"; }
}
# Mid-build: after the first progress line.
for signal in INT TERM; do
  want=$([ $signal = INT ] && echo 130 || echo 143)
  dir=$tmp/mass-$signal
  old_files "$dir"
  signal_mid_run mass $signal "$want" "$dir.err" "of $count buildings" "$insula" mass \
    "$tmp/city.geojson" --roof gable -o "$dir/out.glb" -o "$dir/out.obj" -o "$dir/out.city.json" \
    --report "$dir/report.json"
  kept_old "$dir" || fail "mass SIG$signal: earlier files not kept"
  grep -q "interrupted (SIG$signal); nothing written, earlier files kept" "$dir.err" ||
    fail "mass SIG$signal: no interruption line"
done

# Any moment, writing and renaming included: 130 with all the old files, or 0 with all new ones.
# Two signals in a row must not break the rollback either.
full=$(date +%s%N)
dir=$tmp/mass-full
old_files "$dir"
mass_in "$dir"
wait $pid || fail "uninterrupted mass run"
all_new "$dir" || fail "uninterrupted mass run: outputs"
full_ms=$((($(date +%s%N) - full) / 1000000))
interrupted_runs=0
for percent in 10 30 60 80 90 95 98; do
  dir=$tmp/mass-at-$percent
  old_files "$dir"
  mass_in "$dir"
  sleep "$(awk -v ms=$full_ms -v p=$percent 'BEGIN { printf "%.3f", ms * p / 100000 }')"
  kill -INT $pid 2>/dev/null
  kill -INT $pid 2>/dev/null
  wait $pid
  code=$?
  echo "signalled at $percent% of $full_ms ms: exit $code"
  if [ $code -eq 130 ]; then
    interrupted_runs=$((interrupted_runs + 1))
    kept_old "$dir" || fail "mass interrupted at $percent%: earlier files not kept"
  elif [ $code -eq 0 ]; then
    all_new "$dir" || fail "mass finished at $percent%: outputs not all new"
  else
    fail "mass signalled at $percent%: exit $code"
    cat "$dir.err"
  fi
done
[ $interrupted_runs -gt 0 ] || fail "no run at a spread of delays was interrupted"

# The end of a run (commit, the return from main, freeing the scene) under a stream of signals: a
# signal there once killed the process after the commit (new files, exit 130 from the kill; seen
# once in CI under load). The window was too short for this loop to hit it here in 20 runs with
# the old code, so it checks the invariant (all old or all new) rather than reproducing that bug;
# the fix is structural (interrupt.h: the handlers are never uninstalled). A small city,
# signalled without pause from a random start until the process is gone (a signal before main
# installs the handlers kills it, which is fine: nothing was written yet).
head -c 20000 "$tmp/city.geojson" | sed 's/,{"type": "Feature"[^]]*$//' >"$tmp/small.geojson"
echo ']}' >>"$tmp/small.geojson"
for run in $(seq 20); do
  dir=$tmp/mass-end-$run
  old_files "$dir"
  "$insula" mass "$tmp/small.geojson" --roof gable -o "$dir/out.glb" -o "$dir/out.obj" \
    -o "$dir/out.city.json" --report "$dir/report.json" >/dev/null 2>"$dir.err" &
  pid=$!
  sleep "0.0$((RANDOM % 10))"
  while kill -INT $pid 2>/dev/null; do :; done
  wait $pid
  code=$?
  if [ $code -eq 130 ]; then
    kept_old "$dir" || fail "signals at the end, run $run: exit 130 and earlier files not kept"
  elif [ $code -eq 0 ]; then
    all_new "$dir" || fail "signals at the end, run $run: exit 0, outputs not all new"
  else
    fail "signals at the end, run $run: exit $code"
  fi
done

# build --lot (the .bldg village path, a building per lot) and random, after the first progress line.
awk 'BEGIN {
  printf "{\"type\": \"FeatureCollection\", \"features\": ["
  for (i = 0; i < 400; i++) {
    x = (i % 20) * 20; y = int(i / 20) * 16
    printf "%s{\"type\": \"Feature\", \"id\": \"lot%d\", \"properties\": {}, ", (i ? "," : ""), i
    printf "\"geometry\": {\"type\": \"Polygon\", \"coordinates\": [[[%d,%d],[%d,%d],[%d,%d],[%d,%d],[%d,%d]]]}}",
      x, y, x + 14, y, x + 14, y + 10, x, y + 10, x, y
  }
  print "]}"
}' >"$tmp/lots.geojson"
dir=$tmp/build
old_files "$dir"
signal_mid_run "build --lot" TERM 143 "$dir.err" "of 400 buildings" \
  "$insula" build "$root/examples/bldg/village/village.bldg" --lot "$tmp/lots.geojson" \
  -o "$dir/out.glb" -o "$dir/out.obj" -o "$dir/out.city.json" --report "$dir/report.json"
kept_old "$dir" || fail "build --lot SIGTERM: earlier files not kept"

dir=$tmp/random
mkdir -p "$dir"
echo "old grammar" >"$dir/building_000.bldg"
echo "old report" >"$dir/building_000.json"
signal_mid_run "random" INT 130 "$dir.err" "of 400 buildings" \
  "$insula" random --count 400 --seed 3 --shape L -o "$dir" --report "$tmp/random.json"
[ "$(cat "$dir/building_000.bldg")" = "old grammar" ] && [ "$(cat "$dir/building_000.json")" = "old report" ] ||
  fail "random SIGINT: earlier files not restored"
[ "$(ls -A "$dir" | wc -l)" -eq 2 ] || { fail "random SIGINT: files left"; ls -A "$dir" | head; }
[ -e "$tmp/random.json" ] && fail "random SIGINT: report written"

finish interrupt
