#!/usr/bin/env bash
# This project against a CPU patch-match peer (e.g. OpenMVS DensifyPointCloud)
# on the real sets and the bundled scene, one after the other on the same
# machine: per set, msp_stereo then `colmap stereo_fusion --input_type
# geometric` on a fresh copy of the workspace, then the peer's command on
# another fresh copy; wall time, user+sys CPU time and peak resident memory
# (/usr/bin/time) of each, the fused points and a coverage figure, in one
# Markdown table with the ratio of our wall time to the peer's. Rows are
# printed as each run ends.
#
#   bench/peer_bench.sh [--sets a,b,...] [--threads N] [--peer_cmd 'CMD'] [--keep DIR]
#                       [--data DIR] [--bundled_options 'msp_make_scene options']
#                       [msp_stereo options...]
#
# Sets (--sets, comma-separated, in this order; default all):
#   bundled       a fresh `msp_make_scene` workspace (640x480, 10 views, or as
#                 --bundled_options says); fused F1 at 0.5 % against its exact
#                 ground truth (msp_evaluate; the copies are made without it)
#   temple        DATA/templeSparseRing, 640x480; points, and occupied 2-mm
#                 voxels inside its published box (+5 mm)
#   herzjesu768   DATA/herzjesu-P8 at --PatchMatchStereo.max_image_size 768
#   herzjesu1536  DATA/herzjesu-P8 at its full 1536x1024
#   fountain768   DATA/fountain-P11 at --PatchMatchStereo.max_image_size 768
#   fountain1536  DATA/fountain-P11 at its full 1536x1024
#                 (these four: points and occupied 1-cm voxels of the whole cloud)
# DATA is --data (default ../shared/data beside the project). The data sets
# are not modified: images are symlinked, sparse/ and the .cfg files copied.
#
# --threads N (default 2): --PatchMatchStereo.num_threads of msp_stereo,
# --StereoFusion.num_threads of the fusion and {threads} of the peer.
# --peer_cmd 'CMD': a shell command (bash -c, run in the copy's folder) with
# the placeholders {workspace} (the copy: images/, sparse/, stereo/*.cfg),
# {threads}, {max_image_size} (0 when the set runs at its full size) and
# {output_ply}, where it must write its fused cloud (any PLY with x, y, z).
# Values are substituted shell-quoted: write {workspace}, not "{workspace}".
# E.g. with OpenMVS (its converter to its scene format first):
#   --peer_cmd 'InterfaceCOLMAP -i {workspace} -o {workspace}/scene.mvs &&
#     DensifyPointCloud {workspace}/scene.mvs --max-threads {threads} &&
#     cp {workspace}/scene_dense.ply {output_ply}'
# (names as in OpenMVS 2.x, check yours; for the 768 sets add its option
# for the largest image size with {max_image_size}).
# Without it our rows are printed and the peer's left empty.
# --keep DIR keeps every workspace, cloud and log in DIR/<set>/{ours,peer}
# (DIR/scene: the generated bundled scene); otherwise a temporary folder
# removed on exit. msp_stereo options after the arguments go to our runs
# alone (e.g. --PatchMatchStereo.max_image_size 320 for a quick look at the
# full-size sets). Binaries from $MSP_BIN (default build/bin), COLMAP from
# $COLMAP (default /usr/bin/colmap). Run it on an otherwise idle machine.
set -euo pipefail
# shellcheck source=bench/lib/run_row.sh
source "$(dirname "$0")/lib/run_row.sh"
root="$(cd "$(dirname "$0")/.." && pwd)"
bin="${MSP_BIN:-$root/build/bin}"
colmap="${COLMAP:-/usr/bin/colmap}"
python=/usr/bin/python3

usage() { sed -n '2,48p' "$0" | sed 's/^# \{0,1\}//' >&2; exit 1; }
die() { echo "peer_bench.sh: $*" >&2; exit 1; }

all_sets="bundled,temple,herzjesu768,herzjesu1536,fountain768,fountain1536"
selected=$all_sets threads=2 peer_cmd="" keep="" bundled_options=""
data="$root/../shared/data"
while [ $# -gt 0 ]; do
  case "$1" in
    --sets|--threads|--peer_cmd|--keep|--data|--bundled_options)
      [ $# -ge 2 ] || die "$1 needs a value"
      case "$1" in
        --sets) selected=$2 ;;
        --threads) threads=$2 ;;
        --peer_cmd) peer_cmd=$2 ;;
        --keep) keep=$2 ;;
        --data) data=$2 ;;
        --bundled_options) bundled_options=$2 ;;
      esac
      shift 2 ;;
    -h|--help) usage ;;
    --*) break ;;
    *) echo "peer_bench.sh: unexpected argument \`$1\`" >&2; usage ;;
  esac
