#!/bin/sh
# kill -9 at many moments spread over a run, each followed by a check of what
# is on disk (only whole maps, byte-identical to an uninterrupted run's, or
# temporary names no reader takes for output), then a run to the end: the
# maps equal the uninterrupted run's and nothing temporary is left.
# Usage: kill_test.sh <bin_dir> [num_kills]
set -eu
NUM_KILLS=${2:-24}
. "$(dirname "$0")/common.sh"

reference "$TMP/ref"
echo "uninterrupted run: $ref_ms ms"
cp -a "$TMP/ref.base" "$TMP/ws"
hits=0
i=1
while [ "$i" -le "$NUM_KILLS" ]; do
  # Spread over the first 95 % of a run (a resumed run redoes the images
  # whose final maps are missing, and their sources, so each run is about as
  # long as the first).
  delay_ms=$((ref_ms * 95 * i / (100 * NUM_KILLS)))
  stereo_bg "$TMP/ws"
  sleep "$(echo "$delay_ms" | awk '{printf "%.3f", $1 / 1000}')"
  if kill -9 "$pid" 2> /dev/null; then hits=$((hits + 1)); fi
  wait "$pid" || true
  check_partial "$TMP/ws" "$TMP/ref"
  echo "kill $i at $delay_ms ms: $(map_files "$TMP/ws" | grep -c '\.bin$' || true) whole map files"
  i=$((i + 1))
done
# A kill may come after a run ended (a busy machine ran it faster than the
# first): at least 20 must hit.
min_hits=$((NUM_KILLS * 5 / 6))
[ "$hits" -ge "$min_hits" ] || fail "only $hits of $NUM_KILLS kills hit a running msp_stereo"
stereo "$TMP/ws" || { cat "$TMP/ws.err"; fail "the run after the kills"; }
check_complete "$TMP/ws" "$TMP/ref"
echo "kill test passed: $hits kills, maps identical to the uninterrupted run"
