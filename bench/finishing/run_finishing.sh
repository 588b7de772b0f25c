#!/usr/bin/env bash
# CAM finishing programs (issue 13): the reference contour and a free-form surface at
# 0.02-0.2 mm chords, at 100 k and 1 M blocks, each with a header variant (none, G642, G645,
# COMPCAD, CYCLE832(0.01,1) ...), through `drycut run`: planned time, lowest feed while
# cutting, number of feed dips, CPU time and blocks/s, in one table.
#
# Usage: bench/finishing/run_finishing.sh [drycut] [figures file]
# Environment: SIZES="100000 1000000", KINDS="contour surface",
#              VARIANTS="none G642 G645 COMPCAD CYCLE832(0.01,1)" (space-separated blocks; none =
#              no header block), WORK=/tmp/drycut_finishing
# A variant drycut does not take (an alarm: the run stops there) shows as "alarm N" in the time
# column.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
DRYCUT=$(readlink -f "${1:-build/drycut}")
OUT=${2:-/tmp/drycut_finishing_figures.txt}
WORK=${WORK:-/tmp/drycut_finishing}
SIZES=${SIZES:-"100000 1000000"}
KINDS=${KINDS:-"contour surface"}
VARIANTS=${VARIANTS:-"none G642 G645 COMPCAD CYCLE832(0.01,1)"}
mkdir -p "$WORK"
: > "$OUT"

echo "| program | blocks | header | planned time s | lowest feed mm/min | dips | CPU s | M blocks/s | peak RSS MB |" | tee -a "$OUT"
echo "|---|---|---|---|---|---|---|---|---|" | tee -a "$OUT"
for kind in $KINDS; do
  for n in $SIZES; do
    for variant in $VARIANTS; do
      tag=$(echo "$variant" | tr -c 'A-Za-z0-9\n' '_')
      f="$WORK/${kind}_${n}_${tag}.mpf"
      header=$([ "$variant" = none ] && echo "" || echo "$variant")
      [ -s "$f" ] || python3 "$here/generate_finishing.py" "$kind" "$n" "$f" "$header"
      rc=0
      /usr/bin/time -f "%U %S %M" -o "$WORK/time.txt" "$DRYCUT" run -q "$f" > "$WORK/stdout.txt" 2> "$WORK/stderr.txt" || rc=$?
      awk -v k="$kind" -v n="$n" -v v="$variant" -v rc="$rc" -v tf="$WORK/time.txt" '
        /^  time  / && !t { t = $2 }
        /INCOMPLETE: stopped by alarm/ { alarm = $5 }
        /^  feed while cutting/ { low = $4 }
        /^  feed dips below/ { dips = $NF }
        END {
          getline line < tf; split(line, x, " ")
          cpu = x[1] + x[2]; rss = x[3] / 1024
          if (alarm != "") t = "alarm " alarm " (incomplete)"
          if (rc > 1) t = "alarm (exit " rc ")"
          printf "| %s | %d | %s | %s | %s | %s | %.2f | %.2f | %.1f |\n", k, n, v, t, low == "" ? "-" : low,
                 dips == "" ? "0" : dips, cpu, n / (cpu > 0 ? cpu : 1e-9) / 1e6, rss
        }' "$WORK/stdout.txt" | tee -a "$OUT"
    done
  done
done
echo "figures written to $OUT"
