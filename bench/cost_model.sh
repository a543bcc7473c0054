#!/usr/bin/env bash
# The cost model of a run: per pyramid round and step of a pass, seconds and
# share of the run (from a normal build) beside the window costs evaluated per
# pixel of one image-pass (from a counting build, -DMSP_COUNT_EVALUATIONS=ON,
# whose own seconds are inflated by the counting and not shown), split for
# the sweeps into propagation and refinement.
#
#   bench/cost_model.sh [--workspace WS] [msp_stereo options...]
#
# --workspace defaults to a fresh `msp_make_scene` workspace (640x480, 10
# views). The counting build goes to build-count/ (configured on first use);
# the normal binaries come from $MSP_BIN (default build/bin).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${MSP_BIN:-$root/build/bin}"
count_build="${MSP_COUNT_BUILD:-$root/build-count}"

workspace=""
if [ "${1:-}" = "--workspace" ]; then
  workspace=$(cd "$2" && pwd)
  shift 2
fi
[ -x "$bin/msp_stereo" ] || { echo "no $bin/msp_stereo: build first (scripts/build.sh)" >&2; exit 1; }

cmake -S "$root" -B "$count_build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUDA_ENABLED=OFF \
  -DMSP_BUILD_TESTS=OFF -DMSP_COUNT_EVALUATIONS=ON > /dev/null
cmake --build "$count_build" --target msp_stereo > /dev/null

scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
if [ -z "$workspace" ]; then
  workspace=$scratch/scene
  "$bin/msp_make_scene" --output "$workspace" > /dev/null
fi

# run NAME BIN_DIR: msp_stereo on a fresh copy of the workspace; its cost
# model table into $scratch/NAME.table, user CPU seconds into NAME.cpu.
run() {
  rm -rf "$scratch/ws"
  cp -r "$workspace" "$scratch/ws"
  rm -rf "$scratch/ws/stereo/depth_maps" "$scratch/ws/stereo/normal_maps"
  mkdir -p "$scratch/ws/stereo/depth_maps" "$scratch/ws/stereo/normal_maps"
  /usr/bin/time -f "%U %e %M" -o "$scratch/$1.time" \
    "$2/msp_stereo" --workspace_path "$scratch/ws" --log_level 2 "${@:3}" > "$scratch/$1.log"
  sed -n '/^Cost model/,$p' "$scratch/$1.log" | grep '^  ' > "$scratch/$1.table"
}

args=("$@")
run normal "$bin" "${args[@]}"
run counting "$count_build/bin" "${args[@]}"
read -r user wall rss < "$scratch/normal.time"

echo "Cost model of $workspace (options: ${args[*]:-defaults})"
echo "normal build: wall $wall s, user CPU $user s, peak $((rss / 1024)) MiB"
# Seconds and share from the normal run, counts from the counting run: the
# two tables have the same rows (one schedule).
paste -d"|" "$scratch/normal.table" "$scratch/counting.table" |
  awk -F"|" '{ printf "%s%s\n", substr($1, 1, 46), substr($2, 47) }'
