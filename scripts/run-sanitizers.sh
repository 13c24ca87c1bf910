#!/usr/bin/env bash
# Sanitizer runs, after the normal suite (.ci/run):
#   1. an ASan+UBSan build (build-asan/, clang) running the CTest suite, the
#      soak test included, with leak detection on;
#   2. each libFuzzer target for a bounded number of inputs, on the same build;
#   3. a TSan build (build-tsan/) of the library and the two-thread test.
# Any report fails the script (-fno-sanitize-recover=all, halt_on_error).
# Prints each phase's wall time at the end. Longer fuzzing and soaking: see
# docs/reliability.md (e.g. SSAO_FUZZ_RUNS=200000 scripts/run-sanitizers.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
root=$PWD
jobs=$(nproc)
# Inputs per fuzzer in CI (tests/fuzz/run-fuzzers.sh: the argv parsers get
# 5x, the ABI fuzzer, which renders, a tenth): about two minutes in all on
# 2 cores; raise it for a longer run.
: "${SSAO_FUZZ_RUNS:=20000}"

export CC=clang-14 CXX=clang++-14
. scripts/ccache-env.sh
# -O1 and line tables only: full stack traces with file:line, and a build
# several minutes shorter than with full debug info.
common=(-DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only"
        "-DCMAKE_C_FLAGS_RELWITHDEBINFO=-O1 -gline-tables-only"
        # The viewer (GLFW, tests under xvfb) is not built: its tests are not
        # in SSAO_TEST_AREAS below and no other test runs it; the plugin code
        # it drives is what the other tests drive.
        -DCMAKE_DISABLE_FIND_PACKAGE_glfw3=ON "${ssao_cmake_launcher[@]}")
# intercept_tls_get_addr=0: LeakSanitizer does not track the dynamic TLS
# blocks of dlopen'ed modules, so it does not scan them as roots. At exit it
# read a bogus record there with Mesa loaded and its tracer crashed ("Tracer
# caught signal 11", docs/reliability.md). Fewer roots can only make it
# report more, never less; static TLS is still scanned.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_init_order=1:detect_odr_violation=2:intercept_tls_get_addr=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
export LSAN_OPTIONS=suppressions=$root/tests/sanitizers/lsan.supp:print_suppressions=0
export TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$root/tests/sanitizers/tsan.supp

phases=()
phase_start=$SECONDS
step() {
  if [ -n "${phase_name:-}" ]; then phases+=("$(printf '%4d s  %s' $((SECONDS - phase_start)) "$phase_name")"); fi
  phase_name=$*
  phase_start=$SECONDS
  echo; echo "== run-sanitizers: $* ($(date -u +%T))"
}

step "ASan+UBSan build"
cmake -S . -B build-asan "${common[@]}" -DSSAO_SANITIZE=address,undefined -DSSAO_FUZZ=ON \
  "-DSSAO_TEST_AREAS=unit;plugin;host;reference;hard_cases;reliability;fuzz" >/dev/null
cmake --build build-asan -j"$jobs"
# See tests/sanitizers/keep_modules.c: dlclose() keeps modules mapped, so
# LeakSanitizer names the module of every leak (nothing is suppressed by it).
$CC -shared -fPIC -O1 -o build-asan/keep_modules.so tests/sanitizers/keep_modules.c

step "ASan+UBSan: the CTest suite"
# Left out (-LE): the tests whose programs are built outside this build and
# cannot load an instrumented libssao.so (it needs the sanitizer runtime in
# the executable): the package test's fresh CMake consumers, the Python
# interpreter (python.*), and the doc blocks that run the Python host.
# The library code they reach is reached by the C/C++ tests here.
# Left out (-E): reference.limit_oracle and reference.limit_oracle_views, a
# brute-force test oracle (about 140 s of CPU time in the release build, over
# 300 s under ASan on a loaded 2-core machine for the first alone); the
# depth-limit code they check runs here in reference.limit and
# reference.limit_convergence.
LD_PRELOAD=$root/build-asan/keep_modules.so \
  ctest --test-dir build-asan --output-on-failure -j"$jobs" -LE '^(package|python|readme)$' -E '^reference\.limit_oracle(_views)?$'

step "fuzzers: scene and EXR $SSAO_FUZZ_RUNS inputs each, argv $((SSAO_FUZZ_RUNS * 5)), ABI $((SSAO_FUZZ_RUNS / 10))"
bash tests/fuzz/run-fuzzers.sh build-asan "$SSAO_FUZZ_RUNS"

step "TSan build of the library and the thread test"
cmake -S . -B build-tsan "${common[@]}" -DSSAO_SANITIZE=thread "-DSSAO_TEST_AREAS=reliability" >/dev/null
cmake --build build-tsan -j"$jobs" --target ssao test_threads

step "TSan: two threads, two contexts"
SSAO_PLUGIN=$root/build-tsan/plugin/libssao.so build-tsan/tests/reliability/test_threads

step "done"
echo "run-sanitizers: all sanitizer runs passed; wall time per phase:"
printf '  %s\n' "${phases[@]}"
