#!/bin/sh
# A full disk, a read-only stereo/ and a source image removed during a run:
# a clear error naming the file, a non-zero exit, the finished maps kept
# (byte-identical to an uninterrupted run's); after the full disk, a run that
# resumes to the same maps as an uninterrupted run.
#
# A full disk is simulated with the file size limit (RLIMIT_FSIZE, `ulimit -f`,
# set in bytes with util-linux's prlimit): a small tmpfs
# or loop device needs root and mounts, and this limit makes write(2) fail as
# a full disk does (EFBIG instead of ENOSPC), on the same code path, for any user.
# Read-only is chmod; as root (containers) with the capabilities that bypass
# file modes dropped (setpriv), so that the modes hold.
# Usage: io_errors_test.sh <bin_dir>
set -eu
. "$(dirname "$0")/common.sh"

reference "$TMP/ref"
lost=img_001.png

# A workspace where every image but $lost has its final maps.
unfinished() {
  rm -rf "$1"
  cp -a "$TMP/ref" "$1"
  rm "$1"/stereo/depth_maps/$lost.* "$1"/stereo/normal_maps/$lost.*
}

# expect_error WS PATTERN: the last run failed with one ERROR line matching
# PATTERN, said how many images are done, and kept the finished maps.
expect_error() {
  grep -q "^ERROR: $2" "$1.err" || { cat "$1.err"; fail "no error '$2'"; }
  grep -q "^2 of 3 reference images have their final maps" "$1.log" || fail "no count of done images"
  check_partial "$1" "$TMP/ref"
  for f in $(map_files "$TMP/ref"); do
    case "$f" in
      */$lost.*) ;;
      *) [ -f "$1/stereo/$f" ] || fail "$f was lost" ;;
    esac
  done
}

# Full disk: the depth map (48 KiB) fits under the limit, the normal map (144 KiB) does not.
ws="$TMP/full"
unfinished "$ws"
code=0
command -v prlimit > /dev/null || fail "prlimit (util-linux) is needed"
# shellcheck disable=SC2086
prlimit --fsize=100000 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS \
  > "$ws.log" 2> "$ws.err" || code=$?
[ "$code" -eq 1 ] || fail "disk full: exit code $code"
expect_error "$ws" "cannot write $ws/stereo/normal_maps/$lost.photometric.bin: File too large"
[ -z "$(find "$ws/stereo" -name '*.tmp-*')" ] || fail "disk full: temporary file left"
stereo "$ws" || fail "disk full: the run after space came back"
check_complete "$ws" "$TMP/ref"

# Read-only stereo/.
as_user() { "$@"; }
if [ "$(id -u)" -eq 0 ]; then
  command -v setpriv > /dev/null || fail "setpriv (util-linux) is needed to test file modes as root"
  as_user() { setpriv --bounding-set=-dac_override,-dac_read_search,-fowner "$@"; }
fi
ws="$TMP/readonly"
unfinished "$ws"
chmod -R a-w "$ws/stereo"
code=0
# shellcheck disable=SC2086
as_user sh -c 'ws=$1; shift; "$0" --workspace_path "$ws" "$@" > "$ws.log" 2> "$ws.err"' \
  "$BIN/msp_stereo" "$ws" $STEREO_OPTIONS || code=$?
[ "$code" -eq 1 ] || fail "read-only: exit code $code"
expect_error "$ws" "cannot write $ws/stereo/depth_maps/$lost.photometric.bin: Permission denied"

# A source image removed during a run: images are read at the start, so that
# run finishes with the same maps; the next run that needs it names it.
ws="$TMP/vanished"
cp -a "$TMP/ref.base" "$ws"
stereo_bg "$ws"
wait_for_line "$ws.log" "^Round "
mv "$ws/images/img_002.png" "$TMP/img_002.png"
wait "$pid" || { cat "$ws.err"; fail "vanished image: the run that had read it"; }
check_complete "$ws" "$TMP/ref"
rm "$ws"/stereo/depth_maps/$lost.* "$ws"/stereo/normal_maps/$lost.*
code=0
stereo "$ws" || code=$?
[ "$code" -eq 1 ] || fail "vanished image: exit code $code"
grep -q "^ERROR: .*$ws/images/img_002.png" "$ws.err" || { cat "$ws.err"; fail "vanished image: message"; }
check_partial "$ws" "$TMP/ref"
echo "I/O error test passed"
