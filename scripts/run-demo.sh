#!/usr/bin/env bash
# The main job: sets up a fresh Debian machine, builds, and renders the bundled
# scene with and without ambient occlusion into ./out.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/host/ssao-host "$@"
