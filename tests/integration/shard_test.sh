#!/bin/sh
# Sharded runs on the real msp_stereo and a small generated workspace: three
# processes of --MspStereo.shard K/3 at the same time write maps byte-identical
# to one process's with the same seed and leave no shared state behind; while
# they run, a second process of a shard and an unsharded run are refused; a
# shard killed with -9 and started again resumes after its last saved pass,
# and the maps are still identical; two image lists make a run as well; a
# shard alone stops after --MspStereo.shard_timeout naming the missing images.
# Usage: shard_test.sh <bin_dir>
set -eu
. "$(dirname "$0")/faults/common.sh"

# The scene of the issue (6 views, two coarse-to-fine rounds, 8 passes).
SCENE_OPTIONS="--width 128 --height 96 --num_cameras 6 --seed 5"
STEREO_OPTIONS="--PatchMatchStereo.num_threads 1 --random_seed 7"

reference "$TMP/ref"
echo "one process: $ref_ms ms"

# shard_bg WS K N: shard K/N of WS in the background, log in WS.K.log,
# errors in WS.K.err; its pid in $pid.
shard_bg() {
  # shellcheck disable=SC2086
  nice -n 15 "$BIN/msp_stereo" --workspace_path "$1" $STEREO_OPTIONS --MspStereo.shard "$2/$3" \
    > "$1.$2.log" 2> "$1.$2.err" &
  pid=$!
}

# shards WS N: shards 0..N-1 of WS in the background; their pids in $pids.
shards() {
  pids=""
  k=0
  while [ "$k" -lt "$2" ]; do
    shard_bg "$1" "$k" "$2"
    pids="$pids $pid"
    k=$((k + 1))
  done
}

wait_all() {
  for p in $pids; do wait "$p" || { cat "$1".*.err; fail "a shard of $1 failed"; }; done
}

# Three shards at once, a refused duplicate and a refused unsharded run.
ws="$TMP/three"
cp -a "$TMP/ref.base" "$ws"
t0=$(now_ms)
shards "$ws" 3
wait_for_line "$ws.1.log" "^Round 1/2, photometric pass 1"
code=0
# shellcheck disable=SC2086
nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS --MspStereo.shard 1/3 \
  > "$TMP/dup.log" 2> "$TMP/dup.err" || code=$?
[ "$code" -eq 1 ] || fail "a second process of shard 1/3 ran (exit $code)"
grep -q "^ERROR: the workspace is in use by another msp_stereo (pid .*msp_stereo.shard-1-of-3.lock" \
  "$TMP/dup.err" || { cat "$TMP/dup.err"; fail "the second shard 1/3's message"; }
code=0
# shellcheck disable=SC2086
nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS \
  > "$TMP/all.log" 2> "$TMP/all.err" || code=$?
[ "$code" -eq 1 ] || fail "an unsharded run ran beside the shards (exit $code)"
grep -q "in use by another msp_stereo (pid .*stereo/msp_stereo.lock" "$TMP/all.err" ||
  { cat "$TMP/all.err"; fail "the unsharded run's message"; }
wait_all "$ws"
echo "three shards at once: $(($(now_ms) - t0)) ms"
check_complete "$ws" "$TMP/ref"
[ ! -e "$ws/stereo/msp_shared" ] || fail "the shared pass states were left in $ws/stereo/msp_shared"
grep -q "^  img_001.png .*%" "$ws.1.log" || fail "shard 1/3 does not report its image img_001.png"
grep -q "^  img_000.png" "$ws.1.log" && fail "shard 1/3 reports another shard's image"

# kill -9 of a shard in a geometric pass, then the same command again: it
# resumes after its last saved pass while the others wait at the barrier.
ws="$TMP/killed"
cp -a "$TMP/ref.base" "$ws"
shards "$ws" 3
killed=$(echo "$pids" | cut -d' ' -f3)
wait_for_line "$ws.1.log" "^Round 1/2, geometric pass 3"
kill -9 "$killed"
wait "$killed" 2> /dev/null || true
pids=$(echo "$pids" | cut -d' ' -f2,4)
grep -q "^Round 2/2" "$ws.1.log" && fail "shard 1/3 was killed too late to test a resume"
shard_bg "$ws" 1 3
pids="$pids $pid"
wait_all "$ws"
grep -q "^shard 1/3: resuming after round 1/2, geometric pass" "$ws.1.log" ||
  fail "shard 1/3 did not resume after a saved pass: $(grep '^shard' "$ws.1.log")"
check_complete "$ws" "$TMP/ref"

# Two image lists that cover the images, at once.
ws="$TMP/lists"
cp -a "$TMP/ref.base" "$ws"
printf '# first half\nimg_000.png\nimg_001.png\nimg_002.png\n' > "$TMP/first.txt"
printf 'img_003.png\n\nimg_004.png\nimg_005.png\n' > "$TMP/second.txt"
stereo_bg "$ws" --MspStereo.image_list "$TMP/first.txt"
first=$pid
wait_for_line "$ws.log" "^image list "
mv "$ws.log" "$ws.first.log"
mv "$ws.err" "$ws.first.err"
stereo "$ws" --MspStereo.image_list "$TMP/second.txt" || { cat "$ws.err"; fail "the second list"; }
wait "$first" || { cat "$ws.first.err"; fail "the first list"; }
check_complete "$ws" "$TMP/ref"

# A shard whose partner never comes stops at the timeout, naming the images.
ws="$TMP/alone"
cp -a "$TMP/ref.base" "$ws"
code=0
stereo "$ws" --MspStereo.shard 0/2 --MspStereo.shard_timeout 1 || code=$?
[ "$code" -eq 1 ] || fail "a shard alone exited with $code"
grep -q "^ERROR: shard 0/2: waited 1 s (--MspStereo.shard_timeout) for 3 image(s) to finish round 1/2, photometric pass 1 in .*: img_001.png (shard 1/2), img_003.png (shard 1/2), img_005.png (shard 1/2)" \
  "$ws.err" || { cat "$ws.err"; fail "the timeout's message"; }
echo "PASS"
