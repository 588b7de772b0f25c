#!/usr/bin/env bash
# The reference experiment's machining times, predicted vs measured (a benchmark, not a test):
# builds drycut if needed, runs `drycut experiment` on the embedded MCV 1210 profile and keeps the
# table and its JSON beside this script.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
[[ -x "$root/build/drycut" ]] || "$root/scripts/build.sh"
out="$root/bench/thesis-times"
"$root/build/drycut" experiment --json "$out/experiment.json" | tee "$out/table.txt"
