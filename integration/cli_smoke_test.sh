#!/bin/sh
# The command-line flow of the bundled scene: msp_make_scene -> msp_write_gt_maps
# -> colmap stereo_fusion -> msp_evaluate --json, on a small scene; then every
# tool's --help and command-line errors.
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
for tool in msp_make_scene msp_write_gt_maps msp_evaluate msp_import_rgbd; do
  "$bin_dir/$tool" --help > "$ws/help.txt"
  grep -q -- '--help' "$ws/help.txt"
  grep -q '(=' "$ws/help.txt"
  if "$bin_dir/$tool" --no_such_option 1 2> "$ws/err.txt"; then exit 1; fi
  grep -q "^ERROR: unknown option \`--no_such_option\`" "$ws/err.txt"
done
# msp_import_rgbd: one ERROR line for a missing depth scale, before anything is written.
if "$bin_dir/msp_import_rgbd" --input "$ws" --output "$ws/rgbd_ws" 2> "$ws/err.txt"; then exit 1; fi
grep -q "^ERROR: --depth_units_per_metre is required" "$ws/err.txt"
test ! -e "$ws/rgbd_ws"
# msp_convert_masks: help, and one ERROR line for an unknown or a missing option.
"$bin_dir/msp_convert_masks" --help > "$ws/help.txt"
grep -q -- '--input_path' "$ws/help.txt"
if "$bin_dir/msp_convert_masks" --input_path a --no_such_option 1 2> "$ws/err.txt"; then exit 1; fi
grep -q "^ERROR: unknown option \`--no_such_option\`" "$ws/err.txt"
if "$bin_dir/msp_convert_masks" --input_path a 2> "$ws/err.txt"; then exit 1; fi
grep -q "^ERROR: missing required option --output_path" "$ws/err.txt"
# msp_bench_patch_match takes bare words (width height num_views [ncc]) and
# checks them before running.
"$bin_dir/msp_bench_patch_match" --help > "$ws/help.txt"
grep -q -- '--width arg (=640)' "$ws/help.txt"
for args in "64x 48 3" "0 48 3" "-64 48 3" "64 48 1" "64 48 3 fast" "64 48 3 ncc extra"; do
  # shellcheck disable=SC2086
  if "$bin_dir/msp_bench_patch_match" $args > /dev/null 2> "$ws/err.txt"; then exit 1; fi
  grep -q '^ERROR: ' "$ws/err.txt"
done
echo "cli smoke test passed"
