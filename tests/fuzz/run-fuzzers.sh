#!/usr/bin/env bash
# Runs every libFuzzer target of a build (default build-asan) for a bounded
# number of inputs on a scratch copy of its committed seed corpus; the tree
# is never written. Usage: tests/fuzz/run-fuzzers.sh [BUILD_DIR] [RUNS]
# RUNS is the count for the scene and EXR targets; the argv parsers, which
# take microseconds, get 5 x RUNS; the ABI fuzzer, which renders on llvmpipe,
# gets RUNS/10. Fails on the first finding (its input is kept in
# $SSAO_FUZZ_ARTIFACTS, default ./fuzz-artifacts/).
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build-asan}
runs=${2:-20000}
artifacts=${SSAO_FUZZ_ARTIFACTS:-$PWD/fuzz-artifacts}
mkdir -p "$artifacts"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

fuzz() {
  local name=$1 n=$2; shift 2
  local exe=$build/tests/fuzz/$name
  [ -x "$exe" ] || { echo "run-fuzzers: $exe is missing (configure with -DSSAO_FUZZ=ON)" >&2; exit 1; }
  mkdir -p "$work/$name"
  local start=$SECONDS
  # -rss_limit_mb / -timeout: a run that needs more memory or time per input is a finding too.
  "$exe" "$work/$name" "tests/fuzz/corpus/${name#fuzz_}" -runs="$n" -seed=1 -rss_limit_mb=2560 -timeout=20 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$name-" "$@" > "$work/$name.log" 2>&1 || {
    tail -n 60 "$work/$name.log"; echo "run-fuzzers: $name found a problem (see above)" >&2; exit 1; }
  local execs
  execs=$(grep -m1 'stat::number_of_executed_units' "$work/$name.log" | awk '{print $2}')
  echo "run-fuzzers: $name: ${execs:-?} inputs in $((SECONDS - start)) s, corpus $(ls "$work/$name" | wc -l) new inputs"
}

fuzz fuzz_scene "$runs" -max_len=65536
fuzz fuzz_exr "$runs" -max_len=4096
fuzz fuzz_flags "$((runs * 5))" -max_len=512
fuzz fuzz_abi "$((runs / 10))" -max_len=1024
