#!/usr/bin/env bash
# Builds the libFuzzer targets of the file readers (fuzz/) with clang into
# ./build-fuzz and runs each for SECONDS (default 30) from its seed corpus in
# fuzz/corpus/<target>, as many at a time as there are cores (MSP_FUZZ_JOBS).
# Fails when a target finds a crash, hang (an input taking over 10 s), leak,
# or allocation over 512 MB; the input is left in build-fuzz/artifacts/ (turn
# it into a unit test in tests/io/reader_hardening_test.cc).
#
#   scripts/fuzz.sh [SECONDS]          build and fuzz every target
#   scripts/fuzz.sh --seeds WORKSPACE  rewrite fuzz/corpus from a workspace of msp_make_scene
#
# MSP_FUZZ_BUILD_DIR overrides the build folder. New inputs found go to
# build-fuzz/corpus/<target>, never into the committed seeds.
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD="${MSP_FUZZ_BUILD_DIR:-build-fuzz}"
TARGETS=(sparse_model_binary_fuzzer sparse_model_text_fuzzer dense_map_fuzzer
         patch_match_config_fuzzer project_ini_fuzzer mask_layer_fuzzer workspace_image_fuzzer
         rgbd_capture_fuzzer)

mkdir -p "$BUILD"
CC=clang CXX=clang++ cmake -S . -B "$BUILD" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCUDA_ENABLED=OFF -DMSP_PYTHON=OFF -DMSP_BUILD_TESTS=OFF -DMSP_FUZZ=ON > "$BUILD/configure.log" 2>&1 ||
  { cat "$BUILD/configure.log"; exit 1; }
cmake --build "$BUILD" --target msp_fuzzers

if [ "${1:-}" = "--seeds" ]; then
  [ $# -eq 2 ] || { echo "usage: scripts/fuzz.sh --seeds WORKSPACE" >&2; exit 2; }
  rm -rf fuzz/corpus
  "$BUILD/fuzz/msp_fuzz_seeds" --workspace "$2" --output fuzz/corpus
  exit 0
fi

SECONDS_EACH="${1:-30}"
case "$SECONDS_EACH" in
  '' | *[!0-9]*) echo "usage: scripts/fuzz.sh [SECONDS]" >&2; exit 2 ;;
esac

mkdir -p "$BUILD/artifacts"
# The targets write each input to a file (the readers take paths): in a RAM
# folder when there is one, so the disk is not the bottleneck.
if [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi

# One target: its log in $BUILD/<target>.log, and $BUILD/<target>.failed when
# it found something. -malloc_limit_mb: the readers check sizes against the
# file before they allocate, so no input of a few kB may ask for more.
fuzz_target() {
  local target=$1
  mkdir -p "$BUILD/corpus/$target"
  rm -f "$BUILD/$target.failed"
  "$BUILD/fuzz/$target" -max_total_time="$SECONDS_EACH" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=512 -max_len=16384 \
    -artifact_prefix="$BUILD/artifacts/$target-" -print_final_stats=1 \
    "$BUILD/corpus/$target" "fuzz/corpus/$target" > "$BUILD/$target.log" 2>&1 ||
    touch "$BUILD/$target.failed"
}

# MSP_FUZZ_JOBS targets at a time (default: one per core).
JOBS="${MSP_FUZZ_JOBS:-$(nproc)}"
running=0
for target in "${TARGETS[@]}"; do
  [ -d "fuzz/corpus/$target" ] || { echo "ERROR: no seed corpus fuzz/corpus/$target" >&2; exit 1; }
  echo "== $target: ${SECONDS_EACH} s"
  fuzz_target "$target" &
  running=$((running + 1))
  if [ "$running" -ge "$JOBS" ]; then
    wait -n
    running=$((running - 1))
  fi
done
wait

failed=0
for target in "${TARGETS[@]}"; do
  if [ -e "$BUILD/$target.failed" ]; then
    tail -n 60 "$BUILD/$target.log"
    echo "ERROR: $target failed; the input is in $BUILD/artifacts/" >&2
    failed=1
  else
    echo "$target: $(grep -E 'stat::(number_of_executed_units|peak_rss_mb)' "$BUILD/$target.log" |
      tr -s ' ' | tr '\n' ' ')"
  fi
done
[ "$failed" -eq 0 ] || exit 1
echo "fuzz: ${#TARGETS[@]} targets, ${SECONDS_EACH} s each, no failure"
