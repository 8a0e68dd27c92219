#!/usr/bin/env bash
# README's first command: set up, build the command-line program (only it), and
# make the bundled seashell 60-set tilable, with its report, tile catalog and
# pictures (the result beside the input at the same camera) in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
# The pictures need a headless renderer: Debian's f3d under Xvfb.
bash scripts/setup.sh --cli f3d xvfb xauth imagemagick

mkdir -p out
./build/bin/k_set_tilable examples/Tilable_surfaces/data/seashell.off -k 60 \
  -o out/seashell_k60.ply --report out/seashell_k60_report.json \
  --catalog out/seashell_k60_tiles.csv --components out/seashell_k60_edges.ply
bash scripts/render.sh out/seashell_k60.ply out/seashell_k60.png
bash scripts/render.sh out/seashell_k60_edges.ply out/seashell_k60_edges.png
bash scripts/side_by_side.sh examples/Tilable_surfaces/data/seashell.off out/seashell_k60.ply \
  out/seashell_k60_side_by_side.png

echo
echo "demo: wrote"
for f in out/seashell_k60.ply out/seashell_k60_report.json out/seashell_k60_tiles.csv \
         out/seashell_k60_edges.ply out/seashell_k60.png out/seashell_k60_edges.png \
         out/seashell_k60_side_by_side.png; do
  echo "  $(pwd)/$f"
done
