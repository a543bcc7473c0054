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
# The figures of the ground truth written as maps and fused, read from the
# JSON: the maps must come back exact (every pixel valid and within 1 %,
# median error 0), every fused point must lie on the ground truth (accuracy
# 1), and completeness is what COLMAP's fusion of perfect maps reaches.
# Measured (seed 3, 320x240, 6 cameras): 19,724 points; at 0.5 % of the
# extent completeness 0.82 (0.96 over samples seen by >= 3 views), F1 0.90
# (0.98); at 0.02 m, the lowest, completeness 0.70, F1 0.82 (0.91). The
# bounds sit below those by a margin for COLMAP versions; maps read or
# written wrongly, points off the surface, or a wrong F1 fall outside.
python3 - "$ws/eval.json" <<'PY'
import json
import sys

d = json.load(open(sys.argv[1]))
failures = []


def check(name, value, low, high):
    if not low <= value <= high:
        failures.append("%s = %r, expected in [%r, %r]" % (name, value, low, high))


check("num_missing_maps", d["num_missing_maps"], 0, 0)
check("number of depth maps", len(d["depth_maps"]), 6, 6)
for m in d["depth_maps"] + [d["average"]]:
    for part in ("all", "textureless", "textured", "near_edge"):
        f = m[part]
        where = "%s %s " % (m["name"], part)
        check(where + "num_gt", f["num_gt"], 1, m["width"] * m["height"] or 10**9)
        for key in ("valid_fraction", "complete_1", "accurate_1", "complete_abs_1", "accurate_abs_1"):
            check(where + key, f[key], 0.999, 1.0)
        check(where + "median_rel_error", f["median_rel_error"], 0.0, 1e-6)
    check(m["name"] + " depth where the ground truth is empty", m["empty"]["with_depth_fraction"], 0.0, 0.0)
fused = d["fused"]
check("fused num_points", fused["num_points"], 5000, 80000)
check("fused num_judged", fused["num_judged"], 0.99 * fused["num_points"], fused["num_points"])
for t in fused["thresholds"]:
    where = "fused at %g m " % t["metres"]
    a, c = t["accuracy"], t["completeness"]
    check(where + "accuracy", a, 0.99, 1.0)
    check(where + "completeness", c, 0.6, 1.0)
    check(where + "completeness_multi", t["completeness_multi"], max(c, 0.75), 1.0)
    check(where + "f1", t["f1"], 2 * a * c / (a + c) - 1e-4, 2 * a * c / (a + c) + 1e-4)
    check(where + "f1_multi", t["f1_multi"], 0.85, 1.0)
check("fused off_textureless num_judged", fused["off_textureless"]["num_judged"], 1, fused["num_judged"])
for a in fused["off_textureless"]["accuracy"]:
    check("fused off_textureless accuracy", a, 0.99, 1.0)
if failures:
    sys.exit("msp_evaluate's figures of the fused ground truth:\n  " + "\n  ".join(failures))
PY
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
