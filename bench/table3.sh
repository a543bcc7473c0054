#!/usr/bin/env bash
# The MSP-MVS ablation in the shape of the paper's Table 3: runs msp_stereo on
# a fresh copy of a workspace with ground truth (the bundled scene) once per
# row below, one after the other, fuses with COLMAP (geometric) and evaluates,
# and prints a Markdown table: time, the time ratio to the first row, fused
# F1 / completeness / accuracy (>= 3 views) at 0.5 % and 2 % of the scene
# extent, and the depth maps' share within 1 % on textureless pixels, near a
# true depth edge and near an edge between alike colours (msp_evaluate).
#
#   bench/table3.sh [--rows ID,ID,...] [--seeds S,S,...] [--drop_unknown] [--ideal_masks]
#                   <workspace> [msp_stereo options...]
#
# The options after the workspace go to every row, e.g. a quick look:
#   bench/table3.sh WS --PatchMatchStereo.max_image_size 320 --PatchMatchStereo.num_threads 1
# --rows runs the named rows only (ids below), in the table's order.
# --seeds runs every row once per seed (--random_seed S) and prints the
# means: the figures of one seed swing by a point or two.
# --drop_unknown leaves out of each row the options this msp_stereo does not
# accept, and names them under the table: for a binary built before a part
# existed, whose rows then run that part as that binary does. Without it an
# unknown option stops the script before the first run.
# --ideal_masks adds, after `full`, the rows of the method with a perfect
# prior (full_ideal, noref_ideal, default_ideal, whole_windows_ideal;
# bench/lib/table3_rows.sh): they read the
# scene's ideal mask layers, its surface ids (msp_make_scene --ideal_masks,
# made again in a scratch folder from ground_truth/scene.json, whose images
# must match the workspace's byte for byte), and every other row runs the
# embedded segmenter beside them (no mask files, even when the workspace has
# a masks/ folder). Without it every row reads the workspace's masks/ if it
# has one. E.g. the perfect prior beside the embedded segmenter:
#   bench/table3.sh --ideal_masks --rows full,full_ideal,default WS
# Binaries from $MSP_BIN (default build/bin); colmap from $COLMAP (/usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"

# shellcheck source=bench/lib/table3_rows.sh
source "$(dirname "$0")/lib/table3_rows.sh"

selected=""
seeds=""
drop_unknown=0
ideal_masks=0
while [ $# -gt 0 ]; do
  case "$1" in
    --rows) selected=$2; shift 2 ;;
    --seeds) seeds=${2//,/ }; shift 2 ;;
    --drop_unknown) drop_unknown=1; shift ;;
    --ideal_masks) ideal_masks=1; shift ;;
    *) break ;;
  esac
