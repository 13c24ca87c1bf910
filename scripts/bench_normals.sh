#!/usr/bin/env bash
# Depth-only input against the G-buffer's normals: two
# quick ssao-bench runs over the same scenes, settings and references, one
# with the G-buffer's normals and one with normal_texture = 0, into
# DIR/gbuffer and DIR/depth (default docs/bench-normals); then the docs'
# bench:normals block is written from them (scripts/normals_readme.py).
# Needs a build (scripts/build.sh). Usage: scripts/bench_normals.sh [DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/bench-normals}
for normals in gbuffer depth; do
  build/bench/ssao-bench --quick --scales 1 --normals "$normals" --out "$out/$normals" > "$out.$normals.log" 2>&1 || {
    tail -n 20 "$out.$normals.log"; exit 1; }
  rm -f "$out.$normals.log"
done
/usr/bin/python3 scripts/normals_readme.py "$out"
