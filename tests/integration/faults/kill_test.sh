#!/bin/sh
# kill -9 at many moments spread over a run, each followed by a check of what
# is on disk (only whole maps, byte-identical to an uninterrupted run's, or
# temporary names no reader takes for output), then a run to the end: the
# maps equal the uninterrupted run's and nothing temporary is left.
# Usage: kill_test.sh <bin_dir> [num_kills]
set -eu
NUM_KILLS=${2:-20}
. "$(dirname "$0")/common.sh"

reference "$TMP/ref"
echo "uninterrupted run: $ref_ms ms"
num_maps=$(map_files "$TMP/ref" | grep -c '\.bin$')
run_ms=$ref_ms
cp -a "$TMP/ref.base" "$TMP/ws"
hits=0
attempts=0
while [ "$hits" -lt "$NUM_KILLS" ]; do
  attempts=$((attempts + 1))
  [ "$attempts" -le $((2 * NUM_KILLS)) ] || fail "only $hits of $attempts kills hit a running msp_stereo"
  # A workspace a run finished has nothing left to kill: start it again.
  if [ "$(map_files "$TMP/ws" | grep -c '\.bin$' || true)" -eq "$num_maps" ]; then
    rm -rf "$TMP/ws"
    cp -a "$TMP/ref.base" "$TMP/ws"
  fi
  # The kills spread over the first 95 % of a run (a resumed run redoes the
  # images whose final maps are missing, and their sources, so each run is
  # about as long as the first).
  delay_ms=$((run_ms * 95 * (hits + 1) / (100 * NUM_KILLS)))
  t0=$(now_ms)
  stereo_bg "$TMP/ws"
  sleep "$(echo "$delay_ms" | awk '{printf "%.3f", $1 / 1000}')"
  kill -9 "$pid" 2> /dev/null || true
  code=0
  wait "$pid" || code=$?
  if [ "$code" -eq 137 ]; then
    hits=$((hits + 1))
  elif [ "$code" -eq 0 ]; then
    # The run ended first (the machine got less busy): time the runs anew.
    run_ms=$(($(now_ms) - t0))
  else
    cat "$TMP/ws.err"
    fail "a run between the kills exited with $code"
  fi
  check_partial "$TMP/ws" "$TMP/ref"
  echo "kill at $delay_ms ms: $(map_files "$TMP/ws" | grep -c '\.bin$' || true) whole map files"
done
stereo "$TMP/ws" || { cat "$TMP/ws.err"; fail "the run after the kills"; }
check_complete "$TMP/ws" "$TMP/ref"
echo "kill test passed: $hits kills in $attempts runs, maps identical to the uninterrupted run"