done
# The usage: the comment at the top.
[ $# -gt 0 ] || { awk 'NR > 1 && !/^#/ { exit } NR > 1 { sub(/^# ?/, ""); print }' "$0" >&2; exit 1; }
ablation_init "$1"
shift
common=("$@")
require_known_options "${common[@]}"

# make_ideal_masks DIR: the workspace's ideal mask layers in DIR, from
# msp_make_scene --ideal_masks with the scene's seed, image size, cameras and
# sky window; ends the script unless its images are the workspace's.
make_ideal_masks() {
  local json="$workspace/ground_truth/scene.json" scene="$scratch/ideal_scene" args
  args=$(/usr/bin/python3 - "$json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
if "seed" not in s or not s.get("cameras"):
    sys.exit("%s: no seed and cameras: not a scene of msp_make_scene" % sys.argv[1])
c = s["cameras"]
print("--seed %d --width %d --height %d --num_cameras %d%s" % (
    int(s["seed"]), c[0]["width"], c[0]["height"], len(c),
    "" if s.get("sky_window", True) else " --no_sky_window"))
PY
  ) || { echo "--ideal_masks needs a workspace of msp_make_scene" >&2; exit 1; }
  # shellcheck disable=SC2086  # the arguments above, split on purpose
  run_logged "$scratch/make_scene.log" "$bin/msp_make_scene" --output "$scene" $args --ideal_masks
  local image name
  for image in "$scene"/images/*; do
    name=${image#"$scene/images/"}
    cmp -s "$image" "$workspace/images/$name" || {
      echo "--ideal_masks: msp_make_scene $args gives another images/$name than $workspace" \
        "(a workspace of another renderer, or not of msp_make_scene)" >&2
      exit 1
    }
  done
  mv "$scene/masks" "$1"
  rm -rf "$scene"
}

if [ "$ideal_masks" = 1 ]; then
  require_known_options --MspStereo.mask_path
  with_ideal=()
  for row in "${rows[@]}"; do
    with_ideal+=("$row")
    [ "${row%%|*}" = full ] && with_ideal+=("${ideal_rows[@]}")
  done
  rows=("${with_ideal[@]}")
elif [ -d "$workspace/masks" ]; then
  echo "note: every row's prior reads the mask layers in $workspace/masks" \
    "(--ideal_masks runs the embedded segmenter beside the ideal masks)" >&2
fi

ids=()
for row in "${rows[@]}"; do ids+=("${row%%|*}"); done
if [ -n "$selected" ]; then
  for id in ${selected//,/ }; do
    for ideal in "${ideal_rows[@]}"; do
      [ "$ideal_masks" = 1 ] || [ "$id" != "${ideal%%|*}" ] ||
        { echo "--rows: row \`$id\` needs --ideal_masks" >&2; exit 1; }
    done
    printf '%s\n' "${ids[@]}" | grep -qxF -- "$id" ||
      { echo "--rows: no row \`$id\`; rows: ${ids[*]}" >&2; exit 1; }
  done
  kept=()
  for row in "${rows[@]}"; do
    case ",$selected," in *",${row%%|*},"*) kept+=("$row") ;; esac
  done
  rows=("${kept[@]}")
fi

# Every row's options, checked (or pruned) before the first run.
notes=()
plans=()
missing=""
for row in "${rows[@]}"; do
  id=${row%%|*}
  rest=${row#*|}
  read -r -a options <<< "${rest#*|}"
  unknown=$(unknown_options ${options[@]+"${options[@]}"})
  if [ -n "$unknown" ] && [ "$drop_unknown" = 0 ]; then
    missing+="  $id: $(paste -sd ' ' <<< "$unknown")"$'\n'
  elif [ -n "$unknown" ]; then
    kept=()
    for ((i = 0; i < ${#options[@]}; i += 2)); do
      grep -qxF -- "${options[i]}" <<< "$unknown" || kept+=("${options[i]}" "${options[i + 1]}")
    done
    options=(${kept[@]+"${kept[@]}"})
    notes+=("$id ran without $(paste -sd ' ' <<< "$unknown")")
  fi
  plans+=("$id|${rest%%|*}|${options[*]+${options[*]}}")
done
if [ -n "$missing" ]; then
  printf '%s does not know these options (--drop_unknown runs without them):\n%s' \
    "$bin/msp_stereo" "$missing" >&2
  exit 1
fi

if [ "$ideal_masks" = 1 ]; then
  make_ideal_masks "$scratch/ideal_masks"
  mkdir -p "$scratch/no_masks"
fi

echo "msp_stereo options of every row: ${common[*]+${common[*]}}"
echo
printf '| row | wall s | CPU-s | CPU x | F1 0.5 %% | comp. 0.5 %% | acc. 0.5 %% | F1 2 %% | comp. 2 %% | acc. 2 %% | textureless within 1 %% | near-edge within 1 %% (valid) | alike-edge within 1 %% (valid) | depth where empty %% |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n'
first_runs=""
n=0
for plan in "${plans[@]}"; do
  n=$((n + 1))
  plan_fields "$plan"
  # With --ideal_masks the ideal rows read the scene's surface ids, the
  # others no mask files.
  masks=()
  if [ "$ideal_masks" = 1 ]; then
    masks=(--MspStereo.mask_path "$scratch/no_masks")
    for ideal in "${ideal_rows[@]}"; do
      [ "$id" = "${ideal%%|*}" ] && masks=(--MspStereo.mask_path "$scratch/ideal_masks")
    done
  fi
  echo "row $n/${#plans[@]} ($id): msp_stereo ${common[*]+${common[*]}} ${options[*]+${options[*]}} ${masks[*]+${masks[*]}}" >&2
  runs=()
  for seed in ${seeds:-default}; do
    seed_option=()
    [ "$seed" = default ] || seed_option=(--random_seed "$seed")
    run_row ${common[@]+"${common[@]}"} ${options[@]+"${options[@]}"} ${masks[@]+"${masks[@]}"} \
      ${seed_option[@]+"${seed_option[@]}"}
    cp "$scratch/eval.json" "$scratch/eval_$seed.json"
    runs+=("$scratch/eval_$seed.json" "$(cat "$scratch/time")")
  done
  first_runs=${first_runs:-${runs[*]}}
  /usr/bin/python3 - "$label" "${runs[*]}" "$first_runs" <<'PY'
import json, sys
label = sys.argv[1]
def load(spec):  # "eval.json wall user eval.json wall user ..."
    f = spec.split()
    return [(json.load(open(f[i])), float(f[i + 1]), float(f[i + 2])) for i in range(0, len(f), 3)]
runs, first = load(sys.argv[2]), load(sys.argv[3])
mean = lambda values: sum(values) / len(values)
pct = lambda pick: "%.2f" % (100.0 * mean([pick(e) for e, _, _ in runs]))
fused = []
for k in range(2):  # 0.5 % then 2 % of the extent; the absolute ones follow
    for key in ("f1_multi", "completeness_multi", "accuracy"):
        fused.append(pct(lambda e: e["fused"]["thresholds"][k][key]))
region = lambda r: "%s (%s)" % (pct(lambda e: e["average"][r]["complete_1"]),
                                pct(lambda e: e["average"][r]["valid_fraction"]))
empty = lambda e: (e["average"].get("empty") or {}).get("with_depth_fraction", 0.0)
user = mean([u for _, _, u in runs])
ratio = user / mean([u for _, _, u in first])
print("| " + " | ".join([label, "%.0f" % mean([w for _, w, _ in runs]), "%.0f" % user,
                         "%.2f" % ratio] + fused +
                        [pct(lambda e: e["average"]["textureless"]["complete_1"]),
                         region("near_edge"), region("alike_edge"), pct(empty)]) + " |")
PY
done
echo
[ -z "$seeds" ] || echo "Means over seeds $seeds."
echo "CPU x = user CPU time over the first row's. Fused figures over the surface seen by >= 3 views;"
echo "map figures: share of ground-truth pixels within 1 % depth (and with a valid depth), mean over images."
for note in ${notes[@]+"${notes[@]}"}; do echo "$note"; done
