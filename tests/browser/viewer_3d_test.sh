#!/usr/bin/env bash
# Browser test of the report's 3D view: renders a `drycut report` page in headless Chromium with
# software WebGL (SwiftShader) and lets the page test itself (trace_viewer.js, URL hash
# #selftest): it reads the drawn canvas back and checks that the pixels where path samples
# project are painted and pixels away from the path are not, moves the playback bar from the
# first to the last sample and checks that the shown block changes, and steps back a block with
# shift + left arrow, then plays the program to its end. The verdict lands in the DOM, which --dump-dom prints; this script checks
# it and which blocks were shown. Then, with WebGL disabled, that the page says so.
# Needs Chromium and Debian's libjs-three (scripts/setup-debian.sh --with-browser installs both).
# Fails when either is missing; skips (exit 77) only when DRYCUT_NO_BROWSER=1 is set.
# Usage: viewer_3d_test.sh PATH/TO/drycut
set -euo pipefail

drycut="${1:?usage: viewer_3d_test.sh PATH/TO/drycut}"

source "$(dirname "$0")/find_browser.sh"

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

# In 3D: a rapid down to Z5, a plunge, a full circle, a corner, a ramp up in Z, a retract.
cat > "$work/VIEW3D.MPF" <<'NC'
N10 G0 X10 Y0 Z5
N20 G64 SOFT F3000
N30 G1 Z-1 F500
N40 G2 X10 Y0 I-10 J0 F3000
N50 G1 X14 Y0
N60 X14 Y6 Z1
N70 X12 Y7 ; corner & <tag> shown as text
N80 X10 Y0 Z-1
N90 G0 Z20
N100 M30
NC
"$drycut" report "$work/VIEW3D.MPF" -o "$work/report.html" -q
if grep -q 'id="trace-viewer-missing"' "$work/report.html"; then
  echo "FAILED: the report has no 3D view:"
  grep -o 'id="trace-viewer-missing"[^<]*' "$work/report.html"
  echo "(install Debian's libjs-three: scripts/setup-debian.sh)"
  exit 1
fi

# Software WebGL: SwiftShader through ANGLE (recent Chromium wants it allowed explicitly).
flags=(--headless --no-sandbox --use-gl=angle --use-angle=swiftshader --enable-unsafe-swiftshader
       --disable-quic --no-first-run --disable-background-networking --disable-component-update
       --disable-sync --hide-scrollbars --window-size=1200,1600)
timeout 120 "$browser" "${flags[@]}" --user-data-dir="$work/profile" --virtual-time-budget=10000 --dump-dom \
  "file://$work/report.html#selftest" > "$work/dom.html" 2>/dev/null || true

verdict="$(grep -o '<pre id="trace-selftest">[^<]*' "$work/dom.html" | sed 's/<pre id="trace-selftest">//' || true)"
if [[ -z "$verdict" ]]; then
  status="$(grep -o 'id="trace-status"[^>]*>[^<]*' "$work/dom.html" || true)"
  echo "FAILED: the viewer wrote no self-test verdict (did WebGL start? status: ${status:-none})"
  exit 1
fi
echo "viewer: $verdict"
fail=0
[[ "$verdict" == *"VERDICT PASS"* ]] || { echo "FAILED: the viewer's self-test failed"; fail=1; }
# The playback bar at its start shows the first block, at its end the last motion (N90), and
# shift + left arrow the block before it (N80); block text stays text (&lt;tag&gt; in the DOM).
[[ "$verdict" == *"block at start [VIEW3D.MPF:1 N10 G0 X10 Y0 Z5]"* ]] || { echo "FAILED: wrong first block"; fail=1; }
[[ "$verdict" == *"block at end [VIEW3D.MPF:9 N90 G0 Z20]"* ]] || { echo "FAILED: wrong last block"; fail=1; }
[[ "$verdict" == *"shift+left shows [VIEW3D.MPF:8 N80 X10 Y0 Z-1]"* ]] || { echo "FAILED: shift+left arrow did not go back to N80"; fail=1; }
# After the checks the page plays the program from the start at the highest speed.
playback="$(grep -o '<pre id="trace-selftest-playback">[^<]*' "$work/dom.html" | sed 's/<pre id="trace-selftest-playback">//' || true)"
echo "playback: ${playback:-none}"
if [[ ! "$playback" =~ ^"playback at sample "([0-9]+)" of "([0-9]+)", playing false, block [VIEW3D.MPF:9 N90 G0 Z20]"$ ]] ||
   [[ "${BASH_REMATCH[1]}" != "${BASH_REMATCH[2]}" ]]; then
  echo "FAILED: playing did not run the trace to its end"
  fail=1
fi
if grep -q '<tag>' "$work/dom.html"; then
  echo "FAILED: block text became markup"
  fail=1
fi
# A browser without WebGL gets a note instead of the view (and the rest of the page).
timeout 120 "$browser" "${flags[@]}" --disable-webgl --disable-3d-apis --user-data-dir="$work/profile-nogl" \
  --dump-dom "file://$work/report.html" > "$work/dom-nogl.html" 2>/dev/null || true
if ! grep -q 'id="trace-status" class="note">WebGL is not available' "$work/dom-nogl.html" ||
   ! grep -q '<svg id="top-view"' "$work/dom-nogl.html"; then
  echo "FAILED: without WebGL the page does not say so or lost its top view"
  fail=1
fi
exit $fail
