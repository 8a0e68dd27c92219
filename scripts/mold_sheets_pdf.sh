#!/usr/bin/env bash
# Puts the mold sheets that `k_set_tilable --mold-sheets DIR` wrote into one
# PDF, one A4 page per tile in the order of their ids, each sheet fitted to the
# page (its scale bar gives the scale). Installs librsvg2-bin (rsvg-convert)
# when it is missing.
#
# Usage: mold_sheets_pdf.sh DIR OUT.pdf
set -euo pipefail
if [ $# -ne 2 ]; then
  echo "usage: $0 DIR OUT.pdf" >&2
  exit 2
fi
dir=$1 out=$2
shopt -s nullglob
sheets=("$dir"/tile_*.svg)
if [ ${#sheets[@]} -eq 0 ]; then
  echo "mold_sheets_pdf: no tile_*.svg in '$dir'" >&2
  exit 2
fi
command -v rsvg-convert > /dev/null ||
  bash "$(dirname "$0")/setup.sh" --packages-only librsvg2-bin
# A4 portrait, 15 mm margins: the sheet fills 180 x 267 mm, keeping its aspect.
rsvg-convert -f pdf --page-width 210mm --page-height 297mm --left 15mm --top 15mm \
  -w 180mm -h 267mm -a -o "$out" "${sheets[@]}"
echo "mold_sheets_pdf: ${#sheets[@]} sheets in $out"
