#!/usr/bin/env bash
# Fuzzes reading, validation and a small pipeline run with libFuzzer (clang,
# AddressSanitizer, UndefinedBehaviorSanitizer) for SECONDS seconds (default
# 600), seeded with the test and example data and the recorded regressions.
#   bash scripts/fuzz.sh [SECONDS]
# The corpus grows in build-fuzz/corpus/; an input that fails is written to
# build-fuzz/artifacts/ and the run stops with a non-zero exit code: copy it
# to fuzz/Tilable_surfaces/regressions/ (named refused_* or accepted_*), fix
# the bug, and test_fuzz_regressions replays it from then on.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
bash scripts/setup.sh --packages-only g++ cmake make libcgal-dev libeigen3-dev libboost-dev \
  libboost-program-options-dev nlohmann-json3-dev clang libclang-rt-dev
CC=clang CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=Fuzz \
  -DCMAKE_CXX_FLAGS_FUZZ="-O1 -g" -DBUILD_TESTING=OFF -DTILABLE_SURFACES_BUILD_BENCHMARKS=OFF \
  -DTILABLE_SURFACES_BUILD_FUZZER=ON > build-fuzz-configure.log 2>&1 \
  || { cat build-fuzz-configure.log; exit 1; }
nice -n 15 cmake --build build-fuzz -j 2 --target fuzz_read_and_tile
mkdir -p build-fuzz/corpus build-fuzz/seeds build-fuzz/artifacts
cp test/Tilable_surfaces/data/*.off test/Tilable_surfaces/data/*.obj \
   fuzz/Tilable_surfaces/regressions/*_* build-fuzz/seeds/
cp -n examples/Tilable_surfaces/data/*.off build-fuzz/seeds/  # mostly the same files
# Small seeds of every format: a 2 x 2 grid in OFF, OBJ, ASCII and binary PLY.
printf 'OFF\n9 4 0\n0 0 0\n1 0 0\n2 0 0\n0 1 0\n1 1 .2\n2 1 0\n0 2 0\n1 2 0\n2 2 .1\n4 0 1 4 3\n4 1 2 5 4\n4 3 4 7 6\n4 4 5 8 7\n' \
  > build-fuzz/seeds/grid.off
printf 'ply\nformat ascii 1.0\nelement vertex 6\nproperty double x\nproperty double y\nproperty double z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n2 0 .3\n0 1 0\n1 1 0\n2 1 0\n4 0 1 4 3\n4 1 2 5 4\n' \
  > build-fuzz/seeds/grid_ascii.ply
{ printf 'ply\nformat binary_little_endian 1.0\nelement vertex 6\nproperty float x\nproperty float y\nproperty float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n'
  python3 -c 'import struct,sys; sys.stdout.buffer.write(b"".join(struct.pack("<3f",*p) for p in [(0,0,0),(1,0,0),(2,0,.3),(0,1,0),(1,1,0),(2,1,0)]) + b"".join(struct.pack("<B4i",4,*f) for f in [(0,1,4,3),(1,2,5,4)]))'
} > build-fuzz/seeds/grid_binary.ply
nice -n 15 build-fuzz/bin/fuzz_read_and_tile build-fuzz/corpus build-fuzz/seeds \
  -max_total_time="$seconds" -max_len=65536 -timeout=30 -rss_limit_mb=2048 -malloc_limit_mb=1024 \
  -artifact_prefix=build-fuzz/artifacts/ -print_final_stats=1
