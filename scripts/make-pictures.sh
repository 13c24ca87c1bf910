#!/usr/bin/env bash
# Regenerates the README's pictures from the bundled scene (spot-on-ground.glb):
#   docs/images/at_a_glance.png   lit without AO | lit with AO | our AO | ray-traced truth, one view
#   docs/images/{ao,lit_ao,lit_no_ao,modes}.png   ssao-host's pictures of that view (plugin defaults)
#   docs/images/viewer.png        ssao-viewer's window with its overlay (under xvfb-run)
# and, with --bench, the accuracy-versus-time plot docs/bench/error_vs_time.png with the
# benchmark's tables and the README's figures (scripts/run-bench.sh, then scripts/bench_readme.py:
# three scenes, about ten minutes on a CPU).
# Without --bench the committed plot is left as it is. Runs in about a minute on llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/.."

bench=0
for arg in "$@"; do
  case "$arg" in
    --bench) bench=1 ;;
    -h|--help) sed -n '2,8p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "make-pictures: unknown argument '$arg' (only --bench)" >&2; exit 2 ;;
  esac
done

scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)" --target ssao ssao-host ssao-reference ssao-error ssao-viewer

# One view for every panel: ssao-host's three-quarter view of the cow, 400 x 300.
W=400 H=300
view=(--width "$W" --height "$H" --eye 2.3,1.6,-2.6 --target 0,0.65,0)
preset=medium   # the plugin's recommended preset (SSAO_PRESET_DEFAULT)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

build/host/ssao-host "${view[@]}" --preset "$preset" --out "$work/ours" >/dev/null
build/host/ssao-host "${view[@]}" --out "$work/defaults" >/dev/null
build/reference/ssao-reference "${view[@]}" --samples 1024 --quiet --out "$work/truth" >/dev/null
rmse=$(build/reference/ssao-error "$work/ours/ao.exr" "$work/truth" | awk '$1 == "all" { printf "%.3f", $3 }')

/usr/bin/python3 scripts/picture_strip.py docs/images/at_a_glance.png \
  "lit, no AO=$work/ours/lit_no_ao.png" \
  "lit with our AO=$work/ours/lit_ao.png" \
  "our AO ($preset, RMSE $rmse)=$work/ours/ao.png" \
  "ray-traced truth=$work/truth/reference_ao.png"
for f in ao lit_ao lit_no_ao modes; do
  /usr/bin/python3 -c 'import sys; from PIL import Image; Image.open(sys.argv[1]).save(sys.argv[2], optimize=True)' \
    "$work/defaults/$f.png" "docs/images/$f.png"
done
# ssao-viewer with its overlay after key 3, the HIGH preset (its GPU times vary from run to run).
printf '0 3\n12 F12\n' >"$work/viewer.txt"
xvfb-run -a -s "-screen 0 640x480x24" build/host/ssao-viewer --width 480 --height 360 \
  --script "$work/viewer.txt" --frames 13 --screenshot-dir "$work/viewer" >/dev/null
/usr/bin/python3 -c 'import sys; from PIL import Image; Image.open(sys.argv[1]).save(sys.argv[2], optimize=True)' \
  "$work/viewer/frame-00012.png" docs/images/viewer.png

echo "make-pictures: docs/images/at_a_glance.png (preset $preset: RMSE $rmse against 1024 rays per pixel)"
echo "make-pictures: docs/images/ao.png lit_ao.png lit_no_ao.png modes.png (plugin defaults), viewer.png"

if [ "$bench" -eq 1 ]; then
  scripts/run-bench.sh
  for f in error_vs_time.png bench.csv bench.md presets.txt bench.dat front_vr.dat front_limit.dat plot.gp; do
    [ -f "bench-out/$f" ] && cp "bench-out/$f" "docs/bench/$f"
  done
  # The README's preset table, per-scene summary, targets and time table.
  /usr/bin/python3 scripts/bench_readme.py docs/bench
  echo "make-pictures: docs/bench/ from bench-out/, bench blocks of the README and docs/ rewritten (scripts/bench_readme.py)"
fi
ls -l docs/images/*.png docs/bench/error_vs_time.png | awk '{ printf "  %7d bytes  %s\n", $5, $9 }'
