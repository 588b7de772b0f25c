#!/usr/bin/env bash
# Configures and builds drycut (Release) into ./build after installing missing packages.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh "$@"
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
