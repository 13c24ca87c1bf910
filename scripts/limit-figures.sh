#!/usr/bin/env bash
# The depth-only limit's figures for the README: for each bundled scene (their own
# camera and radius, as ssao-host and ssao-bench use them), ssao-reference --limit
# at a small size, then ssao-error of the limit against V_R. Prints a Markdown
# table; everything else lands in $OUT (default ./limit-out).
#   scripts/limit-figures.sh [WIDTH HEIGHT]      (default 256 144; needs scripts/build.sh first)
set -euo pipefail
cd "$(dirname "$0")/.."
W=${1:-256}
H=${2:-144}
OUT=${OUT:-limit-out}
REF=build/reference/ssao-reference
ERR=build/reference/ssao-error
for exe in "$REF" "$ERR"; do
  [ -x "$exe" ] || { echo "limit-figures: $exe is missing (run scripts/build.sh)" >&2; exit 1; }
done
mkdir -p "$OUT"
rm -f "$OUT/limit.csv"
echo "| scene | size | geometry px | limit vs V_R PSNR: all / interior / silhouette (dB) | RMSE all | mean error | limit noise: rms / p99 std. error | V_R trace (s) | limit (s) |"
echo "|---|---|---:|---|---:|---:|---|---:|---:|"
for scene in assets/models/spot-on-ground.glb assets/models/teapot-on-ground.glb assets/scenes/corner.gltf; do
  name=$(basename "${scene%.*}")
  dir="$OUT/$name"
  "$REF" "$scene" --width "$W" --height "$H" --limit --dump-buffers --quiet --out "$dir" >"$OUT/$name.log"
  # TEST = the limit, REF = the folder (V_R with its depth for the silhouette band):
  # the rows against V_R are limit vs V_R.
  "$ERR" "$dir/limit_ao.exr" "$dir" --csv "$OUT/limit.csv" --label "$name" >"$OUT/$name.error.txt"
  awk -F, -v n="$name" -v size="${W}x${H}" -v logf="$OUT/$name.log" '
    BEGIN {
      while ((getline line < logf) > 0) {
        if (line ~ /^limit +mean AO/) { match(line, /rms [0-9.]+/); rms = substr(line, RSTART + 4, RLENGTH - 4);
                                        match(line, /percentile [0-9.]+/); p99 = substr(line, RSTART + 11, RLENGTH - 11) }
        if (line ~ /^time +limit/) { split(line, t, " "); lim_s = t[3] }
        else if (line ~ /^time /) { split(line, t, " "); trace_s = t[2] }
      }
    }
    $1 == n && $NF == "V_R" { psnr[$2] = $6; rmse[$2] = $5; mean[$2] = $7; px[$2] = $3 }
    END {
      printf "| %s | %s | %s | %.2f / %.2f / %.2f | %.4f | %+.4f | %s / %s | %s | %s |\n", n, size, px["all"],
             psnr["all"], psnr["interior"], psnr["silhouette"], rmse["all"], mean["all"], rms, p99, trace_s, lim_s
    }' "$OUT/limit.csv"
done
echo
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')"
