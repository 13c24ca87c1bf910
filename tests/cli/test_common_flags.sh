#!/usr/bin/env bash
# The tools behave alike (CTest: cli.common_flags):
#   test_common_flags.sh HOST REFERENCE ERROR BENCH [VIEWER]
# --version and --help exit 0; an unknown flag or a missing value exits 2 with
# one line on stderr, "TOOL: error: ...", naming the flag and the flag it most
# likely meant; --flag=value and --flag value give the same result (identical
# output files, or the same message for a bad value).
set -uo pipefail
host=$1 reference=$2 error=$3 bench=$4 viewer=${5:-}
. "$(dirname "$0")/checks.sh"

# expect_usage_error TOOL FLAG ARGS...: exit 2, exactly one stderr line, naming FLAG.
expect_usage_error() {
  local tool=$1 flag=$2; shift 2
  "$tool" "$@" >"$work/stdout" 2>"$work/stderr"
  local code=$? lines
  lines=$(wc -l <"$work/stderr")
  [ "$code" -eq 2 ] && [ "$lines" -eq 1 ] && grep -qF -- "$flag" "$work/stderr" ||
    { echo "  $(basename "$tool") $*: exit $code, $lines stderr lines: $(cat "$work/stderr")"; return 1; }
}

for tool in "$host" "$reference" "$error" "$bench"; do
  name=$(basename "$tool")
  check "$name --version prints '$name X.Y.Z (C ABI M.m)'" \
    bash -c '[[ "$("$1" --version)" =~ ^$2\ [0-9]+\.[0-9]+\.[0-9]+\ \(C\ ABI\ [0-9]+\.[0-9]+\)$ ]]' _ "$tool" "$name"
  check "$name --help exits 0 and lists --version" bash -c '"$1" --help | grep -q -- --version' _ "$tool"
  check "$name -h is --help" bash -c 'cmp -s <("$1" -h) <("$1" --help)' _ "$tool"
  check "$name --bogus: exit 2, one line naming it" expect_usage_error "$tool" --bogus --bogus
  check "$name --bogus=1: exit 2, one line naming it" expect_usage_error "$tool" --bogus --bogus=1
  check "$name --bogus: the line starts '$name: error: '" bash -c '"$1" --bogus 2>&1 >/dev/null | grep -q "^$2: error: unknown flag"' _ "$tool" "$name"
  check "$name --verison: did you mean --version?" expect_usage_error "$tool" "unknown flag '--verison'; did you mean --version?" --verison
  check "$name --hel: did you mean --help? (a unique prefix)" expect_usage_error "$tool" "did you mean --help?" --hel
  check "$name --bogus: no guess three edits away (--out)" bash -c '! "$1" --bogus 2>&1 | grep -q "did you mean"' _ "$tool"
  check "$name --version=1: --version takes no value" expect_usage_error "$tool" "--version takes no value" --version=1
  check "$name --help=1: --help takes no value" expect_usage_error "$tool" "--help takes no value" --help=1
  valued=--out
  [ "$name" = ssao-error ] && valued=--label
  check "$name $valued --bogus: a flag is not taken as $valued's value" \
    expect_usage_error "$tool" "$valued needs a value, got the flag '--bogus'" "$valued" --bogus
done
# A misspelling of each tool's own flags (within two edits, or a unique prefix).
check "ssao-host --radus: did you mean --radius?" expect_usage_error "$host" "did you mean --radius?" --radus 0.3
check "ssao-host --rad: did you mean --radius? (not --radius-pixels)" expect_usage_error "$host" "did you mean --radius?" --rad 0.3
check "ssao-reference --samles: did you mean --samples?" expect_usage_error "$reference" "did you mean --samples?" --samles 8
check "ssao-error --lable: did you mean --label?" expect_usage_error "$error" "did you mean --label?" a.exr b.exr --lable x
check "ssao-bench --frmes: did you mean --frames?" expect_usage_error "$bench" "did you mean --frames?" --frmes 3
check "ssao-host --zzzzzz: no guess" bash -c '! "$1" --zzzzzz 2>&1 | grep -q "did you mean"' _ "$host"
if [ -n "$viewer" ]; then
  check "ssao-viewer --bogus: the line starts ssao-viewer: error:" bash -c \
    '"$1" --bogus 2>&1 >/dev/null | grep -q "^ssao-viewer: error: unknown flag"' _ "$viewer"
  check "ssao-viewer --widht: did you mean --width?" expect_usage_error "$viewer" "did you mean --width?" --widht 9
  # One list of preset names: ssao-host took chapter, ssao-viewer refused it.
  check "ssao-viewer --preset chapter is accepted (stops later, for want of a display)" bash -c \
    '! env -u DISPLAY -u WAYLAND_DISPLAY "$1" --preset chapter 2>&1 | grep -q -- --preset' _ "$viewer"
