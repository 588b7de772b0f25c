#!/usr/bin/env bash
# Builds everything with AddressSanitizer + UndefinedBehaviorSanitizer (-DDRYCUT_SANITIZE=ON,
# Debug at -O1 to keep CI time reasonable; -g1 keeps the file:line of sanitizer stack traces but
# drops variable debug info, which cut the compile time of a TU by 30-45 %) in its own build folder and runs the whole CTest
# suite. Any sanitizer report stops the process (halt_on_error) and so fails its test; leaks
# count (detect_leaks). The end-to-end tests run the sanitized drycut binary, which inherits
# these options. Usage: scripts/sanitize.sh [build dir]   (default: build-sanitize)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${1:-$root/build-sanitize}
jobs=${JOBS:-2}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-g1 -O1" \
  -DDRYCUT_SANITIZE=ON -DDRYCUT_BUILD_TESTS=ON
cmake --build "$build" -j "$jobs"

export ASAN_OPTIONS=halt_on_error=1:abort_on_error=1:detect_leaks=1:detect_stack_use_after_return=1:strict_string_checks=1
export UBSAN_OPTIONS=halt_on_error=1:abort_on_error=1:print_stacktrace=1
# The install (packaging) and browser (Chromium rendering) tests check no memory use of drycut's
# own that the report tests do not run already; they run in scripts/test.sh.
ctest --test-dir "$build" --output-on-failure -j "$jobs" --timeout 900 -LE "^(install|browser)$"
