#!/usr/bin/env bash
# The HTML report in a real browser (Debian's chromium, headless, driven by
# puppeteer-core from npm): the page of INPUT's K-set tilable result lists
# its K tiles, draws the 3D view (the canvas has pixels other than the
# background), and a click on a panel selects it (the panel's tile is told and
# its mold sheet marked). Exit 77 (skipped, ctest SKIP_RETURN_CODE) when
# chromium, npm or this build's three.js is missing.
#
# Usage: html_report_browser_test.sh K_SET_TILABLE INPUT K WORK_DIR [SCREENSHOT.png] [ORBIT_FRAMES]
#   ORBIT_FRAMES: also orbit the camera once in that many frames and print the
#   milliseconds per frame.
set -euo pipefail
program=$1 input=$2 k=$3 work=$4 screenshot=${5:-} frames=${6:-0}
here=$(cd "$(dirname "$0")" && pwd)
puppeteer_version=24.43.1

chromium=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium" ]; then
  echo "SKIPPED: chromium is not installed (as root: apt-get install -y chromium)"
  exit 77
fi
mkdir -p "$work"
if [ ! -d "$work/node_modules/puppeteer-core" ]; then
  if ! command -v npm > /dev/null ||
     ! npm install --prefix "$work" --silent --no-audit --no-fund --fetch-retries=0 \
         "puppeteer-core@$puppeteer_version" > "$work/npm.log" 2>&1; then
    echo "SKIPPED: puppeteer-core@$puppeteer_version could not be installed from npm (see $work/npm.log)"
    exit 77
  fi
fi

html="$work/$(basename "${input%.*}")_k$k.html"
if ! "$program" "$input" -k "$k" -q -o "$work/result.ply" --html "$html" > "$work/run.log" 2>&1; then
  if grep -q -- "--html is not available in this build" "$work/run.log"; then
    echo "SKIPPED: $(grep -- '--html is not available' "$work/run.log")"
    exit 77
  fi
  cat "$work/run.log"
  exit 1
fi
echo "html_report_browser_test: $html ($(stat -c %s "$html") bytes)"
CHROMIUM="$chromium" PUPPETEER_CORE="$work/node_modules/puppeteer-core" \
  node "$here/html_report_browser_check.js" "$html" "$k" "$screenshot" "$frames"
