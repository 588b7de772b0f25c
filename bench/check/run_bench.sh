#!/usr/bin/env bash
# Benchmark of `drycut check` on generated CAM-style programs (1M and 10M lines).
# Usage: bench/check/run_bench.sh [path/to/drycut] [output figures file]
# Prints lines/s and peak RSS per size and writes them to the figures file.
set -euo pipefail
DRYCUT=${1:-build/drycut}
OUT=${2:-/tmp/drycut_check_bench.txt}
WORK=/tmp/drycut_check_bench
mkdir -p "$WORK"

generate() {  # $1 = number of lines, $2 = file
  [ -f "$2" ] && return
  awk -v n="$1" 'BEGIN {
    print "N1 G54 G17 G90 G64 SOFT"
    for (i = 2; i < n; i++)
      printf "N%d G1 X%.3f Y%.3f Z%.3f F1500\n", i, 12.345 + (i % 1000) * 0.001, -6.789 + (i % 777) * 0.002, 0.123 - (i % 91) * 0.001
    printf "N%d M30\n", n
  }' > "$2"
}

: > "$OUT"
for n in 1000000 10000000; do
  f="$WORK/cam_${n}.mpf"
  generate "$n" "$f"
  /usr/bin/time -v "$DRYCUT" check "$f" > "$WORK/out.txt" 2> "$WORK/time.txt"
  secs=$(grep "Elapsed (wall clock)" "$WORK/time.txt" | awk -F': ' '{print $2}' | awk -F: '{ if (NF == 3) print $1*3600 + $2*60 + $3; else print $1*60 + $2 }')
  # CPU time (user + system) gives the one-core rate even on a busy machine.
  cpu=$(awk -F': ' '/User time|System time/ { t += $2 } END { print t }' "$WORK/time.txt")
  rss=$(grep "Maximum resident set size" "$WORK/time.txt" | awk -F': ' '{print $2}')
  size=$(stat -c %s "$f")
  rate=$(awk -v n="$n" -v s="$secs" 'BEGIN { printf "%.2f", n / s / 1e6 }')
  cpu_rate=$(awk -v n="$n" -v s="$cpu" 'BEGIN { printf "%.2f", n / s / 1e6 }')
  line="lines=$n file_MB=$((size / 1000000)) wall_s=$secs Mlines_per_s_wall=$rate cpu_s=$cpu Mlines_per_s_cpu=$cpu_rate peak_RSS_MB=$((rss / 1024))"
  echo "$line" | tee -a "$OUT"
done
