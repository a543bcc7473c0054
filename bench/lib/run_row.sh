# shellcheck shell=bash
# The part of an ablation run every row shares, sourced by bench/table3.sh and
# bench/textureless_ablation.sh: msp_stereo on a fresh copy of a workspace
# with ground truth (the bundled scene), COLMAP's geometric fusion, then
# msp_evaluate --json. Binaries from $MSP_BIN (default build/bin), COLMAP from
# $COLMAP (default /usr/bin/colmap).

# ablation_init WORKSPACE: sets `workspace` (absolute; never written to),
# `bin`, `colmap` and `scratch`, a temporary folder removed on exit.
ablation_init() {
  local root
  root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
  [ -d "$1/ground_truth" ] || { echo "$1: no ground_truth/ (a workspace of msp_make_scene?)" >&2; exit 1; }
  workspace=$(cd "$1" && pwd)
  bin="${MSP_BIN:-$root/build/bin}"
  colmap="${COLMAP:-/usr/bin/colmap}"
  scratch=$(mktemp -d)
  trap 'rm -rf "$scratch"' EXIT
}

# unknown_options OPTION...: the option names (--Section.name) among the
# arguments that $bin/msp_stereo does not accept (--help_all: the advanced ones
# too), one a line; so that a table stops before its first run rather than
# after an hour.
unknown_options() {
  local known
  known=$("$bin/msp_stereo" --help_all | grep -oE '^  --[A-Za-z_.]+' | sed 's/^ *//')
  local arg
  for arg in "$@"; do
    case "$arg" in
      --*) grep -qxF -- "$arg" <<< "$known" || echo "$arg" ;;
    esac
  done
}

# require_known_options OPTION...: ends the script naming the options
# msp_stereo does not accept.
require_known_options() {
  local unknown
  unknown=$(unknown_options "$@")
  if [ -n "$unknown" ]; then
    echo "$bin/msp_stereo does not know: $(paste -sd ' ' <<< "$unknown")" >&2
    exit 1
  fi
}

# run_logged LOG COMMAND...: runs COMMAND with its output in LOG; when it fails,
# names it with its exit code and the tail of LOG, and ends the script.
run_logged() {
  local log=$1 rc=0
  shift
  "$@" > "$log" 2>&1 || rc=$?
  if [ "$rc" -ne 0 ]; then
    {
      echo "FAILED (exit $rc): $*"
      echo "--- last lines of its output:"
      tail -n 30 "$log"
    } >&2
    exit 1
  fi
}

# run_row [msp_stereo option...]: one run on a fresh copy of the workspace.
# Leaves the figures in $scratch/eval.json and "<wall s> <user CPU-s>" of
# msp_stereo in $scratch/time.
run_row() {
  local ws="$scratch/ws"
  rm -rf "$ws"
  cp -r "$workspace" "$ws"
  rm -rf "$ws/stereo/depth_maps" "$ws/stereo/normal_maps" "$ws/stereo/msp" "$ws/fused.ply"
  mkdir -p "$ws/stereo/depth_maps" "$ws/stereo/normal_maps"
  run_logged "$scratch/stereo.log" /usr/bin/time -f "%e %U" -o "$scratch/time" \
    "$bin/msp_stereo" --workspace_path "$ws" "$@"
  run_logged "$scratch/fusion.log" "$colmap" stereo_fusion --workspace_path "$ws" \
    --input_type geometric --output_path "$ws/fused.ply"
  run_logged "$scratch/evaluate.log" "$bin/msp_evaluate" --workspace "$ws" \
    --fused "$ws/fused.ply" --json "$scratch/eval.json"
}

# link_real_workspace SRC OUT: OUT (recreated) as a workspace that runs on
# the COLMAP dense workspace SRC without writing to it: images symlinked,
# sparse/ and the .cfg files copied.
link_real_workspace() {
  rm -rf "$2"
  mkdir -p "$2/stereo"
  ln -s "$1/images" "$2/images"
  cp -r "$1/sparse" "$2/"
  cp "$1/stereo/patch-match.cfg" "$1/stereo/fusion.cfg" "$2/stereo/"
}
