#!/usr/bin/env bash
# Builds the HTML reference manual from doc/Tilable_surfaces/ (doxygen) and
# fails on any doxygen warning. Installs doxygen when it is missing.
#
# Usage: doc.sh [OUTPUT_DIR]     default build/doc; the manual is OUTPUT_DIR/html/index.html
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-build/doc}"
command -v doxygen > /dev/null || bash scripts/setup.sh --packages-only doxygen
mkdir -p "$out"
rm -rf "$out/html" "$out/warnings.log"
# The Doxyfile with the output directory and the warning log under $out.
{ cat doc/Tilable_surfaces/Doxyfile
  echo "OUTPUT_DIRECTORY = \"$out\""
  echo "WARN_LOGFILE = \"$out/warnings.log\""; } | doxygen - > "$out/doxygen.log" 2>&1 \
  || { cat "$out/doxygen.log"; echo "doc: doxygen failed" >&2; exit 1; }
# Warnings go to the log file, except those about the configuration itself.
# Those in /usr/include are the libraries' own (read only for their macros,
# such as CGAL's named parameters): not ours to fix.
warnings=$( { grep -i "warning" "$out/doxygen.log" || true; cat "$out/warnings.log" 2>/dev/null || true; } \
            | { grep -v "^/usr/include/" || true; } )
if [ -n "$warnings" ]; then
  echo "$warnings"
  echo "doc: $(echo "$warnings" | wc -l) doxygen warning line(s), see above" >&2
  exit 1
fi
[ -f "$out/html/index.html" ] || { echo "doc: no $out/html/index.html" >&2; exit 1; }
echo "doc: $out/html/index.html"