fi
check "ssao-host and ssao-viewer name the same presets" bash -c \
  '"$1" --preset x 2>&1 | grep -q "low|medium|high|ultra|chapter" &&
   { [ -z "$2" ] || "$2" --preset x 2>&1 | grep -q "low|medium|high|ultra|chapter"; }' _ "$host" "$viewer"

# A valued flag without its value, and a bad value in both spellings (same message).
check "ssao-host --width (no value): exit 2" expect_usage_error "$host" --width --width
check "ssao-bench --width (no value): exit 2" expect_usage_error "$bench" --width --width
check "ssao-error --band (no value): exit 2" expect_usage_error "$error" --band a.exr b.exr --band
# ssao-error needs its two images before a flag's value is looked at.
images_for() { [ "$(basename "$1")" = ssao-error ] && echo "a.exr b.exr"; }
for pair in "$host:--width:0" "$reference:--samples:x" "$error:--band:300" "$bench:--width:4" "$bench:--frames:x"; do
  IFS=: read -r tool flag value <<<"$pair"
  a=$("$tool" $(images_for "$tool") "$flag=$value" 2>&1 >/dev/null); ca=$?
  b=$("$tool" $(images_for "$tool") "$flag" "$value" 2>&1 >/dev/null); cb=$?
  check "$(basename "$tool") $flag=$value and $flag $value: both exit 2 with the same message ($a)" \
    test "$ca" -eq 2 -a "$cb" -eq 2 -a "$a" = "$b" -a -n "$a"
done
check "a switch takes no value: ssao-reference --quiet=1 exits 2" expect_usage_error "$reference" --quiet --quiet=1
# An argument with a line break is quoted with it escaped: still one line (found by fuzz_flags).
check "ssao-host with two scenes, one named 'a<newline>b': exit 2, one line" \
  expect_usage_error "$host" "more than one scene file given: 'a\x0ab'" $'a\nb' c.glb
check "ssao-error --bogus<newline>: exit 2, one line" expect_usage_error "$error" "'--bogus\x0a'" a.exr b.exr $'--bogus\n'
check "a coordinate beyond float range: ssao-host --eye=1e57,2,3 exits 2 (not an inf camera)" expect_usage_error "$host" --eye --eye=1e57,2,3
check "a coordinate beyond float range: ssao-reference --target 0,-4e38,0 exits 2" expect_usage_error "$reference" --target --target 0,-4e38,0

# Same run, both spellings: identical files.
check "ssao-host --width=48 --out=DIR and --width 48 --out DIR write identical ao.exr" bash -c '
  "$1" --width=48 --height=32 --frames=1 --only=ao --out="$2/h1" >/dev/null &&
  "$1" --width 48 --height 32 --frames 1 --only ao --out "$2/h2" >/dev/null &&
  cmp -s "$2/h1/ao.exr" "$2/h2/ao.exr"' _ "$host" "$work"
# The DEFAULT preset is medium: taking it and then a radius must change nothing
# (bias and thickness follow the radius set after the preset).
check "ssao-host --preset medium --radius 1 writes the same ao.exr as --radius 1" bash -c '
  "$1" --width 48 --height 32 --frames 1 --only ao --radius 1 --out "$2/p0" >/dev/null &&
  "$1" --width 48 --height 32 --frames 1 --only ao --radius 1 --preset medium --out "$2/p1" >/dev/null &&
  cmp -s "$2/p0/ao.exr" "$2/p1/ao.exr"' _ "$host" "$work"
check "ssao-reference --samples=8 and --samples 8 write identical reference_ao.exr" bash -c '
  "$1" --width=24 --height=16 --samples=8 --quiet --out="$2/r1" >/dev/null &&
  "$1" --width 24 --height 16 --samples 8 --quiet --out "$2/r2" >/dev/null &&
  cmp -s "$2/r1/reference_ao.exr" "$2/r2/reference_ao.exr"' _ "$reference" "$work"
check "ssao-error --band=2 and --band 2 print the same table, and --label=x and --label x the same CSV row" bash -c '
  "$1" "$2/r1/reference_ao.exr" "$2/r1" --band=2 --label=x --csv "$2/eq.csv" >"$2/eq.txt" &&
  "$1" "$2/r1/reference_ao.exr" "$2/r1" --band 2 --label x --csv "$2/sp.csv" >"$2/sp.txt" &&
  grep -q "^all" "$2/eq.txt" && cmp -s "$2/eq.txt" "$2/sp.txt" &&
  grep -q "^x,all," "$2/eq.csv" && cmp -s "$2/eq.csv" "$2/sp.csv"' \
  _ "$error" "$work"

finish "common flags"
