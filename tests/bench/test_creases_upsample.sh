#!/usr/bin/env bash
# The upsample on the creases scene: the relief's grooves (0.04 wide, one and
# a half grid blocks at 320x180) are dark and the ridge tops beside them open,
# a few percent apart in view z. DEFAULT (half resolution) against V_R must
# reach 24.5 dB there: measured 25.5 dB with the upsample that weighs taps by
# the depth their tangent planes put under the pixel, 22.9 dB with one that
# compared view z alone (the grooves took the ridges' AO in bright stripes).
#   test_creases_upsample.sh SSAO_HOST SSAO_REFERENCE SSAO_ERROR PLUGIN SCENE
set -eu
host=$1 reference=$2 error=$3 plugin=$4 scene=$5
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$reference" "$scene" --width 320 --height 180 --samples 128 --quiet --out "$tmp/ref" > /dev/null
"$host" "$scene" --plugin "$plugin" --width 320 --height 180 --only ao --no-sheet --out "$tmp/ao" > /dev/null
psnr=$("$error" "$tmp/ao/ao.exr" "$tmp/ref" | awk '$1 == "all" { print $4 }')
echo "creases, DEFAULT against V_R: $psnr dB (at least 24.5)"
awk -v p="$psnr" 'BEGIN { exit !(p >= 24.5) }' || { echo "FAIL: below 24.5 dB"; exit 1; }
