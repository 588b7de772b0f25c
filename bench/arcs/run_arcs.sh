#!/usr/bin/env bash
# Arc benchmark (issue 17): tangent-continuous random arcs and helices through `drycut run`,
# side by side with LinuxCNC's interpreter `rs274` on the same path, in one run.
#
# Usage: bench/arcs/run_arcs.sh [drycut binary] [earlier drycut binary] [figures file]
#   The earlier binary (optional, e.g. built from the commit before the change) is run on the
#   same files: blocks/s before/after and the planned times, which must agree within 0.1 %.
# Environment: BLOCKS=200000, KINDS="mixed helix", MODES="G64_SOFT G64_BRISK G60 G60_SOFT"
#              (the planned-time comparison; throughput is measured on G64 SOFT),
#              WORK=/tmp/drycut_arcs, PEER=1 (0 skips rs274).
# rs274 comes from Debian's linuxcnc-uspace (installed with apt-get when missing and running as
# root; never a dependency of drycut). It reads the RS274 dialect file (no SOFT, otherwise the
# same lines); drycut reads both.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
DRYCUT=$(readlink -f "${1:-build/drycut}")
BEFORE=${2:-}
[ -n "$BEFORE" ] && BEFORE=$(readlink -f "$BEFORE")
OUT=${3:-/tmp/drycut_arcs_figures.txt}
WORK=${WORK:-/tmp/drycut_arcs}
BLOCKS=${BLOCKS:-200000}
KINDS=${KINDS:-"mixed helix"}
MODES=${MODES:-"G64_SOFT G64_BRISK G60 G60_SOFT"}
PEER=${PEER:-1}
mkdir -p "$WORK"
: > "$OUT"

cpu_seconds() { awk -F': ' '/User time|System time/ { t += $2 } END { print t }' "$1"; }
peak_rss_mb() { awk -F': ' '/Maximum resident set size/ { printf "%.1f", $2 / 1024 }' "$1"; }
planned_time() { awk '/^  time  / { print $2; exit }' "$1"; }

# measure LABEL COMMAND... : CPU time (user + system), blocks/s on one core, peak RSS.
measure() {
  local label=$1; shift
  local t="$WORK/time.txt" rc=0
  /usr/bin/time -v "$@" > "$WORK/stdout.txt" 2> "$t" || rc=$?
  local cpu rss planned
  cpu=$(cpu_seconds "$t"); rss=$(peak_rss_mb "$t"); planned=$(planned_time "$WORK/stdout.txt")
  awk -v l="$label" -v n="$BLOCKS" -v c="$cpu" -v r="$rss" -v rc="$rc" -v p="${planned:--}" 'BEGIN {
    printf "%-34s cpu_s=%-6.2f kblocks_s=%-7.0f peak_RSS_MB=%-6s planned_s=%-12s exit=%d\n",
           l, c, n / (c > 0 ? c : 1e-9) / 1e3, r, p, rc }' | tee -a "$OUT"
  cp "$WORK/stdout.txt" "$WORK/last_stdout.txt"
}

if [ "$PEER" = 1 ] && ! command -v rs274 > /dev/null && [ "$(id -u)" = 0 ]; then
  { apt-get install -y --no-install-recommends linuxcnc-uspace || true; } 2>&1 | tail -2
fi

for kind in $KINDS; do
  f="$WORK/${kind}_${BLOCKS}.mpf"; g="$WORK/${kind}_${BLOCKS}.ngc"
  [ -s "$f" ] || python3 "$here/generate_arcs.py" "$kind" "$BLOCKS" sinumerik "$f"
  [ -s "$g" ] || python3 "$here/generate_arcs.py" "$kind" "$BLOCKS" rs274 "$g"
  echo "== $kind: $BLOCKS blocks ($f)" | tee -a "$OUT"
  measure "drycut check" "$DRYCUT" check "$f"
  measure "drycut run (G64 SOFT)" "$DRYCUT" run -q "$f"
  [ -n "$BEFORE" ] && measure "earlier drycut run (G64 SOFT)" "$BEFORE" run -q "$f"
  if [ "$PEER" = 1 ] && command -v rs274 > /dev/null; then
    measure "drycut run (RS274 file)" "$DRYCUT" run -q "$g"
    [ -n "$BEFORE" ] && measure "earlier drycut run (RS274 file)" "$BEFORE" run -q "$g"
    # rs274 writes its canonical machining calls to a file; PROGRAM_END shows it read to M30.
    measure "rs274 -g (RS274 file)" sh -c "rs274 -g '$g' '$WORK/rs274_calls.txt' < /dev/null"
    echo "  rs274: $(grep -c . "$WORK/rs274_calls.txt") canonical calls, $(grep -c PROGRAM_END "$WORK/rs274_calls.txt") PROGRAM_END" |
      tee -a "$OUT"
  fi
  if [ -n "$BEFORE" ]; then
    # Planned times in other modes: the G64 SOFT line replaced, the same path.
    for mode in $MODES; do
      m="$WORK/${kind}_${BLOCKS}_${mode}.mpf"
      sed "s/^G64 SOFT\$/${mode/_/ }/" "$f" > "$m"
      a=$("$DRYCUT" run -q "$m" | awk '/^  time  / { print $2; exit }')
      b=$("$BEFORE" run -q "$m" | awk '/^  time  / { print $2; exit }')
      awk -v m="$mode" -v a="$a" -v b="$b" 'BEGIN {
        printf "  planned time %-9s earlier %12.2f s  now %12.2f s  change %+.4f %%\n", m, b, a, (a - b) / b * 100 }' |
        tee -a "$OUT"
    done
  fi
done
echo "figures written to $OUT"
