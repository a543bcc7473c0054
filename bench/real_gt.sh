#!/usr/bin/env bash
# Real frames with sensor ground truth: imports a posed RGB-D capture with
# msp_import_rgbd (office-rgbd by default: a fixed selection of 14 frames, the
# corridor's walls, doors, sofa and cabinet), then per row runs msp_stereo on
# a fresh copy of the workspace, fuses with COLMAP (geometric) and evaluates
# against the sensor depth, and prints one Markdown table: map figures over
# the measured pixels (within 5 % / 1 %, textureless ones within 5 %, and of
# those two other frames see at the filter's angle, bench/map_stages.py
# --seen, the share right before the filter and kept right), fused
# accuracy / completeness / F1 at 5 cm and 2 cm, and time per frame. Then,
# unless --no_bundled, the bundled scene at 640x480 with the default options
# in the same sitting, for its time per image.
#
#   bench/real_gt.sh [--rows IDS] [--no_bundled] [--keep DIR] <rgbd dir> [msp_stereo options...]
#
# <rgbd dir> holds images/, depth/ (16-bit PNGs, millimetres), K.txt and
# poses.txt, as ../shared/data/office-rgbd does. Rows (--rows, comma-separated,
# in this order): default (the default options: the conventional patch-match
# core), method (--MspStereo.deformable true: the whole MSP-MVS method), and the Table 3 rows of
# bench/lib/table3_rows.sh by id (baseline = APD-MVS, novar, ...); the default
# set is default,method,baseline. --keep DIR keeps the imported workspace
# and each row's maps, fused cloud, previews and evaluation in DIR/<row>.
# Frames: $RGBD_FRAMES (default 0-8,35-39), depth units $RGBD_UNITS (1000).
# Binaries from $MSP_BIN (default build/bin); colmap from $COLMAP (/usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
# shellcheck source=bench/lib/table3_rows.sh
source "$(dirname "$0")/lib/table3_rows.sh"

selected="default,method,baseline"
bundled=1
keep=""
while [ $# -gt 0 ]; do
  case "$1" in
    --rows) selected=$2; shift 2 ;;
    --no_bundled) bundled=0; shift ;;
    --keep) keep=$2; shift 2 ;;
    *) break ;;
  esac
done
[ $# -gt 0 ] || { sed -n '2,24p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }
data=$(cd "$1" && pwd)
shift
common=("$@")
frames=${RGBD_FRAMES:-0-8,35-39}
units=${RGBD_UNITS:-1000}

root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${MSP_BIN:-$root/build/bin}"
colmap="${COLMAP:-/usr/bin/colmap}"
top=$(mktemp -d)
trap 'rm -rf "$top"' EXIT

# id -> label and options, checked before the first run.
plans=()
for id in ${selected//,/ }; do
  case "$id" in
    default) plans+=("default|default options (conventional core)|") ;;
    method) plans+=("method|MSP-MVS (deformable true)|--MspStereo.deformable true") ;;
    *)
      row=$(table3_row "$id")
      [ -n "$row" ] || { echo "--rows: no row \`$id\`" >&2; exit 1; }
      plans+=("$row") ;;
  esac
done

echo "importing $data (frames $frames)" >&2
run_logged "$top/import.log" "$bin/msp_import_rgbd" --input "$data" --output "$top/office" \
  --depth_units_per_metre "$units" --frames "$frames" --colmap "$colmap"
cat "$top/import.log"
[ -z "$keep" ] || { rm -rf "$keep"; mkdir -p "$keep"; cp -r "$top/office" "$keep/workspace"; }
num_frames=$(wc -l < "$top/office/ground_truth/images.txt")

ablation_init "$top/office"
trap 'rm -rf "$scratch" "$top"' EXIT
require_known_options ${common[@]+"${common[@]}"} --MspStereo.write_previews 1
for plan in "${plans[@]}"; do
  plan_fields "$plan"
  require_known_options ${options[@]+"${options[@]}"}
done

