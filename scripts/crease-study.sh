#!/usr/bin/env bash
# Where the half-resolution grid loses: DEFAULT's error against the error of
# the same march at full resolution, pixel by pixel, on every benchmark scene
# (standard view, the scene's radius, 320x180). For each scene it renders
# DEFAULT in one frame and converged (the mean over 64 frame indices, what a
# TAA host sees), the full-resolution march converged and in one frame with 8,
# 16 and 32 directions, the G-buffer's normals, and the ray-traced reference
# and depth-only limit (256 rays, 256 directions); scripts/crease_study.py
# then measures where the grid's extra error lies (the pixels where the
# surface turns, and the worst 1%) and what DEFAULT would read with those
# pixels marched at full resolution. Writes OUT/crease_study.csv (default
# docs/bench/crease_study). Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=docs/bench/crease_study
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out=$2; shift 2 ;;
    *) echo "crease-study: unknown argument '$1' (--out DIR)" >&2; exit 2 ;;
  esac
done
. scripts/bench-scenes.sh
study_folders "$out"
scenes=$bench_scenes
runs="half:
half_converged:--accumulate 64 --frame-index 1
full_converged:--resolution full --accumulate 64 --frame-index 1
full_8:--resolution full
full_16:--resolution full --samples 16
full_32:--resolution full --samples 32"
for sc in $scenes; do
  name=$(basename "$sc" | sed 's/\..*//')
  d="$work/$name"
  mkdir -p "$d"
  build/reference/ssao-reference "$sc" --width 320 --height 180 --samples 256 --limit --limit-directions 256 \
    --quiet --out "$d/ref" >/dev/null
  build/host/ssao-host "$sc" --width 320 --height 180 --no-sheet --out "$d/gbuffer" >/dev/null
  while IFS=: read -r run flags; do
    # shellcheck disable=SC2086
    build/host/ssao-host "$sc" --width 320 --height 180 --only ao --no-sheet $flags --out "$d/$run" >/dev/null
  done <<< "$runs"
  echo "$name rendered" >&2
done
/usr/bin/python3 scripts/crease_study.py "$work" > "$out/crease_study.csv"
echo "wrote $out/crease_study.csv"
