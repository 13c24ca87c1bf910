#!/usr/bin/env bash
# Sanitizer runs (issue 11), after the normal suite (.ci/run):
#   1. an ASan+UBSan build (build-asan/, clang) running the whole CTest suite,
#      the soak test included, with leak detection on;
#   2. each libFuzzer target for a bounded number of inputs, on the same build;
#   3. a TSan build (build-tsan/) of the library and the two-thread test.
# Any report fails the script (-fno-sanitize-recover=all, halt_on_error).
# Longer fuzzing: see README, "Reliability".
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
root=$PWD
jobs=$(nproc)
: "${SSAO_FUZZ_RUNS:=20000}"   # inputs per fuzzer (CI); raise it for a longer run

export CC=clang-14 CXX=clang++-14
common=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g"
        "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -g")
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_init_order=1:detect_odr_violation=2
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/sanitizers/tsan.supp

step() { echo; echo "== run-sanitizers: $* ($(date -u +%T))"; }

step "ASan+UBSan build"
cmake -S . -B build-asan "${common[@]}" -DSSAO_SANITIZE=address,undefined -DSSAO_FUZZ=ON \
  "-DSSAO_TEST_AREAS=unit;plugin;host;reference;hard_cases;reliability;fuzz" >/dev/null
cmake --build build-asan -j"$jobs"

step "ASan+UBSan: the whole CTest suite"
start=$SECONDS
ctest --test-dir build-asan --output-on-failure -j"$jobs"
echo "suite under ASan+UBSan: $((SECONDS - start)) s"

step "fuzzers, $SSAO_FUZZ_RUNS inputs each"
bash tests/fuzz/run-fuzzers.sh build-asan "$SSAO_FUZZ_RUNS"

step "TSan build of the library and the thread test"
cmake -S . -B build-tsan "${common[@]}" -DSSAO_SANITIZE=thread "-DSSAO_TEST_AREAS=reliability" >/dev/null
cmake --build build-tsan -j"$jobs" --target ssao test_threads

step "TSan: two threads, two contexts"
start=$SECONDS
SSAO_PLUGIN=$root/build-tsan/plugin/libssao.so build-tsan/tests/reliability/test_threads
echo "thread test under TSan: $((SECONDS - start)) s"

step "all sanitizer runs passed"
