#!/usr/bin/env bash
# The thickness rule of the visibility estimator, measured: DEFAULT with
# T = 0.5, 0.75, 1 and 1.5 x R on every benchmark scene (standard view,
# 320x180) at 0.5, 1 and 2 x its radius, PSNR and bias against V_R (256 rays).
# Writes OUT/thickness.csv (default docs/bench). Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scenes="assets/models/spot-on-ground.glb assets/models/teapot-on-ground.glb assets/scenes/corner.gltf
        assets/scenes/overhang.gltf assets/scenes/creases.gltf assets/scenes/clutter.gltf"
echo "scene,radius_scale,thickness_of_r,psnr,bias" > "$work/thickness.csv"
for sc in $scenes; do
  name=$(basename "$sc" | sed 's/\..*//')
  # The scene's radius as every tool picks it (ssao-host's ssao: line).
  R=$(build/host/ssao-host "$sc" --width 32 --height 18 --only ao --no-sheet --out "$work/probe" |
      grep -o "radius [0-9.e-]*" | head -1 | awk '{print $2}')
  for k in 0.5 1 2; do
    r=$(awk -v a="$R" -v b="$k" 'BEGIN { print a * b }')
    build/reference/ssao-reference "$sc" --width 320 --height 180 --samples 256 --radius "$r" --quiet \
      --out "$work/ref" >/dev/null
    for tr in 0.5 0.75 1 1.5; do
      t=$(awk -v a="$r" -v b="$tr" 'BEGIN { print a * b }')
      build/host/ssao-host "$sc" --width 320 --height 180 --only ao --no-sheet --radius "$r" --thickness "$t" \
        --frames 1 --out "$work/host" >/dev/null
      build/reference/ssao-error "$work/host/ao.exr" "$work/ref" --allow-mismatch |
        awk -v s="$name" -v k="$k" -v tr="$tr" '$1 == "all" { print s "," k "," tr "," $4 "," $5 }' >> "$work/thickness.csv"
    done
  done
done
mkdir -p "$out"
cp "$work/thickness.csv" "$out/thickness.csv"
awk -F, 'NR > 1 { n[$3]++; p[$3] += $4 } END { for (t in n) printf "T = %s R: mean PSNR %.2f dB over %d cases\n", t, p[t] / n[t], n[t] }' \
  "$out/thickness.csv" | sort
