#!/usr/bin/env bash
# Where DEFAULT's error comes from: its march on the half-resolution grid,
# taken apart on every benchmark scene (standard view, the scene's radius,
# 320x180). Each configuration changes one thing against DEFAULT (8
# directions x 4 steps, half resolution, the 2x2 upsample):
#   converged    the mean over 64 frame indices (rotation and jitter move
#                with it): DEFAULT without its noise, what a TAA host sees
#   full         the same march at full resolution (no grid, no upsample)
#   32 steps     8 x 32 at half resolution, then at full resolution
# PSNR and bias against V_R and against the depth-only limit (256 rays, 256
# directions), through ssao-error. Writes OUT/grid_study.csv (default
# docs/bench/grid_study). --plugin PATH measures another build of the plugin
# (the patches beside the committed runs). Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/bench/grid_study
plugin=()
while [ $# -gt 0 ]; do
  case "$1" in
    --plugin) plugin=(--plugin "$2"); shift 2 ;;
    --out) out=$2; shift 2 ;;
    *) echo "grid-study: unknown argument '$1' (--plugin PATH, --out DIR)" >&2; exit 2 ;;
  esac
done
. scripts/bench-scenes.sh
study_folders "$out"
scenes=$bench_scenes
configs="DEFAULT:
DEFAULT converged:--accumulate 64 --frame-index 1
full resolution converged:--resolution full --accumulate 64 --frame-index 1
32 steps converged:--steps 32 --accumulate 32 --frame-index 1
32 steps full resolution converged:--steps 32 --resolution full --accumulate 32 --frame-index 1"
echo "scene,config,psnr_vs_vr,bias_vs_vr,psnr_vs_limit,bias_vs_limit" > "$work/grid_study.csv"
for sc in $scenes; do
  name=$(basename "$sc" | sed 's/\..*//')
  build/reference/ssao-reference "$sc" --width 320 --height 180 --samples 256 --limit --limit-directions 256 \
    --quiet --out "$work/ref" >/dev/null
  while IFS=: read -r cfg flags; do
    # shellcheck disable=SC2086
    build/host/ssao-host "$sc" --width 320 --height 180 --only ao --no-sheet "${plugin[@]}" $flags \
      --out "$work/host" >/dev/null
    rm -f "$work/err.csv"
    build/reference/ssao-error "$work/host/ao.exr" "$work/ref" --csv "$work/err.csv" --label x >/dev/null
    awk -F, -v s="$name" -v c="$cfg" '
      $2 == "all" && $12 == "V_R"   { vr = $6; bvr = $7 }
      $2 == "all" && $12 == "limit" { lim = $6; blim = $7 }
      END { printf "%s,%s,%.2f,%+.4f,%.2f,%+.4f\n", s, c, vr, bvr, lim, blim }' "$work/err.csv" \
      >> "$work/grid_study.csv"
  done <<< "$configs"
  echo "$name done" >&2
done
cp "$work/grid_study.csv" "$out/grid_study.csv"
echo "wrote $out/grid_study.csv"