done
extra=("$@")

# set_plan SET: `folder` (under DATA; "" = the generated scene), `set_max`
# (the set's own max_image_size, 0 = none) and `metric` (f1, box or voxel).
set_plan() {
  case "$1" in
    bundled) folder="" set_max=0 metric=f1 ;;
    temple) folder=templeSparseRing set_max=0 metric=box ;;
    herzjesu768) folder=herzjesu-P8 set_max=768 metric=voxel ;;
    herzjesu1536) folder=herzjesu-P8 set_max=0 metric=voxel ;;
    fountain768) folder=fountain-P11 set_max=768 metric=voxel ;;
    fountain1536) folder=fountain-P11 set_max=0 metric=voxel ;;
    *) return 1 ;;
  esac
}
temple_box=(-0.073568 0.021728 -0.012445 0.028855 0.181892 0.062736)
box_voxel=0.002 cloud_voxel=0.01

# Everything is checked before the first run.
case "$threads" in ''|*[!0-9]*|0) die "--threads needs a positive integer, not \`$threads\`" ;; esac
sets=()
for s in ${selected//,/ }; do
  set_plan "$s" || die "unknown set \`$s\` (known: $all_sets)"
  sets+=("$s")
done
[ ${#sets[@]} -gt 0 ] || die "--sets names no set (known: $all_sets)"
for tool in msp_stereo msp_evaluate msp_make_scene; do
  [ -x "$bin/$tool" ] || die "no $tool in $bin (build first, or set MSP_BIN)"
done
[ -x "$colmap" ] || die "no COLMAP at $colmap (set COLMAP)"
if [ -n "$peer_cmd" ]; then
  case "$peer_cmd" in
    *"{output_ply}"*) ;;
    *) die "--peer_cmd must write its cloud to {output_ply}, which it does not name" ;;
  esac
fi
for s in "${sets[@]}"; do
  set_plan "$s"
  [ -z "$folder" ] && continue
  [ -d "$data/$folder" ] || die "set $s: no data folder $data/$folder (--data DIR)"
  for f in images sparse stereo/patch-match.cfg stereo/fusion.cfg; do
    [ -e "$data/$folder/$f" ] || die "set $s: $data/$folder has no $f (not a COLMAP dense workspace)"
  done
done
data=$(cd "$data" 2>/dev/null && pwd || echo "$data")
require_known_options ${extra[@]+"${extra[@]}"}
# The value of --PatchMatchStereo.max_image_size among the extra options, ""
# without one; the options the script sets itself are refused.
extra_max=""
for ((i = 0; i < ${#extra[@]}; ++i)); do
  case "${extra[i]}" in
    --PatchMatchStereo.num_threads|--PatchMatchStereo.num_threads=*) die "give the threads with --threads" ;;
    --workspace_path|--workspace_path=*) die "the script gives --workspace_path itself" ;;
    --PatchMatchStereo.max_image_size=*) extra_max=${extra[i]#*=} ;;
    --PatchMatchStereo.max_image_size) extra_max=${extra[i + 1]:-} ;;
  esac
done
if [ -n "$extra_max" ]; then
  [[ "$extra_max" =~ ^(-1|[0-9]+)$ ]] || die "--PatchMatchStereo.max_image_size needs a number, not \`$extra_max\`"
  for s in "${sets[@]}"; do
    set_plan "$s"
    [ "$set_max" -eq 0 ] || die "set $s has its own max_image_size ($set_max); leave out --PatchMatchStereo.max_image_size or the set"
  done
fi

if [ -n "$keep" ]; then
  mkdir -p "$keep"
  top=$(cd "$keep" && pwd)
else
  top=$(mktemp -d)
  trap 'rm -rf "$top"' EXIT
fi

# image_size WS MAX: "WxH" of WS's first image after COLMAP's downsizing to
# MAX (0 = none).
image_size() {
  "$python" - "$1/images" "$2" <<'PY'
import os, sys
import cv2
folder, limit = sys.argv[1], int(sys.argv[2])
name = sorted(os.listdir(folder))[0]
h, w = cv2.imread(os.path.join(folder, name), cv2.IMREAD_UNCHANGED).shape[:2]
if 0 < limit < max(w, h):
    scale = min(limit / w, limit / h)
    w, h = round(w * scale), round(h * scale)
print("%dx%d" % (w, h))
PY
}

# time_of FILE: "<wall s> <CPU s> <peak KiB>" from /usr/bin/time -f '%e %U %S %M'.
time_of() { awk 'NF == 4 { printf "%s %.2f %d\n", $1, $2 + $3, $4 }' "$1" | tail -n 1; }

# timed NAME COMMAND...: COMMAND with its output in $dir/NAME.log and its
# figures in $dir/NAME.time; a failure ends the script (run_logged).
timed() {
  local name=$1
  shift
  run_logged "$dir/$name.log" /usr/bin/time -f '%e %U %S %M' -o "$dir/$name.time" "$@"
}

# cloud PLY: "<points>|<coverage>" of the set being run ($metric): F1 at
# 0.5 % (msp_evaluate, F1 over the surface >= 3 views see, as pair_run.sh and
# BENCHMARKS.md report it), or the occupied voxels (ply_stats.py); for the
# temple the points cell adds the share inside the box. Run in $(...): a
# failure exits that subshell, whose status the caller's assignment takes.
cloud() {
  local ply=$1 stats
  case "$metric" in
    f1)
      run_logged "$dir/evaluate.log" "$bin/msp_evaluate" --workspace "$scene" --no_maps \
        --fused "$ply" --json "$dir/evaluate.json"
      "$python" - "$dir/evaluate.json" <<'PY'
import json, sys
f = json.load(open(sys.argv[1]))["fused"]
t = [t for t in f["thresholds"] if not t["absolute"] and abs(t["fraction"] - 0.005) < 1e-9][0]
print("%d|%.2f" % (f["num_points"], 100 * t["f1_multi"]))
PY
      ;;
    box)
      stats=$("$python" "$root/bench/ply_stats.py" "$ply" --bbox "${temple_box[@]}" --voxel "$box_voxel") \
        || exit 1
      local points inside voxels
      points=$(sed -n 's/^fused points: \([0-9]*\).*/\1/p' <<< "$stats")
      inside=$(sed -n 's/^inside bbox[^=]*= \([0-9.]*\) %.*/\1/p' <<< "$stats")
      voxels=$(sed -n 's/^occupied voxels inside bbox[^:]*: \([0-9]*\).*/\1/p' <<< "$stats")
      echo "$points (${inside:-0} % in box)|${voxels:-0}" ;;
    voxel)
      stats=$("$python" "$root/bench/ply_stats.py" "$ply" --voxel "$cloud_voxel") || exit 1
      local points voxels
      points=$(sed -n 's/^fused points: \([0-9]*\).*/\1/p' <<< "$stats")
      voxels=$(sed -n 's/^occupied voxels ([^:]*: \([0-9]*\).*/\1/p' <<< "$stats")
      echo "$points|${voxels:-0}" ;;
  esac
}

