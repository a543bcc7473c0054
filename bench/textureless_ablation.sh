#!/usr/bin/env bash
# Textureless surfaces, each step off in turn: runs msp_stereo on a fresh copy
# of a workspace with ground truth (the bundled scene) once per row below,
# one after the other, fuses with COLMAP and evaluates, and prints one table
# row per run: time, fused accuracy and F1 (>= 3 views) at 0.5 % and 2 % of
# the extent, and the textureless pixels' valid share, share within 1 % and
# median normal error.
#
#   bench/textureless_ablation.sh <workspace> [msp_stereo options for every run...]
#
# e.g. bench/textureless_ablation.sh WS --PatchMatchStereo.max_image_size 320
# Binaries from $MSP_BIN (default build/bin); colmap from $COLMAP (/usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
ablation_init "$1"
shift
common=("$@")

rows=(
  "default|"
  "segment planes off|--MspStereo.segment_planes false"
  "textureless filter by NCC (as COLMAP)|--MspStereo.filter_textureless_by_geometry false"
  "nearest-neighbour upsampling|--MspStereo.advanced_joint_bilateral_upsampling false"
  "finest round deformable, 3 iterations|--MspStereo.deformable true --MspStereo.advanced_finest_deformable true --MspStereo.advanced_finest_iterations 3"
  "one round (no pyramid)|--MspStereo.advanced_coarsest_image_size 100000"
)

all_options=("${common[@]}")
for row in "${rows[@]}"; do read -r -a options <<< "${row#*|}"; all_options+=("${options[@]}"); done
require_known_options "${all_options[@]}"

printf '| run | wall s | user CPU-s | fused acc 0.5 / 2 %% | fused F1 0.5 / 2 %% | textureless valid / within 1 %% / normal |\n'
printf '|---|---|---|---|---|---|\n'
for row in "${rows[@]}"; do
  name=${row%%|*}
  read -r -a options <<< "${row#*|}"
  run_row "${common[@]}" "${options[@]}"
  read -r wall user < "$scratch/time"
  /usr/bin/python3 - "$scratch/eval.json" "$name" "$wall" "$user" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
name, wall, user = sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
f = e["fused"]
t = e["average"]["textureless"]
relative = [x for x in f["thresholds"] if not x["absolute"]]  # 0.5 % and 2 % of the extent
acc = " / ".join("%.1f" % (100 * x["accuracy"]) for x in relative)
f1 = " / ".join("%.1f" % (100 * x["f1_multi"]) for x in relative)
print("| %s | %.0f | %.0f | %s | %s | %.1f / %.1f %% / %.1f deg |" % (
    name, wall, user, acc, f1, 100 * t["valid_fraction"], 100 * t["complete_1"],
    t["median_normal_error_deg"]))
PY
done
