#!/usr/bin/env bash
# Installs the Debian packages the project needs (as root, non-interactive),
# then configures and builds a Release build in build/. Idempotent: packages
# already present are not reinstalled, and the build is incremental.
set -euo pipefail
cd "$(dirname "$0")/.."

# Usage: setup.sh                          install the build's packages, configure, build
#        setup.sh --packages-only P...       install the Debian packages P only
packages_only=false
if [ "${1:-}" = "--packages-only" ]; then
  packages_only=true
  shift
  packages=("$@")
else
  packages=(g++ cmake make libcgal-dev libeigen3-dev libboost-dev libboost-program-options-dev
            libgtest-dev nlohmann-json3-dev
            # optional, used when present: parallel loops and the CHOLMOD sparse solver
            libtbb-dev libsuitesparse-dev
            # optional: OpenBLAS as the system BLAS makes CHOLMOD's dense blocks 1.5x faster
            libopenblas0-pthread
            # optional, used when present: the Python module tilable_surfaces (build/python/)
            pybind11-dev python3-dev python3-numpy)
  # scripts/fuzz.sh installs clang and libclang-rt-dev (libFuzzer) on top, when it is run.
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

$packages_only && exit 0
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build-configure.log 2>&1 \
  || { cat build-configure.log; exit 1; }
jobs=$(nproc 2>/dev/null || echo 2)
cmake --build build -j "$jobs" "$@"