# fresh_copy OUT: a fresh copy of the set's workspace in OUT (the generated
# scene without its ground truth, or a real set linked as real_data.sh does).
fresh_copy() {
  if [ -z "$folder" ]; then
    rm -rf "$1"
    cp -r "$scene" "$1"
    rm -rf "$1/ground_truth" "$1/stereo/depth_maps" "$1/stereo/normal_maps" "$1/fused.ply"
    mkdir -p "$1/stereo/depth_maps" "$1/stereo/normal_maps"
  else
    link_real_workspace "$data/$folder" "$1"
    chmod -R u+w "$1/sparse" "$1/stereo"  # copied from a read-only data set: removable
  fi
}

# row CELLS...: one table row.
row() {
  local cell
  for cell in "$@"; do printf '| %s ' "$cell"; done
  printf '|\n'
}

if [ -z "$peer_cmd" ]; then
  echo "no peer command given (--peer_cmd): peer columns empty"
fi
scene=""
case ",${sets[*]// /,}," in
  *,bundled,*)
    scene="$top/scene"
    read -r -a make_options <<< "$bundled_options"
    echo "generating the bundled scene in $scene${bundled_options:+ ($bundled_options)}" >&2
    rm -rf "$scene"
    run_logged "$top/make_scene.log" "$bin/msp_make_scene" --output "$scene" \
      ${make_options[@]+"${make_options[@]}"} ;;
esac

