#!/usr/bin/env bash
# Renders an input surface and its tilable result side by side, at the same
# camera (fitted to the input's bounding box), so fidelity can be judged by eye.
#   bash scripts/side_by_side.sh INPUT.off RESULT.ply OUTPUT.png [extra f3d options]
# INPUT is an ASCII OFF (its bounding box sets the camera); RESULT a PLY with
# per-face colours (k_set_tilable -o RESULT.ply). Needs Debian's f3d, xvfb,
# xauth and imagemagick (scripts/demo.sh installs them).
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 INPUT.off RESULT.ply OUTPUT.png [f3d options]" >&2; exit 2; }
input=$1; result=$2; out=$3; shift 3
for tool in f3d xvfb-run; do
  command -v "$tool" >/dev/null || { echo "side_by_side: $tool is missing (apt-get install f3d xvfb xauth)" >&2; exit 1; }
done
convert=/usr/bin/convert
[ -x "$convert" ] || convert=$(command -v convert) ||
  { echo "side_by_side: convert is missing (apt-get install imagemagick)" >&2; exit 1; }

# Bounding box of the OFF's vertices (comments and blank lines skipped).
read -r cx cy cz dist < <(awk '
  /^[ \t]*#/ || NF == 0 { next }
  state == 0 { state = 1; if ($1 ~ /OFF/) { if (NF >= 4) { nv = $2; state = 2 }; next } }
  state == 1 { nv = $1; state = 2; next }
  state == 2 && seen < nv {
    for (i = 1; i <= 3; ++i) {
      if (seen == 0 || $i < lo[i]) lo[i] = $i
      if (seen == 0 || $i > hi[i]) hi[i] = $i
    }
    ++seen
  }
  END {
    d = sqrt((hi[1]-lo[1])^2 + (hi[2]-lo[2])^2 + (hi[3]-lo[3])^2)
    # distance at which the diagonal fills the 23 degree view angle, plus a margin
    printf "%.9g %.9g %.9g %.9g\n", (lo[1]+hi[1])/2, (lo[2]+hi[2])/2, (lo[3]+hi[3])/2, 2.2 * d
  }' "$input")

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
camera=(--up=+Z --camera-focal-point="$cx,$cy,$cz" --camera-position="$cx,$(awk -v y="$cy" -v d="$dist" 'BEGIN{printf "%.9g", y - d}'),$cz"
        --camera-view-up=0,0,1 --camera-azimuth-angle=35 --camera-elevation-angle=30 --camera-view-angle=23)
render() {
  xvfb-run -a f3d "$1" --output "$2" --edges --resolution=800,700 --no-background "${camera[@]}" \
    "${@:3}" >/dev/null 2>&1 || true
  [ -s "$2" ] || { echo "side_by_side: f3d wrote no image for $1" >&2; exit 1; }
}
render "$input" "$tmp/input.png" "$@"
render "$result" "$tmp/result.png" --cells --scalars=RGBA --comp=-2 "$@"
"$convert" "$tmp/input.png" "$tmp/result.png" +append "$out"
