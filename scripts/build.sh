#!/usr/bin/env bash
# Configures and builds into ./build (Release, warnings as errors on our code).
set -euo pipefail
cd "$(dirname "$0")/.."
. scripts/ccache-env.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "${ssao_cmake_launcher[@]}" >/dev/null
cmake --build build -j"$(nproc)"
