#!/usr/bin/env bash
# Runs the whole workflow on a ready COLMAP dense workspace (e.g. one of
# the Middlebury and Strecha sets) and prints time, peak memory and fused-cloud figures.
#
#   bench/real_data.sh <dataset dir> <output dir> [--sources N] [--bbox x0 y0 z0 x1 y1 z1]
#                      [msp_stereo options...]
#
# The dataset is not modified: images are symlinked, sparse/ and the cfg files
# copied into <output dir>, which is recreated. --sources N rewrites the copied
# patch-match.cfg to `__auto__, N` (COLMAP's own syntax for N source views).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
src=$(cd "$1" && pwd); out=$2; shift 2
sources=""
if [ "${1:-}" = "--sources" ]; then sources=$2; shift 2; fi
bbox=()
if [ "${1:-}" = "--bbox" ]; then bbox=(--bbox "$2" "$3" "$4" "$5" "$6" "$7"); shift 7; fi
link_real_workspace "$src" "$out"
if [ -n "$sources" ]; then
  sed -i "s/^__auto__.*/__auto__, $sources/" "$out/stereo/patch-match.cfg"
fi
/usr/bin/time -v "${MSP_BIN:-$root/build/bin}/msp_stereo" --workspace_path "$out" "$@" \
  > "$out/stereo.log" 2> "$out/time.log"
colmap stereo_fusion --workspace_path "$out" --input_type geometric \
  --output_path "$out/fused.ply" > "$out/fusion.log" 2>&1
echo "dataset: $src"
grep -E "Elapsed \(wall|Maximum resident" "$out/time.log"
/usr/bin/python3 "$root/bench/ply_stats.py" "$out/fused.ply" "${bbox[@]}" --render "$out/fused.png"
