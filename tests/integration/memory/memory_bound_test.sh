#!/bin/sh
# Peak memory independent of the image count (README, "Memory"): msp_stereo
# with a 4 MiB --PatchMatchStereo.cache_size on generated workspaces of 25
# and 100 images. Both peaks stay under the bound README states, and the 100
# images need no more than the 25 but for their larger sparse model (read,
# then freed before the images) and a margin far below what keeping 75 more
# images' data would take.
# Usage: memory_bound_test.sh <bin_dir>
set -eu
BIN=$1
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
. "$(dirname "$0")/common.sh"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

# Kept for every image, the growth is at least its images (16 bytes per
# pixel) and its state (24): 75 more images would add 40 x 75 bytes per
# pixel. A bounded run may differ by an eighth of that (allocator noise).
pixels=$((MEMORY_WIDTH * MEMORY_HEIGHT))
margin_kib=$((40 * 75 * pixels / 8 / 1024))
for n in 25 100; do
  memory_workspace "$TMP/ws$n" "$n" || fail "msp_make_scene of $n images"
  bound=$(memory_bound_kib "$TMP/ws$n")
  eval "model_$n=$(memory_model_kib "$TMP/ws$n")"
  peak=$(memory_peak_kib "$TMP/ws$n") || fail "msp_stereo on $n images"
  maps=$(find "$TMP/ws$n/stereo/depth_maps" -name '*.geometric.bin' | wc -l)
  [ "$maps" -eq "$n" ] || fail "$n images: $maps geometric depth maps"
  echo "$n images: peak $peak KiB, bound $bound KiB, $(cat "$TMP/ws$n.seconds") s"
  [ "$peak" -le "$bound" ] || fail "$n images: peak $peak KiB above the bound $bound KiB"
  eval "peak_$n=$peak"
  rm -rf "$TMP/ws$n"
done
# shellcheck disable=SC2154
growth=$((peak_100 - peak_25))
# shellcheck disable=SC2154
allowed=$((margin_kib + model_100 - model_25))
echo "growth from 25 to 100 images: $growth KiB (allowed $allowed KiB: sparse model $((model_100 - model_25)), margin $margin_kib)"
[ "$growth" -le "$allowed" ] || fail "peak grew by $growth KiB from 25 to 100 images"
echo "memory bound test passed"
