# Sourced by the browser tests: skips (exit 77) when DRYCUT_NO_BROWSER=1 is set, fails when no
# Chromium is found, else sets $browser to its path.
if [[ "${DRYCUT_NO_BROWSER:-}" == "1" ]]; then
  echo "SKIPPED: DRYCUT_NO_BROWSER=1 is set"
  exit 77
fi
browser=""
for candidate in chromium chromium-browser google-chrome; do
  if command -v "$candidate" >/dev/null 2>&1; then
    browser="$(command -v "$candidate")"
    break
  fi
done
if [[ -z "$browser" ]]; then
  echo "FAILED: no Chromium found (install it: scripts/setup-debian.sh --with-browser;" \
       "or set DRYCUT_NO_BROWSER=1 to skip this test explicitly)"
  exit 1
fi
