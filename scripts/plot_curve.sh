#!/usr/bin/env bash
# Draws the K / deviation curve that `k_set_tilable --sweep ... --curve CURVE.csv`
# (or --max-deviation ... --curve) writes: the symmetric Hausdorff distance to
# the input (% of the bounding-box diagonal) against K, tilable results as
# filled points, others as crosses, and the degree of flexibility on the right
# axis. Headless, with gnuplot (installed here if missing).
#   bash scripts/plot_curve.sh CURVE.csv CURVE.png
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 CURVE.csv CURVE.png" >&2; exit 2; }
curve=$1; out=$2
[ -r "$curve" ] || { echo "plot_curve: cannot read '$curve'" >&2; exit 2; }
[ "$(head -n 1 "$curve" | cut -d, -f1,4,7)" = "K,hausdorff_distance,tilable" ] ||
  { echo "plot_curve: '$curve' is not a k_set_tilable curve (header K,DOF,congruence_error,...)" >&2; exit 2; }
command -v gnuplot >/dev/null ||
  bash "$(dirname "$0")/setup.sh" --packages-only gnuplot-nox

# The rows sorted by K: a deviation search writes them in the order tried.
sorted=$(mktemp)
trap 'rm -f "$sorted"' EXIT
tail -n +2 "$curve" | sort -t, -k1,1n > "$sorted"
[ -s "$sorted" ] || { echo "plot_curve: '$curve' has no rows" >&2; exit 2; }

gnuplot <<GNUPLOT
set terminal pngcairo size 900,540 font ",11"
set output "$out"
set datafile separator ","
set title "What each mold buys: deviation from the input against K"
set xlabel "K (distinct molds)"
set ylabel "symmetric Hausdorff distance (% of bounding-box diagonal)"
set y2label "degree of flexibility"
set ytics nomirror
set y2tics
set grid
set key below
set yrange [0:*]
set y2range [0:*]
plot "$sorted" using 1:(\$7 == 1 ? 100 * \$4 : 1/0) with linespoints pt 7 lc rgb "#1f77b4" title "tilable (congruence <= 1e-6)", \
     "$sorted" using 1:(\$7 == 1 ? 1/0 : 100 * \$4) with points pt 2 ps 1.5 lc rgb "#d62728" title "not tilable", \
     "$sorted" using 1:2 axes x1y2 with steps lc rgb "#7f7f7f" dt 2 title "DOF"
GNUPLOT
echo "plot_curve: wrote $out"
