#!/usr/bin/env bash
# The CUDA back-end's proof on a machine with an NVIDIA GPU, run unchanged:
#   1. builds with the GPU's own architecture (nvidia-smi's compute_cap),
#   2. runs the gpu tests (ctest -L gpu: CPU/GPU parity per kernel family and
#      on the bundled scene at 320x240); a skipped test is a failure here,
#   3. runs the bundled scene at 640x480 on both back-ends (same seed) and
#      prints the CUDA run's start-up self-check (src/backend/device_self_check.h),
#      per-image time, peak device memory (the run's buffers, and
#      nvidia-smi's peak of the whole process) and the fused F1 of both
#      (colmap stereo_fusion + msp_evaluate).
# Any unexpected result stops it with "gpu_check: FAILED: ..." and exit 1.
# Without a GPU (no nvidia-smi, or it lists none) it prints why and exits 2
# without building anything.
#
# Usage: bench/gpu_check.sh [build_dir] [out_dir]
#   (defaults build-gpu and out/gpu_check; REAL_COLMAP overrides /usr/bin/colmap)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build-gpu}
out=${2:-out/gpu_check}
colmap_bin=${REAL_COLMAP:-/usr/bin/colmap}

fail() { echo "gpu_check: FAILED: $*" >&2; exit 1; }
step() { echo; echo "== $* ($(date -u +%H:%M:%S))"; }

if ! command -v nvidia-smi >/dev/null 2>&1; then
  echo "gpu_check: no NVIDIA GPU here (nvidia-smi not found); nothing checked" >&2
  exit 2
fi
caps=$(nvidia-smi --query-gpu=compute_cap --format=csv,noheader 2>/dev/null || true)
if [ -z "$caps" ]; then
  echo "gpu_check: no NVIDIA GPU here (nvidia-smi lists none); nothing checked" >&2
  exit 2
fi
arch=$(printf '%s\n' "$caps" | head -n 1 | tr -d ' .')
case "$arch" in
  '' | *[!0-9]*) fail "cannot read the compute capability from nvidia-smi: '$caps'" ;;
esac
nvidia-smi --query-gpu=index,name,compute_cap,memory.total,driver_version --format=csv
command -v nvcc >/dev/null 2>&1 || [ -x /usr/local/cuda/bin/nvcc ] || fail "nvcc not found"
[ -x "$colmap_bin" ] || fail "$colmap_bin not found (set REAL_COLMAP)"
command -v python3 >/dev/null 2>&1 || fail "python3 not found (reads msp_evaluate's JSON)"

step "build for sm_$arch in $build"
mkdir -p "$(dirname "$out")"
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCUDA_ENABLED=ON \
  -DCMAKE_CUDA_ARCHITECTURES="$arch" >"$out.cmake.log" 2>&1 || fail "configure (see $out.cmake.log)"
grep -q "CUDA back-end enabled" "$out.cmake.log" || fail "CMake did not enable the CUDA back-end (see $out.cmake.log)"
cmake --build "$build" || fail "build"
bin="$build/bin"

step "gpu tests"
ctest --test-dir "$build" -L gpu --output-on-failure | tee "$out.ctest.log" ||
  fail "ctest -L gpu"
grep -q "tests passed" "$out.ctest.log" || fail "ctest -L gpu ran no test"
grep -q "Skipped" "$out.ctest.log" &&
  fail "a gpu test skipped on a machine with a GPU (see $out.ctest.log)"

step "bundled scene at 640x480 on both back-ends"
rm -rf "$out"
mkdir -p "$out"
"$bin/msp_make_scene" --output "$out/scene" >"$out/make_scene.log" 2>&1 || fail "msp_make_scene"
for backend in cpu cuda; do
  ws="$out/$backend"
  cp -r "$out/scene" "$ws"
  smi_log="$out/$backend.smi.csv"
  nvidia-smi --query-gpu=memory.used --format=csv,noheader,nounits -lms 200 >"$smi_log" &
  smi=$!
  start=$(date +%s.%N)
  "$bin/msp_stereo" --workspace_path "$ws" --MspStereo.backend "$backend" --random_seed 0 \
    >"$out/$backend.log" 2>&1 || { kill "$smi"; fail "msp_stereo --MspStereo.backend $backend (see $out/$backend.log)"; }
  end=$(date +%s.%N)
  kill "$smi"; wait "$smi" 2>/dev/null || true
  grep -q "^Back-end: $backend " "$out/$backend.log" || fail "$backend run did not use the $backend back-end"
  if [ "$backend" = cuda ]; then
    # The start-up self-check passed (else the run stopped): its figures.
    grep "^Self-check of GPU" "$out/$backend.log" || fail "the cuda run printed no self-check"
  fi
  num_images=$(ls "$ws/stereo/depth_maps/"*.geometric.bin | wc -l)
  [ "$num_images" -gt 0 ] || fail "$backend run wrote no geometric depth map"
  "$colmap_bin" stereo_fusion --workspace_path "$ws" --input_type geometric \
    --output_path "$ws/fused.ply" >"$out/$backend.fusion.log" 2>&1 || fail "stereo_fusion ($backend)"
  "$bin/msp_evaluate" --workspace "$ws" --fused "$ws/fused.ply" --json "$ws/evaluation.json" \
    >"$out/$backend.eval.log" 2>&1 || fail "msp_evaluate ($backend)"
  f1=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1]));
print(" ".join("%.1f%%@%g" % (100*t["f1"], t["fraction"]) for t in d["fused"]["thresholds"] if not t["absolute"]))' \
    "$ws/evaluation.json") || fail "no fused F1 in $ws/evaluation.json"
  per_image=$(python3 -c 'import sys; print("%.2f" % ((float(sys.argv[2]) - float(sys.argv[1])) / int(sys.argv[3])))' \
    "$start" "$end" "$num_images")
  smi_peak=$(sort -n "$smi_log" | tail -n 1)
  buffers=$(grep "peak device memory" "$out/$backend.log" | sed 's/^/    /' || true)
  echo "$backend: $num_images images, ${per_image} s per image, nvidia-smi peak ${smi_peak:-?} MiB used on the GPU, fused F1 $f1"
  [ -n "$buffers" ] && echo "$buffers"
  if [ "$backend" = cuda ] && [ -z "$buffers" ]; then fail "the cuda run printed no peak device memory"; fi
  echo "$f1" >"$out/$backend.f1"
done

step "fused F1 of both back-ends"
python3 - "$out/cpu/evaluation.json" "$out/cuda/evaluation.json" <<'PY' || fail "the back-ends' fused F1 differ by more than 2 points"
import json, sys
cpu, gpu = ([t for t in json.load(open(p))["fused"]["thresholds"] if not t["absolute"]]
            for p in sys.argv[1:3])
worst = 0.0
for a, b in zip(cpu, gpu):
    d = abs(a["f1"] - b["f1"]) * 100
    worst = max(worst, d)
    print("  at %g of the extent: cpu %.2f%%, cuda %.2f%% (difference %.2f points)" %
          (a["fraction"], 100 * a["f1"], 100 * b["f1"], d))
sys.exit(0 if worst <= 2.0 else 1)
PY
echo
echo "gpu_check: OK"
