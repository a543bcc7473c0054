#!/usr/bin/env bash
# Installs what the tests need, builds, and runs every test (unit and
# integration, including COLMAP's stereo_fusion on the bundled scene and the
# Debian package), then fuzzes each file reader for MSP_FUZZ_SECONDS (default
# 20) seconds (scripts/fuzz.sh; 0 skips it).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j2
if [ "${MSP_FUZZ_SECONDS:-20}" != 0 ]; then
  scripts/fuzz.sh "${MSP_FUZZ_SECONDS:-20}"
fi
