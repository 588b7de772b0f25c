#!/usr/bin/env bash
# Corner smoothing at its most expensive: every block transition a corner. A zig-zag of
# BLOCKS G1 blocks (2 mm, turning +-90 degrees alternately, and a 60-degree variant) under each
# header of VARIANTS, through `drycut run`: planned time, rounded corners, CPU time, blocks/s.
#
# Usage: bench/finishing/run_corners.sh [drycut]
# Environment: BLOCKS=100000, VARIANTS="G64 G642 G645 G643", WORK=/tmp/drycut_corners
set -euo pipefail
DRYCUT=$(readlink -f "${1:-build/drycut}")
BLOCKS=${BLOCKS:-100000}
VARIANTS=${VARIANTS:-"G64 G642 G645 G643"}
WORK=${WORK:-/tmp/drycut_corners}
mkdir -p "$WORK"
echo "| path | blocks | header | planned time s | corners rounded | CPU s | M blocks/s |"
echo "|---|---|---|---|---|---|---|"
for angle in 90 60; do
  for variant in $VARIANTS; do
    f="$WORK/zigzag_${angle}_${BLOCKS}_${variant}.mpf"
    [ -s "$f" ] || python3 - "$f" "$BLOCKS" "$variant" "$angle" <<'PY'
import math, sys
path, n, header, angle = sys.argv[1], int(sys.argv[2]), sys.argv[3], float(sys.argv[4])
half = math.radians(angle) / 2
with open(path, "w") as out:
    out.write("G90 G94 G17\nG0 X0 Y0 Z0\n%s SOFT F3000\n" % header)
    x = y = 0.0
    for i in range(n):
        # back and forth in rows of 200 blocks (the turn at a row end is a reversal: no rounding)
        x += 2 * math.cos(half) * (1 if (i // 200) % 2 == 0 else -1)
        y += 2 * math.sin(half) * (1 if i % 2 == 0 else -1)
        out.write("G1 X%.4f Y%.4f\n" % (x, y))
    out.write("M30\n")
PY
    /usr/bin/time -f "%U %S" -o "$WORK/time.txt" "$DRYCUT" run -q "$f" > "$WORK/out.txt" 2>&1 || true
    awk -v a="$angle" -v n="$BLOCKS" -v v="$variant" -v tf="$WORK/time.txt" '
      /^  time  / && !t { t = $2 }
      /INCOMPLETE/ { t = "incomplete" }
      /corner smoothing/ { c = $3 }
      END { getline line < tf; split(line, x, " "); cpu = x[1] + x[2]
            printf "| zig-zag %s deg | %d | %s | %s | %s | %.2f | %.2f |\n", a, n, v, t, c == "" ? 0 : c, cpu, n / (cpu > 0 ? cpu : 1e-9) / 1e6 }' "$WORK/out.txt"
  done
done
