#!/usr/bin/env bash
# Configures and builds msp-stereo into ./build (Release). CUDA is used when
# nvcc is found; pass -DCUDA_ENABLED=OFF to build the CPU back-end only.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build
