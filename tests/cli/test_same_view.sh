#!/usr/bin/env bash
# ssao-host and ssao-reference start from one camera, and ssao-error checks it
# (CTest: cli.same_view):
#   test_same_view.sh HOST REFERENCE ERROR
# Without a scene argument both use the bundled view of the cow, so their
# images compare (all-pixels PSNR above 20 dB; two different cameras gave
# 15.9 dB with exit 0). An ao.exr made from another eye, radius or size is
# refused naming the field, unless --allow-mismatch. A camera that cannot
# render is refused by both.
set -uo pipefail
host=$1 reference=$2 error=$3
. "$(dirname "$0")/checks.sh"
small=(--width 64 --height 48)
"$host" "${small[@]}" --only ao --frames 1 --out "$work/host" >"$work/host.log" 2>&1 || { cat "$work/host.log"; exit 1; }
"$reference" "${small[@]}" --samples 32 --quiet --out "$work/ref" >"$work/ref.log" 2>&1 || { cat "$work/ref.log"; exit 1; }
"$host" "${small[@]}" --only ao --frames 1 --eye 3,2,-3 --out "$work/eye" >/dev/null 2>&1
"$host" "${small[@]}" --only ao --frames 1 --radius 0.3 --out "$work/radius" >/dev/null 2>&1

check "both print the bundled view of the cow" bash -c \
  'grep -q "camera: the bundled view of the cow, .*eye (2.3, 1.6, -2.6), target (0, 0.65, 0)" "$1/host.log" &&
   grep -q "camera    the bundled view of the cow, eye (2.3, 1.6, -2.6), target (0, 0.65, 0)" "$1/ref.log"' _ "$work"
"$error" "$work/host/ao.exr" "$work/ref" >"$work/error.log" 2>&1; code=$?
check "ssao-error host vs reference, defaults: exit 0, no note, PSNR (all) above 20 dB ($(grep '^all' "$work/error.log"))" \
  bash -c '[ "$1" -eq 0 ] && ! grep -q "^note" "$2" && awk '\''$1 == "all" { ok = ($4 + 0 > 20) } END { exit !ok }'\'' "$2"' \
  _ "$code" "$work/error.log"

expect_refused() {  # expect_refused TEST LINE: exit 1, stderr exactly LINE
  "$error" "$1" "$work/ref" >"$work/stdout" 2>"$work/stderr"
  local code=$?
  [ "$code" -eq 1 ] && [ "$(cat "$work/stderr")" = "$2" ] ||
    { echo "  exit $code: $(cat "$work/stderr")"; return 1; }
}
check "another --eye: refused, naming eye and both values" expect_refused "$work/eye/ao.exr" \
  "ssao-error: error: $work/eye/ao.exr and $work/ref/reference_ao.exr were made with a different eye: 3,2,-3 vs 2.3,1.6,-2.6 (--allow-mismatch compares them anyway)."
check "another --radius: refused, naming radius and both values" expect_refused "$work/radius/ao.exr" \
  "ssao-error: error: $work/radius/ao.exr and $work/ref/reference_ao.exr were made with a different radius: 0.3 vs 0.57418 (--allow-mismatch compares them anyway)."
check "--allow-mismatch compares them anyway, saying so" bash -c \
  '"$1" "$2/eye/ao.exr" "$2/ref" --allow-mismatch | grep -q "^mismatch   eye: 3,2,-3 vs 2.3,1.6,-2.6, compared anyway"' \
  _ "$error" "$work"

# A camera that cannot render is refused by both tools, with the same sentence
# (an infinite projection would trace an all-sky image).
both_refuse() {  # both_refuse FRAGMENT FLAGS...: exit 1 from each, stderr naming FRAGMENT
  local fragment=$1; shift
  "$host" "$@" --only ao --frames 1 --out "$work/bad" >/dev/null 2>"$work/host.err"; local h=$?
  "$reference" "$@" --samples 4 --quiet --out "$work/bad" >/dev/null 2>"$work/ref.err"; local r=$?
  [ "$h" -eq 1 ] && [ "$r" -eq 1 ] && grep -q "$fragment" "$work/host.err" && grep -q "$fragment" "$work/ref.err" &&
    [ ! -e "$work/bad/reference_ao.exr" ] || { echo "  exits $h $r: $(cat "$work/host.err") / $(cat "$work/ref.err")"; return 1; }
}
check "an orthographic half height of 1.2e-38 (an infinite projection): both refuse" \
  both_refuse "non-finite view or projection" --width 1 --height 8 --ortho 1.2e-38
sed 's/"radius": 0.75/"radius": 1e300/' "$(dirname "$0")/../host/data/hinted.gltf" >"$work/far_radius.gltf"
check "a radius hint beyond float range: both refuse, naming it" \
  both_refuse "ssao.radius = 1e+300" "$work/far_radius.gltf" --width 8 --height 8

finish "same view"
