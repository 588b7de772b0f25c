#!/usr/bin/env bash
# Builds drycut (Release) and runs the whole-process scale benchmark (bench/scale/run_scale.sh).
# Usage: scripts/bench.sh [figures file]   (environment as in bench/scale/run_scale.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${BUILD_DIR:-$root/build-bench}
cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DDRYCUT_BUILD_TESTS=OFF > /dev/null
cmake --build "$build" --target drycut
exec "$root/bench/scale/run_scale.sh" "$build/drycut" "${1:-/tmp/drycut_scale_figures.txt}"
