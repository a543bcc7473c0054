# shellcheck shell=sh
# Shared by tests/integration/memory/memory_bound_test.sh and bench/memory_bound.sh:
# generated workspaces of N images, the peak memory of msp_stereo on them
# with a low --PatchMatchStereo.cache_size, and the bound README's "Memory"
# section states for it. Needs BIN (the build's bin/) and /usr/bin/time.

# Small images, so that 100 of them run in CI time; each problem matches
# MEMORY_SOURCES sources (the bound's S) in one coarse-to-fine round of the
# conventional core (the four passes of geom_consistency).
MEMORY_WIDTH=64
MEMORY_HEIGHT=64
MEMORY_SOURCES=2
# Every point is seen by about every image, so the sparse model grows with
# the images; few points keep it small beside what the test measures.
MEMORY_POINTS=500
# 4 MiB unless set: states of a few images, images of a few, a round's
# layers of a few.
MEMORY_CACHE_GB=${MEMORY_CACHE_GB:-0.00390625}
MEMORY_STEREO_OPTIONS="--PatchMatchStereo.num_threads 1 --MspStereo.advanced_coarsest_image_size $MEMORY_WIDTH --MspStereo.deformable false --PatchMatchStereo.cache_size $MEMORY_CACHE_GB --log_level 0"

# The bound of README's "Memory": F + M + P x (B0 + B1 x S) + cache_size, F
# the program's fixed part at one thread, M the sparse model while it is
# read (twice the size of sparse/*.bin), P the pixels of the largest image at the
# working resolution, S the sources of a problem.
MEMORY_FIXED_MIB=90
MEMORY_BYTES_PER_PIXEL=400
MEMORY_BYTES_PER_PIXEL_AND_SOURCE=16

# memory_workspace DIR N: a workspace of N generated images and about
# MEMORY_POINTS sparse points whose problems have MEMORY_SOURCES sources each.
memory_workspace() {
  "$BIN/msp_make_scene" --output "$1" --width "$MEMORY_WIDTH" --height "$MEMORY_HEIGHT" \
    --num_cameras "$2" --num_points "$MEMORY_POINTS" > "$1.scene.log" 2>&1 ||
    { cat "$1.scene.log" >&2; return 1; }
  sed -i "s/^__auto__, [0-9]*\$/__auto__, $MEMORY_SOURCES/" "$1/stereo/patch-match.cfg"
}

# memory_peak_kib WS [options...]: runs msp_stereo on WS (log in WS.log) and
# prints its peak resident memory in KiB; its user CPU seconds go to WS.seconds.
memory_peak_kib() {
  ws=$1
  shift
  # shellcheck disable=SC2086
  /usr/bin/time -f "%M %U" -o "$ws.time" nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" \
    $MEMORY_STEREO_OPTIONS "$@" > "$ws.log" 2>&1 || { tail -20 "$ws.log" >&2; return 1; }
  tail -1 "$ws.time" | cut -d' ' -f2 > "$ws.seconds"
  tail -1 "$ws.time" | cut -d' ' -f1
}

# memory_model_kib WS: M of the bound for workspace WS, in KiB.
memory_model_kib() {
  echo $((2 * $(du -k -c "$1"/sparse/*.bin | tail -1 | cut -f1)))
}

# memory_bound_kib WS: the bound in KiB for workspace WS (made as above).
memory_bound_kib() {
  pixels=$((MEMORY_WIDTH * MEMORY_HEIGHT))
  per_pixel=$((MEMORY_BYTES_PER_PIXEL + MEMORY_BYTES_PER_PIXEL_AND_SOURCE * MEMORY_SOURCES))
  cache_kib=$(awk "BEGIN { printf \"%d\", $MEMORY_CACHE_GB * 1024 * 1024 }")
  echo $((MEMORY_FIXED_MIB * 1024 + $(memory_model_kib "$1") + pixels * per_pixel / 1024 + cache_kib))
}
