#!/usr/bin/env bash
# Browser test of `drycut report`: renders a report in headless Chromium and checks that
#  1. the plots are in the DOM the browser built (--dump-dom): each <svg> with its id, and
#     painted elements (polylines, circles) inside them;
#  2. the screenshot is not blank. Without a PNG decoder (zlib is not a dependency) this compares
#     the PNG's size with a screenshot of an empty page of the same window size: PNG compresses
#     a uniform page to a few kB, a page with plots, text and colours to many times that.
# Fails when no Chromium is found; skips (exit 77) only when DRYCUT_NO_BROWSER=1 is set.
# Usage: render_report_test.sh PATH/TO/drycut
set -euo pipefail

drycut="${1:?usage: render_report_test.sh PATH/TO/drycut}"

source "$(dirname "$0")/find_browser.sh"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# A circle (on the reference r = 10), a corner and a short zigzag: dips, knots, alarms-free.
cat > "$work/BROWSER.MPF" <<'NC'
N10 G0 X10 Y0
N20 G64 SOFT F3000
N30 G2 X10 Y0 I-10 J0
N40 G1 X14 Y0
N50 X14 Y6
N60 X12 Y7 ; corner & <tag> shown as text
N70 X10 Y0
N80 M30
NC
"$drycut" report "$work/BROWSER.MPF" -o "$work/report.html" --polar 10 -q
echo '<!DOCTYPE html><html><head><meta charset="utf-8"></head><body></body></html>' > "$work/blank.html"

flags=(--headless --no-sandbox --disable-gpu --disable-quic --no-first-run --disable-background-networking
       --disable-component-update --disable-sync --hide-scrollbars)

render() {  # render NAME MODE... : fresh profile per run, output in the work dir
  local page="$1"; shift
  timeout 120 "$browser" "${flags[@]}" --user-data-dir="$(mktemp -d -p "$work")" "$@" "file://$work/$page" 2>/dev/null
}

render report.html --dump-dom > "$work/dom.html"
fail=0
for id in top-view velocity-time velocity-length deviation; do
  if ! grep -q "<svg id=\"$id\"" "$work/dom.html"; then
    echo "FAILED: <svg id=\"$id\"> is not in the rendered DOM"
    fail=1
  fi
done
polylines=$(grep -o '<polyline' "$work/dom.html" | wc -l)
circles=$(grep -o '<circle' "$work/dom.html" | wc -l)
echo "DOM: $polylines polylines, $circles circles"
if (( polylines < 20 || circles < 5 )); then
  echo "FAILED: too few painted SVG elements in the DOM"
  fail=1
fi
if grep -q '<tag>' "$work/dom.html"; then
  echo "FAILED: block text became markup"
  fail=1
fi

(cd "$work" && render report.html --screenshot="$work/report.png" --window-size=1200,1600 >/dev/null)
(cd "$work" && render blank.html --screenshot="$work/blank.png" --window-size=1200,1600 >/dev/null)
for png in report.png blank.png; do
  if [[ ! -s "$work/$png" ]]; then
    echo "FAILED: Chromium wrote no $png"
    exit 1
  fi
done
report_size=$(stat -c %s "$work/report.png")
blank_size=$(stat -c %s "$work/blank.png")
echo "screenshot: report $report_size bytes, blank page $blank_size bytes"
if (( report_size < 8 * blank_size )); then
  echo "FAILED: the report screenshot is not much larger than a blank page's: nothing painted?"
  fail=1
fi
if [[ -n "${DRYCUT_KEEP_SCREENSHOT:-}" ]]; then cp "$work/report.png" "$DRYCUT_KEEP_SCREENSHOT"; fi
exit $fail