echo "machine: $(nproc) cores, load average at the start $(cut -d' ' -f1-3 /proc/loadavg)"
echo "msp_stereo options: --PatchMatchStereo.num_threads $threads${extra[*]:+ ${extra[*]}}"
[ -z "$peer_cmd" ] || echo "peer command: $peer_cmd"
echo
echo "| set | size | tool | wall s | CPU s | peak MiB | points | voxels or F1 0.5 % | our wall / peer's |"
echo "|---|---|---|---|---|---|---|---|---|"
for s in "${sets[@]}"; do
  set_plan "$s"
  dir="$top/$s"
  rm -rf "$dir"
  mkdir -p "$dir"
  max=$set_max
  if [ -n "$extra_max" ] && [ "$extra_max" -gt 0 ]; then max=$extra_max; fi
  source_ws=${folder:+$data/$folder}
  size=$(image_size "${source_ws:-$scene}" "$max")
  [ "$(image_size "${source_ws:-$scene}" 0)" != "$size" ] || max=0
  own=()
  [ "$set_max" -eq 0 ] || own=(--PatchMatchStereo.max_image_size "$set_max")

  echo "$s ($size): msp_stereo and stereo_fusion" >&2
  fresh_copy "$dir/ours"
  timed stereo "$bin/msp_stereo" --workspace_path "$dir/ours" --PatchMatchStereo.num_threads "$threads" \
    ${own[@]+"${own[@]}"} ${extra[@]+"${extra[@]}"}
  timed fusion "$colmap" stereo_fusion --workspace_path "$dir/ours" --input_type geometric \
    --output_path "$dir/ours/fused.ply" --StereoFusion.num_threads "$threads"
  read -r sw sc sk <<< "$(time_of "$dir/stereo.time")"
  read -r fw fc fk <<< "$(time_of "$dir/fusion.time")"
  figures=$(cloud "$dir/ours/fused.ply")
  IFS='|' read -r points coverage <<< "$figures"
  tw=$(awk -v a="$sw" -v b="$fw" 'BEGIN { printf "%.2f", a + b }')
  tc=$(awk -v a="$sc" -v b="$fc" 'BEGIN { printf "%.2f", a + b }')
  tk=$((sk > fk ? sk : fk))

  row "$s" "$size" "msp_stereo" "$sw" "$sc" "$((sk / 1024))" "" "" ""
  row "$s" "$size" "colmap stereo_fusion" "$fw" "$fc" "$((fk / 1024))" "" "" ""
  row "$s" "$size" "ours (both)" "$tw" "$tc" "$((tk / 1024))" "$points" "$coverage" ""
  if [ -z "$peer_cmd" ]; then
    row "$s" "$size" "peer" "" "" "" "" "" ""
  else
    echo "$s ($size): the peer" >&2
    fresh_copy "$dir/peer"
    out_ply="$dir/peer/fused.ply"
    cmd=$peer_cmd
    cmd=${cmd//"{workspace}"/$(printf '%q' "$dir/peer")}
    cmd=${cmd//"{threads}"/$threads}
    cmd=${cmd//"{max_image_size}"/$max}
    cmd=${cmd//"{output_ply}"/$(printf '%q' "$out_ply")}
    echo "$cmd" > "$dir/peer.cmd"
    (cd "$dir/peer" && timed peer bash -c "$cmd")
    [ -s "$out_ply" ] || die "set $s: the peer command wrote no cloud at $out_ply (command: $cmd; log: $dir/peer.log)"
    read -r pw pc pk <<< "$(time_of "$dir/peer.time")"
    figures=$(cloud "$out_ply")
    IFS='|' read -r ppoints pcoverage <<< "$figures"
    ratio=$(awk -v a="$tw" -v b="$pw" 'BEGIN { if (b > 0) printf "%.2f", a / b; else print "-" }')
    row "$s" "$size" "peer" "$pw" "$pc" "$((pk / 1024))" "$ppoints" "$pcoverage" "$ratio"
  fi
done
echo
echo "wall s and CPU s (user + sys) from /usr/bin/time; peak MiB = the largest resident set of a"
echo "process (ours (both): the larger of the two runs; peer: its largest process). The last"
echo "column, on the peer's row: our total wall time over the peer's (below 1: we are faster). Coverage:"
for s in "${sets[@]}"; do
  set_plan "$s"
  case "$metric" in
    f1) echo "- $s: fused F1 at 0.5 % of the scene's extent against its exact ground truth (over the surface >= 3 views see, msp_evaluate)" ;;
    box) echo "- $s: occupied ${box_voxel} m voxels inside the box ${temple_box[*]} (+5 mm)" ;;
    voxel) echo "- $s: occupied ${cloud_voxel} m voxels of the whole cloud" ;;
  esac
done
echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg)"
[ -z "$keep" ] || echo "workspaces, clouds and logs kept in $top"
