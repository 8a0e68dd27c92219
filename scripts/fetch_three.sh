#!/usr/bin/env bash
# Fetches three.js from the npm registry into a directory of the build, for
# the HTML report of `k_set_tilable --html`, which embeds it so that the page
# needs no network when it is opened. Run by the build (target three_js).
#
# Usage: fetch_three.sh VERSION DIR
# Writes DIR/three.module.min.js, DIR/OrbitControls.js and DIR/LICENSE, and
# exits 0; without npm or the registry it writes nothing and still exits 0 (the
# build goes on, and k_set_tilable says that --html is not available).
set -uo pipefail
version=$1
dir=$2
if ! command -v npm > /dev/null; then
  echo "fetch_three: npm not found: k_set_tilable --html will not be available" >&2
  exit 0
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# No retries: an unreachable registry fails in seconds, not minutes.
if ! (cd "$work" && npm pack --silent --fetch-retries=0 "three@$version" > /dev/null) ||
   ! tar -xzf "$work/three-$version.tgz" -C "$work" package/build/three.module.min.js \
       package/examples/jsm/controls/OrbitControls.js package/LICENSE; then
  echo "fetch_three: could not fetch three@$version from the npm registry:" \
       "k_set_tilable --html will not be available" >&2
  exit 0
fi
mkdir -p "$dir"
cp "$work/package/build/three.module.min.js" "$work/package/examples/jsm/controls/OrbitControls.js" \
   "$work/package/LICENSE" "$dir/"
echo "fetch_three: three.js $version in $dir"
