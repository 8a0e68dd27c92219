#!/usr/bin/env bash
# README's first command: set up, build, and run the main job on a bundled surface.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
./build/bin/quad_shape_statistics examples/Tilable_surfaces/data/seashell.off
