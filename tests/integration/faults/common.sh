# Shared by the fault tests: a small generated workspace, runs of the real
# msp_stereo on it and byte-wise comparisons of the maps with an
# uninterrupted run. Sourced by a test whose first argument is the build's
# bin/; sets BIN and a scratch folder TMP, removed at exit (made writable
# first: a test may leave parts read-only).
# Every run: nice, one thread (the machines running CI are shared).

BIN=$1
TMP=$(mktemp -d)
trap 'chmod -R u+w "$TMP"; rm -rf "$TMP"' EXIT

# One coarse-to-fine round of 3 images: 12 image-passes of a fraction of a second.
SCENE_OPTIONS="--width 128 --height 96 --num_cameras 3 --seed 5"
STEREO_OPTIONS="--PatchMatchStereo.num_threads 1 --random_seed 7 --MspStereo.advanced_coarsest_image_size 128"

fail() {
  echo "FAIL: $*" >&2
  exit 1
}

now_ms() { date +%s%3N; }

# make_scene DIR: a fresh workspace without maps.
make_scene() {
  # shellcheck disable=SC2086
  "$BIN/msp_make_scene" --output "$1" $SCENE_OPTIONS > "$1.scene.log" 2>&1 ||
    { cat "$1.scene.log"; fail "msp_make_scene"; }
}

# stereo WS [options...]: msp_stereo in the foreground, log in WS.log,
# errors in WS.err; returns its exit code.
stereo() {
  ws=$1
  shift
  # shellcheck disable=SC2086
  nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS "$@" > "$ws.log" 2> "$ws.err"
}

# stereo_bg WS: msp_stereo in the background; its pid in $pid.
stereo_bg() {
  ws=$1
  shift
  # The log of an earlier run on $ws goes first: the background job truncates
  # it only once it starts, and wait_for_line would read the old one.
  rm -f "$ws.log" "$ws.err"
  # shellcheck disable=SC2086
  nice -n 15 "$BIN/msp_stereo" --workspace_path "$ws" $STEREO_OPTIONS "$@" > "$ws.log" 2> "$ws.err" &
  pid=$!
}

# wait_for_line FILE PATTERN: waits (up to 120 s) until FILE has a line matching PATTERN.
wait_for_line() {
  i=0
  until grep -q "$2" "$1" 2> /dev/null; do
    i=$((i + 1))
    [ "$i" -le 1200 ] || fail "no line '$2' in $1 after 120 s"
    sleep 0.1
  done
}

# The map files of a workspace, relative to its stereo/ folder, sorted.
map_files() {
  (cd "$1/stereo" && find depth_maps normal_maps -type f | LC_ALL=C sort)
}

# check_partial WS REF: every map file of WS is byte-identical to REF's;
# anything else in the map folders is an atomic write's temporary name.
check_partial() {
  for f in $(map_files "$1"); do
    case "$f" in
      *.bin) cmp -s "$1/stereo/$f" "$2/stereo/$f" || fail "$1/stereo/$f differs from the uninterrupted run's" ;;
      *.bin.tmp-[0-9]*) ;;
      *) fail "unexpected file $1/stereo/$f" ;;
    esac
  done
}

# check_complete WS REF: the same map files as REF, byte-identical, and no
# temporary or spilled file anywhere under stereo/.
check_complete() {
  [ "$(map_files "$1")" = "$(map_files "$2")" ] ||
    fail "$1 has other map files than $2: $(map_files "$1" | tr '\n' ' ')"
  check_partial "$1" "$2"
  leftover=$(find "$1/stereo" -name '*.tmp-*' -o -name 'state-*.bin')
  [ -z "$leftover" ] || fail "files left in $1/stereo: $leftover"
}

# reference DIR: a workspace DIR.base without maps, and DIR with the maps of an
# uninterrupted run; the run's wall time in ms in $ref_ms.
reference() {
  make_scene "$1.base"
  cp -a "$1.base" "$1"
  t0=$(now_ms)
  stereo "$1" || { cat "$1.err"; fail "the uninterrupted run"; }
  ref_ms=$(($(now_ms) - t0))
  [ -n "$(map_files "$1")" ] || fail "the uninterrupted run wrote no maps"
}
