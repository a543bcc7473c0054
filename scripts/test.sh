#!/usr/bin/env bash
# Installs what the tests need, builds, and runs every test (unit and
# integration, including COLMAP's stereo_fusion on the bundled scene and the
# Debian package), then checks the scalar core (the CUDA kernels' arithmetic)
# against the AVX2 core on the CPU (tests/scalar_vs_vector.sh: a second
# build of msp_stereo alone into ./build-scalar, about two minutes), then
# fuzzes each file reader for MSP_FUZZ_SECONDS (default 20) seconds
# (scripts/fuzz.sh; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j2
tests/scalar_vs_vector.sh build build-scalar
if [ "${MSP_FUZZ_SECONDS:-20}" != 0 ]; then
  scripts/fuzz.sh "${MSP_FUZZ_SECONDS:-20}"
fi
