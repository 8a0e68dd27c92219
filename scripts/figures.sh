#!/usr/bin/env bash
# Regenerates the pictures of the manual, README and results.md:
# every bundled surface at one of the paper's K values, input and result at
# the same camera, in doc/Tilable_surfaces/fig/<surface>_side_by_side.png.
# Needs the build (scripts/setup.sh) and the picture tools (scripts/demo.sh
# installs them). Prints each run's summary line.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh --packages-only f3d xvfb xauth imagemagick
data=examples/Tilable_surfaces/data
fig=doc/Tilable_surfaces/fig
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for surface_k in seashell:60 tunnel:10 monkey_saddle:24 swiss_re:9 decocube:9 de_beers_ginza:27; do
  surface=${surface_k%:*}; k=${surface_k#*:}
  ./build/bin/k_set_tilable "$data/$surface.off" -k "$k" -o "$tmp/$surface.ply" --quiet 2>&1 | tail -1
  bash scripts/side_by_side.sh "$data/$surface.off" "$tmp/$surface.ply" "$fig/${surface}_side_by_side.png"
done
# The demo's surface alone and its edge-sharing components (paper Fig. 6).
./build/bin/k_set_tilable "$data/seashell.off" -k 60 -o "$tmp/seashell_k60.ply" \
  --components "$tmp/seashell_k60_edges.ply" --quiet 2>/dev/null
bash scripts/render.sh "$tmp/seashell_k60.ply" "$fig/seashell_k60.png"
bash scripts/render.sh "$tmp/seashell_k60_edges.ply" "$fig/seashell_k60_edges.png"
# The demo's HTML report in headless chromium, a panel clicked (as the browser test opens it).
bash test/Tilable_surfaces/html_report_browser_test.sh build/bin/k_set_tilable "$data/seashell.off" 60 \
  "$tmp/browser" "$fig/seashell_html_report.png" ||
  echo "figures: no picture of the HTML report (it needs chromium and npm)"
