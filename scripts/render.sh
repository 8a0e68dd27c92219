#!/usr/bin/env bash
# Renders a PLY with per-face colours to a PNG, headless (f3d under Xvfb).
#   bash scripts/render.sh INPUT.ply OUTPUT.png [extra f3d options]
# Needs Debian's f3d, xvfb and xauth (scripts/demo.sh installs them).
set -euo pipefail
[ $# -ge 2 ] || { echo "usage: $0 INPUT.ply OUTPUT.png [f3d options]" >&2; exit 2; }
in=$1; out=$2; shift 2
for tool in f3d xvfb-run; do
  command -v "$tool" >/dev/null || { echo "render: $tool is missing (apt-get install f3d xvfb xauth)" >&2; exit 1; }
done
xvfb-run -a f3d "$in" --output "$out" --cells --scalars=RGBA --comp=-2 --edges \
  --resolution=1000,800 --up=+Z --camera-azimuth-angle=35 --camera-elevation-angle=30 \
  --camera-view-angle=23 --no-background "$@" >/dev/null 2>&1 || true
[ -s "$out" ] || { echo "render: f3d wrote no image for $in" >&2; exit 1; }
