#!/bin/sh
# SIGINT and SIGTERM stop a run within a second at a safe point, say what is
# done and how to resume, and exit with 128 + the signal; a second
# msp_stereo on a workspace in use refuses, naming the first; a killed run's
# lock blocks nobody. Each interrupted workspace then runs to the end with
# maps identical to an uninterrupted run's.
# Usage: signal_lock_test.sh <bin_dir>
set -eu
. "$(dirname "$0")/common.sh"

reference "$TMP/ref"

for sig in INT TERM; do
  ws="$TMP/ws_$sig"
  cp -a "$TMP/ref.base" "$ws"
  stereo_bg "$ws"
  wait_for_line "$ws.log" "^Round 1/1, geometric pass 2"
  t0=$(now_ms)
  kill -s "$sig" "$pid"
  code=0
  wait "$pid" || code=$?
  stop_ms=$(($(now_ms) - t0))
  echo "SIG$sig: exit $code after $stop_ms ms"
  if [ "$sig" = INT ]; then expected=130; else expected=143; fi
  [ "$code" -eq "$expected" ] || { cat "$ws.err"; fail "SIG$sig: exit code $code, not $expected"; }
  [ "$stop_ms" -le 1000 ] || fail "SIG$sig: stopped after $stop_ms ms"
  grep -q "^Stopped by SIG$sig between two steps; nothing is half-written" "$ws.log" ||
    fail "SIG$sig: no stop message in $ws.log"
  grep -q "of 3 reference images have their final maps in .*run the same command again to resume" \
    "$ws.log" || fail "SIG$sig: no resume hint in $ws.log"
  check_partial "$ws" "$TMP/ref"
  [ -z "$(find "$ws/stereo" -name '*.tmp-*' -o -name 'state-*.bin')" ] ||
    fail "SIG$sig: temporary files left"
  stereo "$ws" || { cat "$ws.err"; fail "SIG$sig: the resumed run"; }
  check_complete "$ws" "$TMP/ref"
done

# A second run on a workspace in use refuses at once, naming the first.
ws="$TMP/ws_lock"
cp -a "$TMP/ref.base" "$ws"
stereo_bg "$ws"
first=$pid
wait_for_line "$ws.log" "^Round "
code=0
# shellcheck disable=SC2086
nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS \
  > "$TMP/second.log" 2> "$TMP/second.err" || code=$?
[ "$code" -ne 0 ] || fail "the second msp_stereo ran"
grep -q "^ERROR: the workspace is in use by another msp_stereo (pid $first on .*msp_stereo.lock" \
  "$TMP/second.err" || { cat "$TMP/second.err"; fail "the second run's message"; }
grep -q "^Round " "$TMP/second.log" && fail "the second run computed"
wait "$first" || { cat "$ws.err"; fail "the first run after the refused second"; }
check_complete "$ws" "$TMP/ref"

# A lock whose holder was killed blocks nobody.
rm -rf "$ws"
cp -a "$TMP/ref.base" "$ws"
stereo_bg "$ws"
wait_for_line "$ws.log" "^Round "
kill -9 "$pid"
wait "$pid" || true
grep -q "^pid $pid on " "$ws/stereo/msp_stereo.lock" || fail "the lock file does not name $pid"
stereo "$ws" || { cat "$ws.err"; fail "the run after a killed holder"; }
check_complete "$ws" "$TMP/ref"
echo "signal and lock test passed"
