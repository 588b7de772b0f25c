#!/bin/sh
# Writes the reference experiment's 48 programs into this folder (24 progressive 3-D finishing
# programs, 24 single-loop 2-D programs, each a main .MPF and a subprogram .SPF).
# Usage: programs/thesis/generate.sh [path/to/drycut]   (default: build/drycut)
set -e
here=$(cd "$(dirname "$0")" && pwd)
drycut=${1:-"$here/../../build/drycut"}
"$drycut" generate --thesis "$here"
