#!/usr/bin/env bash
# The thickness rule of the visibility estimator, measured: T = 0.5 to 1.5
# x R for the march at 4, 8, 16 and 32 steps (8 directions, half
# resolution, as DEFAULT) and for ULTRA's (full resolution, depth-aware
# blur), on every benchmark scene (standard view, 320x180) at 0.5, 1 and 2 x
# its radius: PSNR and bias against V_R (256 rays). The rule the plugin
# derives (settings.h default_thickness) is read off it. Writes
# OUT/thickness.csv (default docs/bench). Needs a build (scripts/build.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-docs/bench}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
. scripts/bench-scenes.sh
scenes=$bench_scenes
configs="8x4-half:--steps 4
8x8-half:--steps 8
8x16-half:--steps 16
8x32-half:--steps 32
ultra:--preset ultra"
echo "scene,radius_scale,config,steps,thickness_of_r,psnr,bias" > "$work/thickness.csv"
for sc in $scenes; do
  name=$(basename "$sc" | sed 's/\..*//')
  # The scene's radius as every tool picks it (ssao-host's ssao: line).
  R=$(build/host/ssao-host "$sc" --width 32 --height 18 --only ao --no-sheet --out "$work/probe" |
      grep -o "radius [0-9.e-]*" | head -1 | awk '{print $2}')
  for k in 0.5 1 2; do
    r=$(awk -v a="$R" -v b="$k" 'BEGIN { print a * b }')
    build/reference/ssao-reference "$sc" --width 320 --height 180 --samples 256 --radius "$r" --quiet \
      --out "$work/ref" >/dev/null
    while IFS=: read -r cfg flags; do
      # The configuration's step count as the plugin resolves it (ssao-host's ssao: line).
      # shellcheck disable=SC2086
      steps=$(build/host/ssao-host "$sc" --width 32 --height 18 --only ao --no-sheet $flags --out "$work/probe" |
              grep -o "x [0-9]* steps" | head -1 | awk '{print $2}')
      for tr in 0.5 0.625 0.75 0.875 1 1.5; do
        t=$(awk -v a="$r" -v b="$tr" 'BEGIN { print a * b }')
        # shellcheck disable=SC2086
        build/host/ssao-host "$sc" --width 320 --height 180 --only ao --no-sheet --radius "$r" --thickness "$t" \
          $flags --frames 1 --out "$work/host" >/dev/null
        build/reference/ssao-error "$work/host/ao.exr" "$work/ref" --allow-mismatch |
          awk -v s="$name" -v k="$k" -v c="$cfg" -v n="$steps" -v tr="$tr" \
            '$1 == "all" { print s "," k "," c "," n "," tr "," $4 "," $5 }' >> "$work/thickness.csv"
      done
    done <<< "$configs"
  done
done
mkdir -p "$out"
cp "$work/thickness.csv" "$out/thickness.csv"
awk -F, 'NR > 1 { k = $3 " T = " $5 " R"; n[k]++; p[k] += $6 }
         END { for (k in n) printf "%s: mean PSNR %.2f dB over %d cases\n", k, p[k] / n[k], n[k] }' \
  "$out/thickness.csv" | sort
