#!/bin/sh
# bench/peer_bench.sh on a small bundled scene (128x96, 5 views): with a
# stand-in peer (msp_stereo and colmap stereo_fusion again, on the peer's
# copy) the table has our rows and the peer's, with points and F1 parsed from
# both clouds and the wall-time ratio; without a peer the plain message and an
# empty peer row; a peer that writes no cloud, an unknown set, a peer command
# without {output_ply} and a missing data folder end non-zero with a message
# (about 20 s).
# Usage: peer_bench_test.sh <bin_dir> <colmap>
set -eu
bin_dir=$(cd "$1" && pwd)
colmap=$2
[ -x "$colmap" ] || { echo "colmap is not installed at $colmap" >&2; exit 1; }
script="$(cd "$(dirname "$0")/../.." && pwd)/bench/peer_bench.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export MSP_BIN="$bin_dir" COLMAP="$colmap"
scene="--width 128 --height 96 --num_cameras 5 --seed 2"

fail() { echo "FAIL: $*" >&2; exit 1; }

# 1. A stand-in peer: our own pipeline on its copy of the workspace.
peer="'$bin_dir/msp_stereo' --workspace_path {workspace} --PatchMatchStereo.num_threads {threads} --log_level 0"
peer="$peer && test {max_image_size} = 0"
peer="$peer && '$colmap' stereo_fusion --workspace_path {workspace} --input_type geometric --output_path {output_ply}"
bash "$script" --sets bundled --bundled_options "$scene" --keep "$tmp/keep" --peer_cmd "$peer" \
  --log_level 0 > "$tmp/out" 2> "$tmp/err" || { cat "$tmp/out" "$tmp/err"; fail "run with a peer"; }
cat "$tmp/out"
# Our total and the peer's rows: points > 0, F1 at 0.5 % in (0, 100] and the
# same method's within 10 points (COLMAP's fusion is not deterministic across
# threads); times and memory positive, the ratio on the peer's row.
python3 - "$tmp/out" <<'PY' || fail "table of the run with a peer"
import sys
rows = {}
for line in open(sys.argv[1]):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) == 9 and cells[0] == "bundled":
        rows[cells[2]] = cells
assert set(rows) == {"msp_stereo", "colmap stereo_fusion", "ours (both)", "peer"}, rows
for tool in ("ours (both)", "peer"):
    r = rows[tool]
    assert r[1] == "128x96", r
    assert float(r[3]) > 0 and float(r[4]) > 0 and int(r[5]) > 0, r
    assert int(r[6]) > 0, r
    assert 0 < float(r[7]) <= 100, r
ours, peer = rows["ours (both)"], rows["peer"]
assert abs(float(ours[7]) - float(peer[7])) < 10, (ours, peer)
assert ours[8] == "", ours
assert abs(float(peer[8]) - float(ours[3]) / float(peer[3])) < 0.02, (ours, peer)
PY
grep -q "no peer command" "$tmp/out" && fail "the peer was given"
test -f "$tmp/keep/bundled/peer/fused.ply" || fail "--keep kept no peer cloud"
test ! -e "$tmp/keep/bundled/peer/ground_truth" || fail "the peer's copy has the ground truth"

# 2. No peer: the message, our figures, an empty peer row.
bash "$script" --sets bundled --bundled_options "$scene" > "$tmp/out2" 2> "$tmp/err2" \
  || { cat "$tmp/out2" "$tmp/err2"; fail "run without a peer"; }
grep -qx "no peer command given (--peer_cmd): peer columns empty" "$tmp/out2" || fail "no message"
grep -qE '^\| bundled \| 128x96 \| ours \(both\) \| [0-9.]+ \| [0-9.]+ \| [0-9]+ \| [1-9][0-9]* \| [0-9.]+ \|' \
  "$tmp/out2" || fail "our row without a peer"
grep -qE '^\| bundled \| 128x96 \| peer \|( +\|){6}$' "$tmp/out2" || fail "empty peer row"

# expect_error MESSAGE ARGS...: the script ends non-zero naming MESSAGE.
expect_error() {
  message=$1
  shift
  if bash "$script" "$@" > "$tmp/bad.out" 2> "$tmp/bad.err"; then
    fail "exit 0 with $*"
  fi
  grep -q "$message" "$tmp/bad.err" || { cat "$tmp/bad.err"; fail "no \"$message\" for $*"; }
}
# 3. A peer that writes no cloud (after our rows), and bad arguments.
expect_error "wrote no cloud" --sets bundled --bundled_options "$scene" --peer_cmd ': {output_ply}'
grep -q '| bundled | 128x96 | ours (both) |' "$tmp/bad.out" || fail "our rows before the failed peer"
expect_error "FAILED (exit 3)" --sets bundled --bundled_options "$scene" \
  --peer_cmd 'exit 3; {output_ply}'
expect_error "unknown set .nosuch." --sets bundled,nosuch
expect_error "{output_ply}" --sets bundled --peer_cmd 'cp x.ply out.ply'
expect_error "no data folder" --sets temple --data "$tmp/nowhere"
expect_error "needs a positive integer" --threads two
echo "peer_bench_test: OK"
