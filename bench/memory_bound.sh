#!/usr/bin/env bash
# Peak memory of msp_stereo against the number of images (README, "Memory"):
# generated workspaces of each count (64x64 images, 2 sources per problem,
# one round of the conventional core), msp_stereo on one thread with a 4 MiB
# --PatchMatchStereo.cache_size, and a table of the peak resident memory, the
# bound the README states for it and the user CPU time of each count.
#
#   [MEMORY_CACHE_GB=G] bench/memory_bound.sh [--counts "25 50 100"] [msp_stereo options...]
#
# Binaries from $MSP_BIN (default build/bin). MEMORY_CACHE_GB=32 (the
# default cache_size) keeps everything, to see memory grow with the count.
# Extra options go to every run.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
counts="25 50 100"
if [ "${1:-}" = "--counts" ]; then counts=$2; shift 2; fi
BIN="${MSP_BIN:-$root/build/bin}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# shellcheck source=../tests/integration/memory/common.sh
. "$root/tests/integration/memory/common.sh"

echo "| images | peak RSS (MiB) | bound (MiB) | user CPU (s) |"
echo "|---:|---:|---:|---:|"
for n in $counts; do
  memory_workspace "$scratch/ws$n" "$n"
  bound=$(memory_bound_kib "$scratch/ws$n")
  peak=$(memory_peak_kib "$scratch/ws$n" "$@")
  awk -v n="$n" -v p="$peak" -v b="$bound" -v s="$(cat "$scratch/ws$n.seconds")" \
    'BEGIN { printf "| %d | %.1f | %.1f | %.0f |\n", n, p / 1024, b / 1024, s }'
  rm -rf "$scratch/ws$n"
done
