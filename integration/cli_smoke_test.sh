#!/bin/sh
# The command-line flow of the bundled scene: msp_make_scene -> msp_write_gt_maps
# -> colmap stereo_fusion -> msp_evaluate --json, on a small scene.
# Usage: cli_smoke_test.sh <bin_dir> <colmap>
set -eu
bin_dir=$1
colmap=$2
[ -x "$colmap" ] || { echo "colmap is not installed at $colmap" >&2; exit 1; }
ws=$(mktemp -d)
trap 'rm -rf "$ws"' EXIT

"$bin_dir/msp_make_scene" --output "$ws" --seed 3 --width 320 --height 240 --num_cameras 6
"$bin_dir/msp_write_gt_maps" --workspace "$ws"
test -f "$ws/stereo/depth_maps/img_005.png.geometric.bin"
test -f "$ws/stereo/normal_maps/img_005.png.geometric.bin"
"$colmap" stereo_fusion --workspace_path "$ws" --input_type geometric \
  --output_path "$ws/fused.ply" > "$ws/fusion.log" 2>&1 || { cat "$ws/fusion.log"; exit 1; }
"$bin_dir/msp_evaluate" --workspace "$ws" --fused "$ws/fused.ply" --json "$ws/eval.json"
grep -q '"f1_multi"' "$ws/eval.json"
grep -q '"num_missing_maps": 0' "$ws/eval.json"
# Bad input gives one ERROR line and a non-zero exit.
if "$bin_dir/msp_evaluate" --workspace "$ws/nonexistent" 2> "$ws/err.txt"; then exit 1; fi
grep -q '^ERROR: ' "$ws/err.txt"
# Every tool lists its options with their defaults, and stops on an unknown one.
for tool in msp_make_scene msp_write_gt_maps msp_evaluate; do
  "$bin_dir/$tool" --help > "$ws/help.txt"
  grep -q -- '--help' "$ws/help.txt"
  grep -q '(=' "$ws/help.txt"
  if "$bin_dir/$tool" --no_such_option 1 2> "$ws/err.txt"; then exit 1; fi
  grep -q "^ERROR: unknown option \`--no_such_option\`" "$ws/err.txt"
done
echo "cli smoke test passed"
