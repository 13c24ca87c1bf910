#!/usr/bin/env bash
# The main job: installs what the demo needs (not the test, reference, viewer
# or sanitizer packages), builds only the plugin and ssao-host into
# ./build-demo, and renders the bundled scene with and without ambient
# occlusion into ./out. Arguments go to ssao-host (e.g. --preset ultra).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh demo
. scripts/ccache-env.sh
cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF -DSSAO_BUILD_REFERENCE=OFF \
  -DSSAO_INSTALL=OFF "${ssao_cmake_launcher[@]}" >/dev/null
cmake --build build-demo -j"$(nproc)" --target ssao ssao-host
build-demo/host/ssao-host "$@"
