#!/usr/bin/env bash
# What deformable patch matching costs over the conventional core on one
# workspace: runs `--MspStereo.deformable true` and `--MspStereo.deformable false`,
# each on a fresh copy, and prints wall and user CPU seconds of every run, the
# ratio of each pair and the median of the ratios. On a shared machine the
# speed drifts between runs by more than the margin being measured: compare
# the ratios of pairs, never times across pairs, and quote the median.
#
#   bench/deformable_overhead.sh [--concurrent] <workspace> [pairs] [msp_stereo options...]
#
# By default the two runs of a pair follow each other, on all cores. With
# --concurrent they run at the same time on one thread each, so that both see
# the same machine: a drift then slows both alike and leaves the ratio. When
# the first of the two ends, a filler run takes its core until the other ends,
# so that neither finishes alone on a quieter machine (which would flatter it).
# The deformable run ("default" below) is the more sensitive to what runs beside it, so pairs one
# after the other are the fairer measure of what a user sees.
#
# <workspace> is a dense workspace such as msp_make_scene writes; it is not
# modified (its stereo/depth_maps and normal_maps are left out of the copies).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
concurrent=0
if [ "${1:-}" = "--concurrent" ]; then concurrent=1; shift; fi
workspace=$(cd "$1" && pwd); shift
pairs=${1:-2}; [ $# -gt 0 ] && shift
bin="${MSP_BIN:-$root/build/bin}/msp_stereo"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# Runs msp_stereo on a fresh copy named $1 (options follow); its
# "<wall> <user> <peak KiB>" land in $scratch/$1.time.
run() {
  local name=$1; shift
  rm -rf "$scratch/$name"
  cp -r "$workspace" "$scratch/$name"
  rm -rf "$scratch/$name/stereo/depth_maps" "$scratch/$name/stereo/normal_maps" \
         "$scratch/$name/stereo/msp"
  mkdir -p "$scratch/$name/stereo/depth_maps" "$scratch/$name/stereo/normal_maps"
  /usr/bin/time -f "%e %U %M" -o "$scratch/$name.time" "$bin" --workspace_path "$scratch/$name" \
    "$@" > "$scratch/$name.log" 2>&1 || { cat "$scratch/$name.log"; return 1; }
}

# One core kept busy with conventional runs until killed.
keep_busy() {
  while :; do run filler --MspStereo.deformable false --PatchMatchStereo.num_threads 1 "$@" || true; done
}

# Background jobs in process groups of their own: a filler dies with its runs.
set -m
echo "pair  default: wall s  user s  peak MiB | conventional: wall s  user s  peak MiB | ratio wall  user"
for ((k = 1; k <= pairs; ++k)); do
  if [ "$concurrent" = 1 ]; then
    run default --MspStereo.deformable true --PatchMatchStereo.num_threads 1 "$@" &
    default_pid=$!
    run conventional --MspStereo.deformable false --PatchMatchStereo.num_threads 1 "$@" &
    conventional_pid=$!
    wait -n "$default_pid" "$conventional_pid"
    keep_busy "$@" > /dev/null 2>&1 &
    filler_pid=$!
    while kill -0 "$default_pid" 2> /dev/null || kill -0 "$conventional_pid" 2> /dev/null; do
      sleep 1
    done
    kill -- "-$filler_pid" 2> /dev/null || true
    wait "$filler_pid" 2> /dev/null || true
  else
    run default --MspStereo.deformable true "$@"
    run conventional --MspStereo.deformable false "$@"
  fi
  read -r dw du dm < "$scratch/default.time"
  read -r cw cu cm < "$scratch/conventional.time"
  awk -v k="$k" -v dw="$dw" -v du="$du" -v dm="$dm" -v cw="$cw" -v cu="$cu" -v cm="$cm" 'BEGIN {
    printf "%4d  %15.1f %7.1f %9.0f | %20.1f %7.1f %9.0f | %10.3f %5.3f\n",
           k, dw, du, dm / 1024, cw, cu, cm / 1024, dw / cw, du / cu }' | tee -a "$scratch/ratios"
done
# Single pairs wander by several percent on a shared machine: the median of
# the pairs' ratios is the figure to quote.
if [ "$pairs" -gt 1 ]; then
  median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2 ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2) }'; }
  printf "median of %d pairs: ratio wall %.3f, user %.3f\n" "$pairs" \
    "$(awk '{ print $(NF - 1) }' "$scratch/ratios" | median)" "$(awk '{ print $NF }' "$scratch/ratios" | median)"
fi
