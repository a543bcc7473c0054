#!/bin/sh
# Command-line behaviour of the msp_stereo executable: help, option errors,
# a missing workspace and a back-end that cannot run give the documented exit
# codes and one-line errors, and leave nothing behind.
# Usage: msp_stereo_cli_test.sh <msp_stereo> <colmap dispatcher next to it> <msp_make_scene>
set -u
[ $# -eq 3 ] || { echo "usage: $0 <msp_stereo> <colmap dispatcher> <msp_make_scene>" >&2; exit 2; }
MSP=$1
DISPATCHER=$2
MAKE_SCENE=$3
readonly LIMIT=30
. "$(dirname "$0")/../support/checks.sh"
# run ARGS...: sets rc, out (stdout) and err (stderr).
run() {
  timeout "$LIMIT" "$@" >"$TMP/out" 2>"$TMP/err"
  rc=$?
  out=$(cat "$TMP/out")
  err=$(cat "$TMP/err")
}
# A failure is exit code 1 and exactly one "ERROR: " line on stderr.
expect_error() {
  expect_eq "$1: exit code" "$rc" 1
  expect_eq "$1: one stderr line" "$(printf '%s\n' "$err" | wc -l)" 1
  expect_contains "$1: message" "$err" "ERROR: $2"
}

run "$MSP" --help
expect_eq "--help exit code" "$rc" 0
expect_contains "--help lists COLMAP options" "$out" "--PatchMatchStereo.window_radius arg (=5)"
expect_contains "--help lists MspStereo options" "$out" "--MspStereo.backend arg (=auto)"
run "$MSP" -h
expect_eq "-h exit code" "$rc" 0
case "$out" in
  *"--MspStereo.advanced_crf_alpha arg"*) fail "--help leaves the advanced options to --help_all" ;;
  *) pass "--help leaves the advanced options to --help_all" ;;
esac
expect_contains "--help points at --help_all" "$out" "--help_all lists"
run "$MSP" --help_all
expect_eq "--help_all exit code" "$rc" 0
expect_contains "--help_all lists the advanced options" "$out" "--MspStereo.advanced_crf_alpha arg (=0.02)"
expect_contains "--help_all lists the ignored COLMAP options" "$out" "--PatchMatchStereo.num_iterations arg (=5)"

run "$MSP" --workspace_path "$TMP" --bogus_option 1
expect_error "unknown option" "unknown option \`--bogus_option\`"
run "$MSP"
expect_error "no arguments" "missing required option --workspace_path"
run "$MSP" --workspace_path "$TMP" --PatchMatchStereo.window_step 3
expect_error "out-of-range value" "invalid value 3 for --PatchMatchStereo.window_step"
run "$MSP" --workspace_path "$TMP" --MspStereo.seed 3
expect_error "renamed option" "option --MspStereo.seed was renamed --random_seed"
run "$MSP" --workspace_path "$TMP" --MspStereo.crf_alpha 0.1
expect_error "renamed option" "option --MspStereo.crf_alpha was renamed --MspStereo.advanced_crf_alpha"
run "$MSP" --workspace_path "$TMP" --PatchMatchStereo.num_samples many
expect_contains "malformed value names the option" "$err" "PatchMatchStereo.num_samples"
expect_eq "malformed value: exit code" "$rc" 1

missing="$TMP/no such workspace"
run "$MSP" --workspace_path "$missing"
expect_eq "missing workspace: exit code" "$rc" 1
expect_contains "missing workspace: names the path" "$err" "ERROR: "
expect_contains "missing workspace: names the path" "$err" "$missing"
expect_eq "missing workspace: one stderr line" "$(printf '%s\n' "$err" | wc -l)" 1
[ ! -e "$missing" ] && pass "missing workspace is not created" || fail "missing workspace is not created"
# The options in force are printed at start-up, one `--name value` line each.
expect_contains "start-up print: quoted path" "$out" "--workspace_path '$missing'"
expect_contains "start-up print: a default" "$out" "--PatchMatchStereo.window_radius 5"
expect_contains "start-up print: an own option" "$out" "--MspStereo.backend auto"

# A cuda back-end that cannot run (no CUDA in this build, no device, or, on a
# machine with GPUs, a device that does not exist): msp_stereo reads the
# workspace, then stops before writing anything (not even the
# stereo/fusion.cfg it writes when missing).
ws="$TMP/scene"
if "$MAKE_SCENE" --output "$ws" --width 64 --height 64 --num_cameras 3 >"$TMP/scene.log" 2>&1; then
  rm "$ws/stereo/fusion.cfg"
  before=$(ls -R "$ws")
  run "$MSP" --workspace_path "$ws" --MspStereo.backend cuda --PatchMatchStereo.gpu_index 99
  expect_error "cuda back-end" "--"
  expect_contains "cuda back-end: says why" "$err" "CUDA"
  expect_contains "cuda back-end: the workspace is read first" "$out" "Reading workspace"
  [ ! -e "$ws/stereo/fusion.cfg" ] && pass "cuda back-end: no fusion.cfg written" ||
    fail "cuda back-end: no fusion.cfg written"
  expect_eq "cuda back-end: the workspace is unchanged" "$(ls -R "$ws")" "$before"
else
  fail "msp_make_scene writes a workspace"; cat "$TMP/scene.log"
fi

# The same binary through the dispatcher next to it.
run env PATH=/usr/bin:/bin "$DISPATCHER" msp_stereo --help
expect_eq "colmap msp_stereo --help exit code" "$rc" 0
expect_contains "colmap msp_stereo --help reaches msp_stereo" "$out" "--MspStereo.backend"
run env PATH=/usr/bin:/bin "$DISPATCHER" msp_stereo --workspace_path "$missing"
expect_eq "colmap msp_stereo on a missing workspace: exit code" "$rc" 1

finish
