#!/usr/bin/env bash
# Compressor benchmark (bench/compressor/README.md): G64 vs COMPON vs COMPCURV vs COMPCAD on a
# circle R20 in 0.05 mm chords and a wavy free-form line, BLOCKS (default 100000) G1 blocks each.
# Per program: machining time and lowest feed (`drycut run --json -`), CPU seconds and blocks/s of
# `drycut run` (/usr/bin/time), and the largest deviation of the planned path from the
# programmed points and lines measured independently by `drycut deviation --programmed-points`
# (nearest-segment search on sampled paths, not the compressor's own check).
# Usage: bench/compressor/run.sh [DRYCUT] [BLOCKS]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
drycut=$(realpath "${1:-$here/../../build/drycut}")
blocks=${2:-100000}
dir=${DIR:-/tmp/drycut_compressor_bench}
python3 "$here/generate.py" "$dir" "$blocks"
cd "$dir"
printf "%-20s %10s %12s %12s %12s %8s %12s\n" program time_s min_mm_min dev_path_mm dev_pts_mm cpu_s blocks/s
for shape in CIRCLE WAVY; do
  for mode in COMPOF COMPON COMPCURV COMPCAD; do
    p=${shape}_${mode}.MPF
    /usr/bin/time -f "%U %S %M" -o time.txt "$drycut" run "$p" -q --json run.json >/dev/null 2>&1 || true
    read -r user sys rss < time.txt
    "$drycut" deviation "$p" --programmed-points --step 0.01 --json dev.json >/dev/null 2>&1 || true
    python3 - "$p" "$user" "$sys" "$rss" "$blocks" <<'PY'
import json, sys
p, user, sys_, rss, blocks = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), int(sys.argv[4]), int(sys.argv[5])
s = json.load(open("run.json"))["summary"]
d = json.load(open("dev.json"))
cpu = user + sys_
print("%-20s %10.3f %12.1f %12.5f %12.5f %8.2f %12.0f   (peak RSS %d MB)" % (
    p, s["time_s"], s["min_feed_mm_min"], d["path_to_polyline"]["max_mm"], d["points_to_path"]["max_mm"], cpu,
    blocks / cpu if cpu > 0 else 0, rss // 1024))
PY
  done
done
