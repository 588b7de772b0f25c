#!/usr/bin/env bash
# The README's test command: set-up (including Debian's chromium for the browser test), build,
# and every test (GoogleTest through CTest).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh --with-browser
ctest --test-dir build --output-on-failure -j"$(nproc)"
