#!/usr/bin/env bash
# Interface 1.2 added seven features, each off by default. This pins what a
# frame with all of them off looks like: ssao-host's ao.exr for each case in
# cases.txt must hold, bit for bit, the committed image (Mesa 22.3 llvmpipe on
# this project's machine). They were the 1.1 library's output (commit
# d421df5) until these deliberate changes (the cases each changed):
#  1. a preset's thickness follows the scene's radius (ultra-corner,
#     high-reverse-z-teapot);
#  2. the default pass below full resolution reads view z and upsamples 2x2
#     (every half-resolution case);
#  3. the visibility thickness defaults to radius x (0.5 + 1.5 / steps)
#     (every visibility case);
#  4. the upsample weighs taps by the depth their tangent planes put under
#     the pixel (every half-resolution case);
#  5. the depth-aware blur weighs taps by the depth the centre's tangent
#     plane puts under them (ultra-*, kernel-depth-aware-corner,
#     ortho-d16-gaussian-spot);
#  6. HIGH and ULTRA were re-picked (high-reverse-z-teapot, ultra-*);
#  7. the depth-aware blur fits a line through its taps instead of taking
#     their mean (high-reverse-z-teapot, ultra-*, kernel-depth-aware-corner,
#     ortho-d16-gaussian-spot);
#  8. the upsample reads a pixel's view z through the inverse projection's z
#     and w rows (default-corner: a few pixels move by one or two 8-bit steps);
#  9. LOW, HIGH and ULTRA were re-picked by the rule (low-teapot,
#     high-reverse-z-teapot, ultra-*);
# 10. the visibility method's default rotation is gradient noise at full
#     resolution too (high-reverse-z-teapot, ultra-*);
# 11. the gradient noise's step jitter is the noise with x and y swapped, no
#     longer a shifted copy tied to the angle (default-*, low-teapot,
#     high-reverse-z-teapot, ultra-*, world-rgba8-teapot).
# 12. the visibility march's crossing test: a step beyond the thickness
#     still blocks where the previous point lay in front of its texel's
#     tangent plane (default-corner, ultra-corner).
# 13. the full-resolution depth-aware blur reads each tap's own tangent plane
#     under the centre too (two ways: ultra-*, high-reverse-z-teapot,
#     kernel-depth-aware-corner).
# 14. the visibility march's steps stretch with the jitter so that the last
#     reaches the radius at the jitter's top (every visibility case).
# The chapter cases are still 1.1's. On a renderer other than llvmpipe the
# check is skipped (exit 77) and make refuses. The header's other
# attributes (ssao-host records the scene and camera there) are not part of
# the frame: SAME (exr_same_image) compares the image only.
#   run.sh check HOST SAME  compare HOST's output with the committed files
#   run.sh make HOST        (re)write them with HOST, after a deliberate change of the frame
set -euo pipefail
mode=$1 host=$2 same=${3:-}
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../../.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failed=0
while IFS='|' read -r name scene flags; do
  name=$(echo "$name" | xargs)
  [ -z "$name" ] || [ "${name:0:1}" = "#" ] && continue
  scene=$(echo "$scene" | xargs)
  # shellcheck disable=SC2086
  "$host" "$root/$scene" --width 64 --height 48 --only ao --out "$work/$name" $flags > "$work/$name.log" 2>&1 || {
    echo "golden-1.1: $name: ssao-host failed:"; cat "$work/$name.log"; exit 1; }
  # The files are llvmpipe's frames bit for bit: another renderer's rounding
  # differs (an NVIDIA GPU's division, for one), so there is nothing to compare.
  if ! grep -q "^  render: .* on llvmpipe " "$work/$name.log"; then
    echo "golden-1.1: skipped: the files are llvmpipe's output; this renderer: $(grep -m1 '^  render: ' "$work/$name.log")"
    [ "$mode" = make ] && exit 1 || exit 77
  fi
  if [ "$mode" = make ]; then
    cp "$work/$name/ao.exr" "$here/$name.exr"
  elif "$same" "$work/$name/ao.exr" "$here/$name.exr"; then
    echo "golden-1.1: $name: identical"
  else
    echo "golden-1.1: $name: DIFFERS from the 1.1 output"
    failed=1
  fi
done < "$here/cases.txt"
exit $failed
