#!/usr/bin/env bash
# The README's main job: build, then dry-run the reference programs on the embedded MCV 1210 profile.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/build.sh
./build/drycut experiment
