#!/usr/bin/env bash
# README's first command: set up, build the command-line program (only it), and
# make the bundled seashell 60-set tilable, with its report, tile catalog, HTML
# report, mold sheets and pictures (the result beside the input at the same
# camera) in out/.
set -euo pipefail
cd "$(dirname "$0")/.."
# The pictures need a headless renderer: Debian's f3d under Xvfb; the HTML
# report needs three.js, which the build fetches with npm.
bash scripts/setup.sh --cli f3d xvfb xauth imagemagick npm
html=(--html out/seashell_k60.html)
if ! ls build/three.js/*/three.module.min.js > /dev/null 2>&1; then
  echo "demo: three.js could not be fetched from the npm registry: no HTML report"
  html=()
fi

mkdir -p out
./build/bin/k_set_tilable examples/Tilable_surfaces/data/seashell.off -k 60 \
  -o out/seashell_k60.ply --report out/seashell_k60_report.json \
  --catalog out/seashell_k60_tiles.csv --components out/seashell_k60_edges.ply \
  --mold-sheets out/seashell_k60_sheets "${html[@]}"
bash scripts/render.sh out/seashell_k60.ply out/seashell_k60.png
bash scripts/render.sh out/seashell_k60_edges.ply out/seashell_k60_edges.png
bash scripts/side_by_side.sh examples/Tilable_surfaces/data/seashell.off out/seashell_k60.ply \
  out/seashell_k60_side_by_side.png

echo
echo "demo: wrote"
for f in out/seashell_k60.ply out/seashell_k60_report.json out/seashell_k60_tiles.csv \
         out/seashell_k60_sheets/ ${html[@]:1} out/seashell_k60_edges.ply out/seashell_k60.png \
         out/seashell_k60_edges.png out/seashell_k60_side_by_side.png; do
  echo "  $(pwd)/$f"
done
