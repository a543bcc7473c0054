#!/usr/bin/env bash
# How the time of a run grows with the pixels and with the source views:
# default options (or the options given) on generated scenes, one run each,
# printing per image wall and user CPU seconds, peak memory and fused F1.
#
#   bench/scaling.sh [--sizes "320 640 1280"] [--sources "4 9 19"] [msp_stereo options...]
#
# Pixels: 10-view scenes at each width (4:3). Sources: one 20-view scene at
# 320x240 whose patch-match.cfg asks for `__auto__, N`. Binaries from $MSP_BIN
# (default build/bin), COLMAP from $COLMAP (default /usr/bin/colmap).
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${MSP_BIN:-$root/build/bin}"

sizes="320 640 1280" sources="4 9 19"
while [ $# -gt 0 ]; do
  case "$1" in
    --sizes) sizes=$2; shift 2 ;;
    --sources) sources=$2; shift 2 ;;
    *) break ;;
  esac
done
top=$(mktemp -d)
trap 'rm -rf "$top"' EXIT

# row LABEL WORKSPACE IMAGES: one run (run_row) and its figures per image.
row() {
  ablation_init "$2"
  trap 'rm -rf "$scratch" "$top"' EXIT
  run_row "${options[@]}" > /dev/null
  read -r wall user < "$scratch/time"
  python3 - "$1" "$3" "$wall" "$user" "$scratch/eval.json" <<'PY'
import json, sys
label, images, wall, user, path = sys.argv[1], int(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
t = [x for x in json.load(open(path))["fused"]["thresholds"] if not x["absolute"]]
f1 = " / ".join("%.2f" % (100 * x["f1_multi"]) for x in t)
print("| %s | %.1f | %.1f | %s |" % (label, wall / images, user / images, f1))
PY
}
options=("$@")

echo "| run | wall s / image | user CPU-s / image | fused F1 at 0.5 / 2 % |"
echo "|---|---|---|---|"
for width in $sizes; do
  ws="$top/scene-$width"
  "$bin/msp_make_scene" --output "$ws" --width "$width" --height $((width * 3 / 4)) > /dev/null
  row "${width}x$((width * 3 / 4)), 10 views, 9 sources" "$ws" 10
done
ws="$top/scene-20"
"$bin/msp_make_scene" --output "$ws" --width 320 --height 240 --num_cameras 20 > /dev/null
for n in $sources; do
  sed -i "s/^__auto__.*/__auto__, $n/" "$ws/stereo/patch-match.cfg"
  row "320x240, 20 views, $n sources" "$ws" 20
done
