#!/usr/bin/env bash
# What deformable patch matching costs over the conventional core on one
# workspace: runs the default options and `--MspStereo.deformable false`
# alternately, each on a fresh copy, and prints wall and user CPU seconds of
# every run and the ratio of each pair. On a shared machine the speed drifts
# between runs by more than the margin being measured: compare the ratios of
# pairs, never times across pairs.
#
#   bench/deformable_overhead.sh <workspace> [pairs] [msp_stereo options...]
#
# <workspace> is a dense workspace such as msp_make_scene writes; it is not
# modified (its stereo/depth_maps and normal_maps are left out of the copies).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
workspace=$(cd "$1" && pwd); shift
pairs=${1:-2}; [ $# -gt 0 ] && shift
bin="${MSP_BIN:-$root/build/bin}/msp_stereo"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Prints "<wall> <user> <peak KiB>" of one run on a fresh copy.
run() {
  rm -rf "$scratch/ws"
  cp -r "$workspace" "$scratch/ws"
  rm -rf "$scratch/ws/stereo/depth_maps" "$scratch/ws/stereo/normal_maps" "$scratch/ws/stereo/msp"
  mkdir -p "$scratch/ws/stereo/depth_maps" "$scratch/ws/stereo/normal_maps"
  /usr/bin/time -f "%e %U %M" -o "$scratch/time" "$bin" --workspace_path "$scratch/ws" "$@" \
    > "$scratch/log" 2>&1 || { cat "$scratch/log"; exit 1; }
  cat "$scratch/time"
}

echo "pair  default: wall s  user s  peak MiB | conventional: wall s  user s  peak MiB | ratio wall  user"
for ((k = 1; k <= pairs; ++k)); do
  read -r dw du dm <<< "$(run "$@")"
  read -r cw cu cm <<< "$(run --MspStereo.deformable false "$@")"
  awk -v k="$k" -v dw="$dw" -v du="$du" -v dm="$dm" -v cw="$cw" -v cu="$cu" -v cm="$cm" 'BEGIN {
    printf "%4d  %15.1f %7.1f %9.0f | %20.1f %7.1f %9.0f | %10.3f %5.3f\n",
           k, dw, du, dm / 1024, cw, cu, cm / 1024, dw / cw, du / cu }'
done
