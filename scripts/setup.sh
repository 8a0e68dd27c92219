#!/usr/bin/env bash
# Installs the Debian packages the project needs (as root, non-interactive),
# then configures and builds a Release build in build/. Idempotent: packages
# already present are not reinstalled, and the build is incremental.
#
# Usage: setup.sh [cmake --build arguments]  everything: the library's programs, the
#                                            Python module, the testsuite, the benchmarks
#        setup.sh --cli [P...]               only what the command-line program needs (and the
#                                            Debian packages P), and only that program
#                                            (README's first command)
#        setup.sh --packages-only P...       install the Debian packages P only
set -euo pipefail
cd "$(dirname "$0")/.."

# The command-line program's packages; the optional ones are used when present:
# parallel loops (TBB), the CHOLMOD sparse solver (1.5x faster on OpenBLAS), ccache.
cli_packages=(g++ cmake make ninja-build libcgal-dev libeigen3-dev libboost-dev libboost-program-options-dev
              nlohmann-json3-dev libtbb-dev libsuitesparse-dev libopenblas0-pthread ccache)
# On top, for the testsuite and the Python module tilable_surfaces (build/python/);
# chromium for the test of the HTML report in a browser (label browser).
test_packages=(libgtest-dev pybind11-dev python3-dev python3-numpy chromium)
# scripts/fuzz.sh installs clang and libclang-rt-dev (libFuzzer) on top, when it is run.

mode=all
case "${1:-}" in
  --packages-only) mode=packages; shift; packages=("$@") ;;
  --cli) mode=cli; shift; packages=("${cli_packages[@]}" "$@") ;;
  *) packages=("${cli_packages[@]}" "${test_packages[@]}") ;;
esac
missing=()
for p in "${packages[@]}"; do
  # npm may come with a Node.js that is no Debian package of that name (NodeSource's
  # nodejs provides it and conflicts with Debian's npm): the command is what counts.
  [ "$p" = npm ] && command -v npm > /dev/null && continue
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

[ "$mode" = packages ] && exit 0
jobs=$(nproc 2>/dev/null || echo 2)
# A new build directory is generated for Ninja when present (its log,
# .ninja_log, gives each unit's compile time); one configured earlier keeps
# its generator.
generator=()
[ ! -f build/CMakeCache.txt ] && command -v ninja > /dev/null && generator=(-G Ninja)
if [ "$mode" = cli ]; then
  # A build configured earlier for everything keeps its settings.
  configure=(); [ -f build/CMakeCache.txt ] || configure=(-DBUILD_TESTING=OFF)
  cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release "${configure[@]}" > build-configure.log 2>&1 \
    || { cat build-configure.log; exit 1; }
  cmake --build build -j "$jobs" --target k_set_tilable
  exit 0
fi
cmake -S . -B build "${generator[@]}" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=ON > build-configure.log 2>&1 \
  || { cat build-configure.log; exit 1; }
cmake --build build -j "$jobs" "$@"
