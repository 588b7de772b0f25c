#!/usr/bin/env bash
# Whole-process scale benchmark: generated CAM-style programs through `drycut check`,
# `drycut path --csv /dev/null --step 1` and `drycut run`, timed with /usr/bin/time -v.
# Reports blocks/s (wall and CPU = user + system, the one-core rate even on a busy machine)
# and peak RSS. Optionally compares with LinuxCNC's standalone interpreter rs274 on the same
# RS274 program (installed here with apt-get when missing; never a dependency of drycut).
#
# Usage: bench/scale/run_scale.sh [drycut binary] [figures file]
# Environment: SIZES="1000000 10000000" (G1 program sizes), ASPLINE_SIZE=1000000,
#              COMMANDS="check path run", PEER=1 (0 skips rs274), PEER_SIZE=1000000,
#              WORK=/tmp/drycut_scale
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
DRYCUT=$(readlink -f "${1:-build/drycut}")
OUT=${2:-/tmp/drycut_scale_figures.txt}
WORK=${WORK:-/tmp/drycut_scale}
SIZES=${SIZES:-"1000000 10000000"}
ASPLINE_SIZE=${ASPLINE_SIZE:-1000000}
COMMANDS=${COMMANDS:-"check path run"}
PEER=${PEER:-1}
PEER_SIZE=${PEER_SIZE:-1000000}
mkdir -p "$WORK"
: > "$OUT"

# Seconds from /usr/bin/time's "h:mm:ss" or "m:ss.ss".
wall_seconds() {
  grep "Elapsed (wall clock)" "$1" | awk -F': ' '{print $2}' |
    awk -F: '{ if (NF == 3) print $1*3600 + $2*60 + $3; else print $1*60 + $2 }'
}
cpu_seconds() { awk -F': ' '/User time|System time/ { t += $2 } END { print t }' "$1"; }
peak_rss_mb() { awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$1"; }

# measure LABEL BLOCKS COMMAND... : runs the command under /usr/bin/time -v and records a line.
measure() {
  local label=$1 blocks=$2; shift 2
  local t="$WORK/time.txt" rc=0
  /usr/bin/time -v "$@" > "$WORK/stdout.txt" 2> "$t" || rc=$?
  local wall cpu rss
  wall=$(wall_seconds "$t"); cpu=$(cpu_seconds "$t"); rss=$(peak_rss_mb "$t")
  local line
  line=$(awk -v l="$label" -v n="$blocks" -v w="$wall" -v c="$cpu" -v r="$rss" -v rc="$rc" 'BEGIN {
    printf "%-28s blocks=%-9d wall_s=%-7.2f cpu_s=%-7.2f Mblocks_s_wall=%-6.2f Mblocks_s_cpu=%-6.2f peak_RSS_MB=%-6s exit=%d",
           l, n, w, c, n / (w > 0 ? w : 1e-9) / 1e6, n / (c > 0 ? c : 1e-9) / 1e6, r, rc }')
  echo "$line" | tee -a "$OUT"
  if [ "$rc" -gt 1 ]; then echo "  (exit $rc: see $WORK/time.txt)"; tail -5 "$t"; fi
}

run_commands() {  # $1 = label, $2 = blocks, $3 = file
  for c in $COMMANDS; do
    case $c in
      check) measure "check $1" "$2" "$DRYCUT" check "$3" ;;
      path) measure "path $1" "$2" "$DRYCUT" path -q "$3" --csv /dev/null --step 1 ;;
      run) measure "run $1" "$2" "$DRYCUT" run -q "$3" ;;
    esac
  done
}

for n in $SIZES; do
  f="$WORK/g1_${n}.mpf"
  "$here/generate_programs.sh" g1 "$n" "$f"
  run_commands "G1 spiral" "$n" "$f"
done
if [ "$ASPLINE_SIZE" -gt 0 ]; then
  f="$WORK/aspline_${ASPLINE_SIZE}.mpf"
  "$here/generate_programs.sh" aspline "$ASPLINE_SIZE" "$f"
  run_commands "ASPLINE spiral" "$ASPLINE_SIZE" "$f"
fi

if [ "$PEER" = 1 ]; then
  # The peer: LinuxCNC's rs274 (interpreter only, prints canonical machining calls).
  if ! command -v rs274 > /dev/null; then
    if [ "$(id -u)" = 0 ]; then
      { apt-get install -y --no-install-recommends linuxcnc-uspace || true; } 2>&1 | tail -3 | tee -a "$OUT"
    fi
  fi
  if command -v rs274 > /dev/null; then
    n=$PEER_SIZE
    f="$WORK/rs274_${n}.ngc"
    "$here/generate_programs.sh" rs274 "$n" "$f"
    # Both read the same file; drycut plans it fully (run), rs274 only interprets it.
    measure "drycut check (RS274 file)" "$n" "$DRYCUT" check "$f"
    measure "drycut run (RS274 file)" "$n" "$DRYCUT" run -q "$f"
    measure "rs274 -g > /dev/null" "$n" sh -c "rs274 -g '$f' /dev/null < /dev/null"
  else
    echo "rs274 not available: peer comparison skipped" | tee -a "$OUT"
  fi
fi
echo "figures written to $OUT"
