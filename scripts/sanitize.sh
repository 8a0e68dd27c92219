#!/usr/bin/env bash
# Builds with AddressSanitizer (with LeakSanitizer) and UndefinedBehaviorSanitizer
# (-O1 -g1, assertions on) in build-sanitize/ and runs the ctest suite there.
#   bash scripts/sanitize.sh [--quick | --fast] [ctest arguments]
#   --quick   builds the target sanitize_quick and runs the tests labelled
#             `sanitize_quick` but not `slow`: those of test_tilable_surfaces_input
#             (reading, validation, bad input, fuzz regressions, every kind of
#             mesh, sweeps, the distance oracle) but the large pipelines, which
#             the Release suite runs; what .ci/run does.
#   --fast    builds the testsuite and runs the tests labelled `fast` (the
#             input-handling tests among them): every part of the package.
#             Without either: everything, the whole suite.
# SANITIZE_JOBS=N sets the build and ctest job count (default: the number of cores).
#
# Any report is fatal: UBSan is compiled with -fno-sanitize-recover=all (the first
# report aborts, whatever UBSAN_OPTIONS say), ASan halts at its first report,
# LeakSanitizer fails the process at exit, and so a report fails its test, also
# one in a process a test starts (test_cli runs the CLI and checks its exit code).
# As a second check, the output ctest recorded of every test, passed ones too, is
# searched for reports. Exit code 0 = every test passed and no report.
# Nothing is suppressed: the suite gives no report, in the package's code or in
# CGAL, Eigen, TBB or CHOLMOD. -g1 (line tables) keeps file:line in stack traces
# and compiles a fifth faster than -g.
set -euo pipefail
cd "$(dirname "$0")/.."
mode=all
case "${1:-}" in
  --quick) mode=quick; shift ;;
  --fast) mode=fast; shift ;;
esac
bash scripts/setup.sh --packages-only g++ cmake make ninja-build libcgal-dev libeigen3-dev libboost-dev \
  libboost-program-options-dev libgtest-dev nlohmann-json3-dev
sanitizers="address,undefined,float-cast-overflow"
flags="-O1 -g1 -fsanitize=$sanitizers -fno-sanitize-recover=all -fno-omit-frame-pointer"
asan_options="halt_on_error=1:abort_on_error=1:detect_leaks=1:check_initialization_order=1"
# The Python tests load the instrumented module into the uninstrumented
# interpreter: the ASan runtime is preloaded, with libstdc++ (ASan finds the
# __cxa_throw it intercepts at start-up, before the module would load it), and
# leaks are not looked for there (CPython keeps its objects to the end by design).
preload="$(g++ -print-file-name=libasan.so) $(g++ -print-file-name=libstdc++.so)"
python_environment="LD_PRELOAD=$preload;ASAN_OPTIONS=${asan_options/detect_leaks=1/detect_leaks=0}"
generator=()  # Ninja for a new build directory, as setup.sh
[ ! -f build-sanitize/CMakeCache.txt ] && command -v ninja > /dev/null && generator=(-G Ninja)
cmake -S . -B build-sanitize "${generator[@]}" -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=$sanitizers" \
  -DCMAKE_MODULE_LINKER_FLAGS_SANITIZE="-fsanitize=$sanitizers" \
  -DCMAKE_SHARED_LINKER_FLAGS_SANITIZE="-fsanitize=$sanitizers" \
  -DTILABLE_SURFACES_PYTHON_TEST_ENVIRONMENT="$python_environment" \
  -DTILABLE_SURFACES_BUILD_BENCHMARKS=OFF -DTILABLE_SURFACES_TEST_BATCH_SIZE=4 \
  -DTILABLE_SURFACES_INPUT_TEST_BATCH_SIZE=4 -DTILABLE_SURFACES_TEST_TIMEOUT_SCALE=10 \
  > build-sanitize-configure.log 2>&1 \
  || { cat build-sanitize-configure.log; exit 1; }
jobs=${SANITIZE_JOBS:-$(nproc 2>/dev/null || echo 2)}
case $mode in
  quick) build_targets=(--target sanitize_quick); ctest_selection=(-L sanitize_quick -LE slow) ;;
  fast) build_targets=(--target tilable_surfaces_testsuite); ctest_selection=(-L fast) ;;
  *) build_targets=(--target all); ctest_selection=() ;;
esac
TIMEFORMAT="sanitize: build %0R s (cpu: %0U s user, %0S s system)"
time nice -n 15 cmake --build build-sanitize -j "$jobs" "${build_targets[@]}"
cd build-sanitize
export ASAN_OPTIONS="$asan_options"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
status=0
TIMEFORMAT="sanitize: tests %0R s (cpu: %0U s user, %0S s system)"
time nice -n 15 ctest --output-on-failure -j "$jobs" "${ctest_selection[@]}" "$@" || status=$?
# Second check: a report in the output of a test that passed all the same.
report='ERROR: (Address|Leak)Sanitizer|:[0-9]+:[0-9]+: runtime error: |SUMMARY: UndefinedBehaviorSanitizer'
if grep -E -q "$report" Testing/Temporary/LastTest.log; then
  echo "sanitize: reports in the output of these tests (Testing/Temporary/LastTest.log):"
  awk -v re="$report" '/^[0-9]+\/[0-9]+ Testing: /{test=$3} $0 ~ re {print "  " test ": " $0}' \
    Testing/Temporary/LastTest.log | head -40
  status=1
fi
[ "$status" -eq 0 ] && echo "sanitize: no sanitizer report, every test passed"
exit "$status"
