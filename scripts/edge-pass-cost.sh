#!/usr/bin/env bash
# What a pass that marches only the pixels where the surface turns would cost
# on llvmpipe (docs/benchmark.md, "Where the grid loses"). DISCARD_PLUGIN is a
# build with docs/bench/experiments/patches/edge_pixels_only.patch (the
# visibility pass discards every other pixel), MASK_PLUGIN one with
# edge_pixels_depth_masked.patch (the grid's sky mask also rejects them, so a
# pass that tests it skips the 4x4 blocks without one). On each benchmark
# scene (standard view, 320x180) it times, with the build tree's plugin:
# DEFAULT, and the full-resolution march of 8 and 16 directions; with
# DISCARD_PLUGIN: the same two marches over the edge pixels only; with
# MASK_PLUGIN: the 16 directions with the depth-aware blur (so that the march
# writes an intermediate, which the plan tests against the mask). Process CPU
# time per frame (LP_NUM_THREADS=1: the difference between runs of 20 and 220
# frames), configurations in turn over three rounds, and the host's GPU timers
# of the grid and visibility passes in the last frame. Writes
# OUT/edge_pass_cost.csv (default docs/bench/crease_study).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: scripts/edge-pass-cost.sh DISCARD_PLUGIN MASK_PLUGIN [--out DIR]" >&2; exit 2; }
for p in "$1" "$2"; do [ -f "$p" ] || { echo "edge-pass-cost: no plugin at '$p'" >&2; exit 2; }; done
edge=$(realpath "$1") mask=$(realpath "$2"); shift 2
out=docs/bench/crease_study
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$(realpath -m "$2"); shift 2 ;;
    *) echo "edge-pass-cost: unknown argument '$1' (--out DIR)" >&2; exit 2 ;;
  esac
done
cd "$(dirname "$0")/.."
export LP_NUM_THREADS=1
. scripts/bench-scenes.sh
study_folders "$out"
scenes=$bench_scenes
configs="DEFAULT:build/plugin/libssao.so:
every pixel, 8 directions:build/plugin/libssao.so:--resolution full --samples 8
every pixel, 16 directions:build/plugin/libssao.so:--resolution full --samples 16
edge pixels, 8 directions:$edge:--resolution full --samples 8
edge pixels, 16 directions:$edge:--resolution full --samples 16
edge pixels by the mask, 16 directions:$mask:--resolution full --samples 16 --blur depth-aware"
# CPU seconds (user + system) of one ssao-host run.
cpu() { /usr/bin/time -f "%U %S" -o "$work/t" "$@" > "$work/log" 2>&1; awk '{print $1 + $2}' "$work/t"; }
echo "scene,config,round,cpu_ms,grid_gpu_ms,visibility_gpu_ms" > "$out/edge_pass_cost.csv"
for round in 1 2 3; do
  for sc in $scenes; do
    name=$(basename "$sc" | sed 's/\..*//')
    while IFS=: read -r cfg plugin flags; do
      # shellcheck disable=SC2206
      run=(build/host/ssao-host "$sc" --width 320 --height 180 --only ao --no-sheet --plugin "$plugin" $flags
           --out "$work/host")
      a=$(cpu "${run[@]}" --frames 20)
      b=$(cpu "${run[@]}" --frames 220)
      grid=$(sed -n 's/.*grid \([0-9.]*\) ms.*/\1/p' "$work/log")
      vis=$(sed -n 's/.*visibility \([0-9.]*\) ms.*/\1/p' "$work/log")
      echo "$name,\"$cfg\",$round,$(awk -v a="$a" -v b="$b" 'BEGIN { printf "%.3f", (b - a) * 1000 / 200 }'),$grid,$vis" \
        >> "$out/edge_pass_cost.csv"
    done <<< "$configs"
  done
  echo "round $round done" >&2
done
echo "wrote $out/edge_pass_cost.csv"
