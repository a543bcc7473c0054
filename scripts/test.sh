#!/usr/bin/env bash
# Installs what the tests need, builds, and runs every test (unit and
# integration, including COLMAP's stereo_fusion on the bundled scene).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install_deps.sh
scripts/build.sh
ctest --test-dir build --output-on-failure -j2
