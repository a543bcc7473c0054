#!/bin/sh
# Tests of the `colmap` dispatcher with a fake real colmap and a fake
# msp_stereo: routing, argument/stdin/exit-code pass-through, help, and
# discovery via REAL_COLMAP / MSP_STEREO / PATH / COLMAP_EXE_PATH.
# Usage: dispatcher_test.sh <path to the dispatcher script>
set -u
[ $# -eq 1 ] || { echo "usage: $0 <dispatcher>" >&2; exit 2; }
SOURCE=$1
unset REAL_COLMAP MSP_STEREO MSP_REPLACE_PATCH_MATCH COLMAP_EXE_PATH
# Every call is bounded so a dispatch loop fails the test instead of hanging.
readonly LIMIT=10

. "$(dirname "$0")/../support/checks.sh"

mkdir -p "$TMP/real" "$TMP/exe" "$TMP/copy" "$TMP/link" "$TMP/bare"
NL='
'

# The fake real colmap: "REAL", then one argument per line; `cat_stdin`
# echoes stdin; help prints a COLMAP-like command list; exits $FAKE_RC.
cat > "$TMP/real/colmap" <<'FAKE'
#!/bin/sh
echo REAL
for arg in "$@"; do printf '%s\n' "$arg"; done
case "${1-}" in
  cat_stdin) cat ;;
  ''|help|-h|--help) printf 'Available commands:\n  help\n  model_transformer\n  patch_match_stereo\n  stereo_fusion\n' ;;
esac
exit "${FAKE_RC:-0}"
FAKE
# The fake msp_stereo: "MSP", then one argument per line; exits $FAKE_RC.
cat > "$TMP/fake_msp_stereo" <<'FAKE'
#!/bin/sh
echo MSP
for arg in "$@"; do printf '%s\n' "$arg"; done
exit "${FAKE_RC:-0}"
FAKE
chmod +x "$TMP/real/colmap" "$TMP/fake_msp_stereo"
cp "$SOURCE" "$TMP/exe/colmap"
cp "$SOURCE" "$TMP/copy/colmap"
cp "$SOURCE" "$TMP/bare/colmap"
chmod +x "$TMP/exe/colmap" "$TMP/copy/colmap" "$TMP/bare/colmap"
cp "$TMP/fake_msp_stereo" "$TMP/exe/msp_stereo"
ln -s "$TMP/exe/colmap" "$TMP/link/colmap"
D="$TMP/exe/colmap"
BASE_PATH=/usr/bin:/bin

# run VAR=VALUE... -- ARGS: runs with a clean PATH plus the given variables.
run() {
  env PATH="$BASE_PATH" REAL_COLMAP="$TMP/real/colmap" MSP_STEREO="$TMP/fake_msp_stereo" \
    timeout "$LIMIT" "$@"
}

# --- pass-through to the real colmap ---------------------------------------
out=$(run "$D" feature_extractor --image_path "a b" "" 'q"uote' '$HOME' '*')
expect_eq "arguments pass through unchanged" "$out" \
  "REAL${NL}feature_extractor${NL}--image_path${NL}a b${NL}${NL}q\"uote${NL}\$HOME${NL}*"
run env FAKE_RC=3 "$D" stereo_fusion >/dev/null
expect_eq "exit code of the real colmap" "$?" 3
run env FAKE_RC=0 "$D" stereo_fusion >/dev/null
expect_eq "exit code 0 of the real colmap" "$?" 0
out=$(printf 'line one\nline two\n' | run "$D" cat_stdin)
expect_eq "stdin reaches the real colmap" "$out" "REAL${NL}cat_stdin${NL}line one${NL}line two"

# --- msp_stereo -------------------------------------------------------------
out=$(run "$D" msp_stereo --workspace_path "my ws" --PatchMatchStereo.geom_consistency true)
expect_eq "msp_stereo routed with arguments" "$out" \
  "MSP${NL}--workspace_path${NL}my ws${NL}--PatchMatchStereo.geom_consistency${NL}true"
run env FAKE_RC=5 "$D" msp_stereo >/dev/null
expect_eq "exit code of msp_stereo" "$?" 5

# --- patch_match_stereo -----------------------------------------------------
out=$(run "$D" patch_match_stereo --workspace_path ws)
expect_eq "patch_match_stereo goes to the real colmap by default" "$out" \
  "REAL${NL}patch_match_stereo${NL}--workspace_path${NL}ws"
out=$(run env MSP_REPLACE_PATCH_MATCH=0 "$D" patch_match_stereo --workspace_path ws)
expect_eq "MSP_REPLACE_PATCH_MATCH=0 keeps the real colmap" "$out" \
  "REAL${NL}patch_match_stereo${NL}--workspace_path${NL}ws"
out=$(run env MSP_REPLACE_PATCH_MATCH=1 "$D" patch_match_stereo --workspace_path "w s")
expect_eq "MSP_REPLACE_PATCH_MATCH=1 routes patch_match_stereo" "$out" \
  "MSP${NL}--workspace_path${NL}w s"

