#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer
# (-O1 -g, assertions on, any report is fatal) in build-sanitize/ and runs the
# whole ctest suite there, except tests given the ctest label
# `slow_under_sanitizers` (none is, so far). Exit code 0 = no report.
#   bash scripts/sanitize.sh [ctest arguments]
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --packages-only g++ cmake make libcgal-dev libeigen3-dev libboost-dev \
  libboost-program-options-dev libgtest-dev nlohmann-json3-dev
flags="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_CXX_FLAGS_SANITIZE="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS_SANITIZE="-fsanitize=address,undefined" \
  -DTILABLE_SURFACES_BUILD_BENCHMARKS=OFF > build-sanitize-configure.log 2>&1 \
  || { cat build-sanitize-configure.log; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
nice -n 15 cmake --build build-sanitize -j "$jobs"
cd build-sanitize
# halt_on_error: the first report fails the test; detect_leaks: leaks count too.
export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1:abort_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
nice -n 15 ctest --output-on-failure -j "$jobs" -LE slow_under_sanitizers "$@"
