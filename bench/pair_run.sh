#!/usr/bin/env bash
# Two builds or two option sets, back to back on the same machine: the
# bundled scene (fused F1 against its exact ground truth) and optionally a
# real workspace such as the temple (points and occupied 2-mm voxels inside
# its box). Absolute times drift between hours here; ratios measured in one
# run do not.
#
#   bench/pair_run.sh [--bundled WS] [--real DIR --bbox x0 y0 z0 x1 y1 z1]
#                     [--repeat N] A B [msp_stereo options for both...]
#
# A and B are each a folder of binaries (msp_stereo, msp_evaluate), optionally
# followed by `:` and options for that side alone, e.g.
#   bench/pair_run.sh --bundled WS build/bin "build/bin:--MspStereo.deformable false"
#   bench/pair_run.sh --bundled WS --real DATA/templeSparseRing \
#     --bbox -0.073568 0.021728 -0.012445 0.028855 0.181892 0.062736 old/bin build/bin
# --bundled defaults to a fresh `msp_make_scene` workspace (640x480, 10 views).
# --repeat N runs each pair N times, alternating A and B. The real
# workspace's images are read in place (symlinked); sparse/ and the .cfg
# files are copied. COLMAP from $COLMAP (default /usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"

bundled="" real="" repeat=1
bbox=()
while [ $# -gt 0 ]; do
  case "$1" in
    --bundled) bundled=$2; shift 2 ;;
    --real) real=$(cd "$2" && pwd); shift 2 ;;
    --bbox) bbox=("$2" "$3" "$4" "$5" "$6" "$7"); shift 7 ;;
    --repeat) repeat=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -ge 2 ] || { sed -n '2,20p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }
side_a=$1 side_b=$2
shift 2
common=("$@")
if [ -n "$real" ] && [ ${#bbox[@]} -ne 6 ]; then
  echo "--real needs --bbox x0 y0 z0 x1 y1 z1 (the object's box, in the model's units)" >&2
  exit 1
fi

# bin_of SIDE / options_of SIDE: the two halves of "BIN_DIR[:options]".
bin_of() { (cd "${1%%:*}" && pwd); }
options_of() { case "$1" in *:*) echo "${1#*:}" ;; *) echo "" ;; esac; }

for side in "$side_a" "$side_b"; do
  [ -x "$(bin_of "$side")/msp_stereo" ] || { echo "$side: no msp_stereo in ${side%%:*}" >&2; exit 1; }
done

if [ -z "$bundled" ]; then
  bundled=$(mktemp -d)/scene
  "$(bin_of "$side_a")/msp_make_scene" --output "$bundled" > /dev/null
  echo "bundled scene generated in $bundled"
fi
ablation_init "$bundled"

# real_row BIN OPTIONS...: msp_stereo on a copy of the real workspace, fusion,
# then "<wall s> <user CPU-s> <peak MiB>" and the box figures in $scratch/real.
real_row() {
  local bin=$1 ws="$scratch/real"
  shift
  link_real_workspace "$real" "$ws"
  run_logged "$scratch/real_stereo.log" /usr/bin/time -f "%e %U %M" -o "$scratch/real_time" \
    "$bin/msp_stereo" --workspace_path "$ws" "$@"
  run_logged "$scratch/real_fusion.log" "$colmap" stereo_fusion --workspace_path "$ws" \
    --input_type geometric --output_path "$ws/fused.ply"
  /usr/bin/python3 "$root/bench/ply_stats.py" "$ws/fused.ply" --bbox "${bbox[@]}" \
    --voxel 0.002 > "$scratch/real_stats"
}

# The line of one side: bundled time and F1, then the real workspace's figures.
measure() {
  local side=$1 label=$2
  bin=$(bin_of "$side")
  read -r -a own <<< "$(options_of "$side")"
  run_row ${common[@]+"${common[@]}"} ${own[@]+"${own[@]}"}
  read -r wall user < "$scratch/time"
  local line
  line=$(/usr/bin/python3 - "$scratch/eval.json" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
t = e["fused"]["thresholds"]
print("%.2f %.2f" % (100 * t[0]["f1_multi"], 100 * t[1]["f1_multi"]))
PY
)
  local real_figures="- - - - -"
  if [ -n "$real" ]; then
    real_row "$bin" ${common[@]+"${common[@]}"} ${own[@]+"${own[@]}"}
    read -r rwall ruser rkib < "$scratch/real_time"
    local inside voxels
    inside=$(sed -n 's/^inside bbox[^:]*: \([0-9]*\).*/\1/p' "$scratch/real_stats")
    voxels=$(sed -n 's/^occupied voxels inside bbox[^:]*: \([0-9]*\).*/\1/p' "$scratch/real_stats")
    real_figures="$rwall $ruser $((rkib / 1024)) $inside $voxels"
  fi
  echo "$label $wall $user $line $real_figures"
}

echo "A: $side_a"
echo "B: $side_b"
echo "options of both: ${common[*]+${common[*]}}"
echo
printf '| run | side | bundled wall s | user CPU-s | F1 0.5 %% | F1 2 %% | real wall s | user CPU-s | peak MiB | points in box | 2-mm voxels in box |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|\n'
declare -a rows_a rows_b
for ((r = 1; r <= repeat; ++r)); do
  rows_a[r]=$(measure "$side_a" A)
  echo "| $r | ${rows_a[r]// / | } |"
  rows_b[r]=$(measure "$side_b" B)
  echo "| $r | ${rows_b[r]// / | } |"
done
echo
# ratio A B: B / A with two decimals, "-" without figures.
ratio() {
  case "$1$2" in *-*) echo "-" ;; *) /usr/bin/python3 -c "import sys; print('%.2f' % (float(sys.argv[2]) / float(sys.argv[1])))" "$1" "$2" ;; esac
}
# Ratios B / A per run: bundled wall and user time, real wall and user time.
for ((r = 1; r <= repeat; ++r)); do
  read -r _ aw au _ _ arw aru _ _ _ <<< "${rows_a[r]}"
  read -r _ bw bu _ _ brw bru _ _ _ <<< "${rows_b[r]}"
  echo "run $r, B / A: bundled wall $(ratio "$aw" "$bw"), user $(ratio "$au" "$bu"); real wall $(ratio "$arw" "$brw"), user $(ratio "$aru" "$bru")"
done
