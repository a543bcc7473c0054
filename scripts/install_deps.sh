#!/usr/bin/env bash
# Installs the Debian 12 packages msp-stereo builds, tests and demos with.
# Idempotent: apt is only called when a package is missing.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config   # toolchain
  libeigen3-dev libopencv-dev libboost-program-options-dev  # libraries
  libopencv-contrib-dev                          # ximgproc: a graph segmenter of the prior
  libsqlite3-dev                                 # msp_import_rgbd reads COLMAP's database
  libgtest-dev libgmock-dev                      # tests
  clang libclang-rt-14-dev                       # libFuzzer targets of the readers (scripts/fuzz.sh)
  dpkg-dev                                       # cpack -G DEB: dpkg-shlibdeps finds the runtime libraries
  colmap                                         # stereo_fusion for demos and tests (no CUDA needed)
  python3-numpy python3-opencv                   # bench/ply_stats.py, the Python module's tests
  pybind11-dev python3-dev                       # the Python module (python/)
  time                                           # peak memory of a run (tests/integration/memory, bench/)
)

missing=()
for package in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ "${#missing[@]}" -eq 0 ]; then
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; fi
echo "Installing: ${missing[*]}"
$SUDO apt-get update
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y "${missing[@]}"