# --- help -------------------------------------------------------------------
for args in help -h --help ''; do
  # shellcheck disable=SC2086 # '' must become no argument at all
  out=$(run "$D" $args)
  rc=$?
  expect_eq "help '$args' exit code" "$rc" 0
  expect_contains "help '$args' lists msp_stereo before patch_match_stereo" "$out" \
    "  model_transformer${NL}  msp_stereo${NL}  patch_match_stereo${NL}  stereo_fusion"
done
out=$(run env FAKE_RC=4 "$D" help)
expect_eq "help keeps the real exit code" "$?" 4

# --- discovery --------------------------------------------------------------
# Real colmap from PATH, skipping the dispatcher itself and another copy of it.
out=$(env PATH="$TMP/exe:$TMP/copy:$TMP/real:$BASE_PATH" MSP_STEREO="$TMP/fake_msp_stereo" \
  timeout "$LIMIT" colmap stereo_fusion --x 1)
expect_eq "PATH lookup skips dispatcher copies" "$out" "REAL${NL}stereo_fusion${NL}--x${NL}1"
# msp_stereo found next to the dispatcher, also when called through a symlink.
out=$(env PATH="$BASE_PATH" timeout "$LIMIT" "$TMP/exe/colmap" msp_stereo -a)
expect_eq "msp_stereo found next to the dispatcher" "$out" "MSP${NL}-a"
out=$(env PATH="$BASE_PATH" timeout "$LIMIT" "$TMP/link/colmap" msp_stereo -b)
expect_eq "msp_stereo found through a symlinked dispatcher" "$out" "MSP${NL}-b"
# msp_stereo from PATH when not next to the dispatcher.
mkdir -p "$TMP/pathbin" && cp "$TMP/fake_msp_stereo" "$TMP/pathbin/msp_stereo"
out=$(env PATH="$TMP/pathbin:$BASE_PATH" timeout "$LIMIT" "$TMP/bare/colmap" msp_stereo -c)
expect_eq "msp_stereo found on PATH" "$out" "MSP${NL}-c"

# COLMAP's run-colmap-*.sh call $COLMAP_EXE_PATH/colmap.
cat > "$TMP/run-colmap-geometric.sh" <<'SCRIPT'
$COLMAP_EXE_PATH/colmap patch_match_stereo --workspace_path . --workspace_format COLMAP \
    --PatchMatchStereo.max_image_size 2000 --PatchMatchStereo.geom_consistency true
$COLMAP_EXE_PATH/colmap stereo_fusion --workspace_path . --input_type geometric
SCRIPT
out=$(env PATH="$TMP/real:$BASE_PATH" COLMAP_EXE_PATH="$TMP/exe" MSP_REPLACE_PATCH_MATCH=1 \
  timeout "$LIMIT" sh "$TMP/run-colmap-geometric.sh")
expect_eq "run-colmap script through COLMAP_EXE_PATH" "$out" \
  "MSP${NL}--workspace_path${NL}.${NL}--workspace_format${NL}COLMAP${NL}--PatchMatchStereo.max_image_size${NL}2000${NL}--PatchMatchStereo.geom_consistency${NL}true${NL}REAL${NL}stereo_fusion${NL}--workspace_path${NL}.${NL}--input_type${NL}geometric"

# --- errors -----------------------------------------------------------------
err=$(env PATH="$BASE_PATH" REAL_COLMAP="$TMP/nonexistent" timeout "$LIMIT" "$D" mapper 2>&1)
rc=$?
[ "$rc" -ne 0 ] && pass "missing REAL_COLMAP fails" || fail "missing REAL_COLMAP fails"
expect_contains "missing REAL_COLMAP is named" "$err" "REAL_COLMAP=$TMP/nonexistent"
err=$(env PATH="$BASE_PATH" MSP_STEREO="$TMP/nonexistent" timeout "$LIMIT" "$D" msp_stereo 2>&1)
rc=$?
[ "$rc" -ne 0 ] && pass "missing MSP_STEREO fails" || fail "missing MSP_STEREO fails"
expect_contains "missing MSP_STEREO is named" "$err" "MSP_STEREO=$TMP/nonexistent"
err=$(env PATH="$BASE_PATH" timeout "$LIMIT" "$TMP/bare/colmap" msp_stereo 2>&1)
rc=$?
[ "$rc" -ne 0 ] && pass "no msp_stereo anywhere fails" || fail "no msp_stereo anywhere fails"
expect_contains "no msp_stereo anywhere is explained" "$err" "cannot find msp_stereo"
err=$(env PATH="$BASE_PATH" REAL_COLMAP="$D" timeout "$LIMIT" "$D" mapper 2>&1)
rc=$?
[ "$rc" -ne 0 ] && [ "$rc" -ne 124 ] && pass "REAL_COLMAP pointing to the dispatcher fails fast" ||
  fail "REAL_COLMAP pointing to the dispatcher fails fast"

finish
