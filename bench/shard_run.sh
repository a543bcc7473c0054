#!/usr/bin/env bash
# A sharded run against one process on the same machine: one msp_stereo with
# N threads, then N shards of one thread each at the same time
# (--MspStereo.shard K/N, the way N machines of a cluster run it), each on a
# fresh copy of the workspace. Prints the wall and summed user CPU seconds of
# both and checks that every depth and normal map of the sharded run equals
# the one-process run's byte for byte (exit 1 when one differs).
#
#   bench/shard_run.sh <workspace> [N] [msp_stereo options...]
#
# <workspace> is a dense workspace such as msp_make_scene writes; it is not
# modified (its maps are left out of the copies). N defaults to 2. MSP_BIN
# is the folder of msp_stereo (default build/bin).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
workspace=$(cd "$1" && pwd); shift
shards=${1:-2}; [ $# -gt 0 ] && shift
bin="${MSP_BIN:-$root/build/bin}/msp_stereo"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# The two copies, without maps or state.
for copy in one sharded; do
  cp -r "$workspace" "$scratch/$copy"
  (cd "$scratch/$copy/stereo" && rm -rf depth_maps normal_maps msp msp_shared)
done

# Runs msp_stereo on copy $1 with log name $2 (options follow); its
# "<wall> <user>" land in $scratch/$2.time.
run() {
  local copy=$1 name=$2; shift 2
  /usr/bin/time -f "%e %U" -o "$scratch/$name.time" "$bin" --workspace_path "$scratch/$copy" \
    "$@" > "$scratch/$name.log" 2>&1 || { cat "$scratch/$name.log"; return 1; }
}

now_ms() { echo $(($(date +%s%N) / 1000000)); }
t0=$(now_ms)
run one one --PatchMatchStereo.num_threads "$shards" "$@"
one_wall=$(awk -v ms=$(($(now_ms) - t0)) 'BEGIN { print ms / 1000 }')
t0=$(now_ms)
pids=()
for ((k = 0; k < shards; ++k)); do
  run sharded "shard$k" --PatchMatchStereo.num_threads 1 --MspStereo.shard "$k/$shards" "$@" &
  pids+=($!)
done
for pid in "${pids[@]}"; do wait "$pid"; done
sharded_wall=$(awk -v ms=$(($(now_ms) - t0)) 'BEGIN { print ms / 1000 }')
sharded_user=$(cat "$scratch"/shard*.time | awk '{ s += $2 } END { printf "%.1f", s }')
waited=$(grep -h "every image has finished" "$scratch"/shard*.log |
         sed 's/.*waited \([0-9.]*\) s.*/\1/' | awk '{ s += $1 } END { printf "%.1f", s }')

differ=0
total=0
for f in $(cd "$scratch/one/stereo" && find depth_maps normal_maps -name '*.bin'); do
  total=$((total + 1))
  cmp -s "$scratch/one/stereo/$f" "$scratch/sharded/stereo/$f" || { echo "differs: $f"; differ=$((differ + 1)); }
done
[ "$(cd "$scratch/sharded/stereo" && find depth_maps normal_maps -name '*.bin' | wc -l)" = "$total" ] ||
  { echo "the sharded run wrote another number of maps"; differ=$((differ + 1)); }

printf "1 process x %d threads: wall %.1f s, user %.1f s\n" "$shards" "$one_wall" \
  "$(cut -d' ' -f2 "$scratch/one.time")"
printf "%d shards x 1 thread:   wall %.1f s, user %.1f s (summed), %s s waiting at barriers (summed)\n" \
  "$shards" "$sharded_wall" "$sharded_user" "$waited"
echo "maps: $((total - differ)) of $total byte-identical"
[ "$differ" = 0 ]
