#!/usr/bin/env bash
# README's second command: set up, build what the testsuite needs (all but the
# benchmarks: target tilable_surfaces_testsuite), and run the whole testsuite.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --target tilable_surfaces_testsuite
jobs=$(nproc 2>/dev/null || echo 2)
cd build
ctest --output-on-failure -j "$jobs"