echo
echo "msp_stereo options of every row: ${common[*]+${common[*]}}"
echo
printf '| row | wall s | CPU-s | wall s / frame | maps within 5 %% / 1 %% | valid %% | textureless within 5 %% | seen: right before the filter / kept and right %% | fused points (judged) | acc. / comp. / F1 at 5 cm | F1 at 5 cm, >= 3 views | acc. / comp. / F1 at 2 cm |\n'
printf '|---|---|---|---|---|---|---|---|---|---|---|---|\n'
n=0
for plan in "${plans[@]}"; do
  n=$((n + 1))
  plan_fields "$plan"
  echo "row $n/${#plans[@]} ($id): msp_stereo ${common[*]+${common[*]}} ${options[*]+${options[*]}}" >&2
  run_row ${common[@]+"${common[@]}"} ${options[@]+"${options[@]}"} --MspStereo.write_previews 1
  COLMAP="$colmap" run_logged "$scratch/stages.log" /usr/bin/python3 "$root/bench/map_stages.py" \
    "$scratch/ws" --seen --json "$scratch/stages.json"
  if [ -n "$keep" ]; then
    cp -r "$scratch/ws/stereo" "$keep/$id"
    cp "$scratch/ws/fused.ply" "$scratch/eval.json" "$scratch/stereo.log" "$keep/$id/"
  fi
  read -r wall user < "$scratch/time"
  /usr/bin/python3 - "$scratch/eval.json" "$label" "$wall" "$user" "$num_frames" \
    "$scratch/stages.json" <<'PY'
import json, sys
e = json.load(open(sys.argv[1]))
# Of the pixels two other frames see at the filter's angle (map_stages.py
# --seen): right before the filter, and kept right (stage 0, "kept").
seen = json.load(open(sys.argv[6]))["totals"]["seen"]
seen_pixels = sum(s[0] for s in seen[:-1])
seen_cell = "%.1f / %.1f" % (100.0 * sum(s[1] for s in seen[:-1]) / seen_pixels,
                             100.0 * seen[0][1] / seen_pixels) if seen_pixels else "-"
label, wall, user, frames = sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), int(sys.argv[5])
pct = lambda v: "%.1f" % (100.0 * v)
a = e["average"]
f = e["fused"]
absolute = {round(t["metres"], 4): t for t in f["thresholds"] if t["absolute"]}
cloud = lambda t: "%s / %s / %s" % (pct(t["accuracy"]), pct(t["completeness"]), pct(t["f1"]))
tl = a["textureless"]
print("| " + " | ".join([
    label, "%.0f" % wall, "%.0f" % user, "%.1f" % (wall / frames),
    "%s / %s" % (pct(a["all"]["complete_2"]), pct(a["all"]["complete_1"])),
    pct(a["all"]["valid_fraction"]),
    pct(tl["complete_2"]) if tl is not None else "-", seen_cell,
    "%d (%d)" % (f["num_points"], f["num_judged"]),
    cloud(absolute[0.05]), pct(absolute[0.05]["f1_multi"]), cloud(absolute[0.02])]) + " |")
PY
done
echo
echo "Maps: mean over frames of the share of measured pixels within 5 % / 1 % relative depth error"
echo "(pixels without a sensor measurement count neither way); valid = measured pixels with a depth."
echo "Fused: accuracy over the points some frame measured, completeness over the sensor's surface"
echo "sample ($num_frames frames, 5 mm voxels), F1 of both; >= 3 views: completeness over the samples"
echo "three or more frames measured, what COLMAP's default fusion can reach. Seen: the measured"
echo "pixels that two other frames see, unoccluded, at a triangulation angle of 3 degrees or more"
echo "(bench/map_stages.py --seen), the most the filtered maps can keep; within 5 %."

if [ "$bundled" = 1 ]; then
  echo "bundled scene at 640x480 (default options), same sitting" >&2
  run_logged "$top/make_scene.log" "$bin/msp_make_scene" --output "$top/bundled"
  run_logged "$top/bundled.log" /usr/bin/time -f "%e %U" -o "$top/bundled.time" \
    "$bin/msp_stereo" --workspace_path "$top/bundled" ${common[@]+"${common[@]}"}
  read -r wall user < "$top/bundled.time"
  images=$(wc -l < "$top/bundled/ground_truth/images.txt")
  echo
  per_image=$(/usr/bin/python3 -c "print('%.1f' % ($wall / $images))")
  echo "Bundled scene, same sitting: $images images at 640x480, $wall s wall ($per_image s per image), $user CPU-s"
fi
