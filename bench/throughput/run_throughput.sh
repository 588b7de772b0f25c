#!/usr/bin/env bash
# Planning throughput per element kind (issue 13 item 6): `drycut run` on 1 M-block programs of
# G1 (G64 SOFT), G1 (G64 BRISK), G2/G3, ASPLINE, BSPLINE and CSPLINE, LinuxCNC's `rs274` on the
# same G1 and G2/G3 paths in the same run, and the peak memory of a 10 M-block G1 program.
#
# Usage: bench/throughput/run_throughput.sh [drycut] [earlier drycut] [figures file]
#   With an earlier binary (e.g. built from the commit before a change) both run on the same
#   files, alternating, REPS times; the table shows medians of the CPU time (user + system:
#   the one-core rate even on a loaded machine), of the wall time (what a user waits: drycut
#   plans on two threads) and the planned times of both (they must agree).
# Environment: BLOCKS=1000000, BIG=10000000 (G1 SOFT, peak RSS; 0 skips), REPS=3,
#              KINDS="g1 g1brisk rs274 arcs arcs_rs274 aspline bspline cspline",
#              PEER=1 (0 skips rs274), WORK=/tmp/drycut_throughput
# Programs (generated once into WORK, not committed): bench/scale/generate_programs.sh (the
# G1 spiral of 0.05-0.5 mm steps and the same points as spline points) and
# bench/arcs/generate_arcs.py kind `arcs` (tangent-continuous G2/G3, radii 1-20 mm, seed 17).
# rs274 comes from Debian's linuxcnc-uspace (apt-get when missing and running as root; never a
# dependency of drycut); it interprets only (canonical calls to a file), drycut plans.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
DRYCUT=$(readlink -f "${1:-build/drycut}")
BEFORE=${2:-}
[ -n "$BEFORE" ] && BEFORE=$(readlink -f "$BEFORE")
OUT=${3:-/tmp/drycut_throughput_figures.txt}
WORK=${WORK:-/tmp/drycut_throughput}
BLOCKS=${BLOCKS:-1000000}
BIG=${BIG:-10000000}
REPS=${REPS:-3}
KINDS=${KINDS:-"g1 g1brisk rs274 arcs arcs_rs274 aspline bspline cspline"}
PEER=${PEER:-1}
mkdir -p "$WORK"
: > "$OUT"

if [ "$PEER" = 1 ] && ! command -v rs274 > /dev/null && [ "$(id -u)" = 0 ]; then
  { apt-get install -y --no-install-recommends linuxcnc-uspace || true; } 2>&1 | tail -2
fi
[ "$PEER" = 1 ] && ! command -v rs274 > /dev/null && { echo "rs274 not available: peer skipped"; PEER=0; }

# program KIND N -> file name (generated when missing)
program() {
  local kind=$1 n=$2 f
  case $kind in
    arcs) f="$WORK/arcs_$n.mpf"; [ -s "$f" ] || python3 "$here/../arcs/generate_arcs.py" arcs "$n" sinumerik "$f" ;;
    arcs_rs274) f="$WORK/arcs_$n.ngc"; [ -s "$f" ] || python3 "$here/../arcs/generate_arcs.py" arcs "$n" rs274 "$f" ;;
    rs274) f="$WORK/rs274_$n.ngc"; "$here/../scale/generate_programs.sh" rs274 "$n" "$f" ;;
    *) f="$WORK/${kind}_$n.mpf"; "$here/../scale/generate_programs.sh" "$kind" "$n" "$f" ;;
  esac
  echo "$f"
}

# measure COMMAND... -> "cpu_s rss_mb planned_s exit wall_s" (planned: drycut's "  time  " line).
# drycut interprets and plans on two threads (src/interp/pipelined_sink.hpp), so its wall time
# is what a user waits and its CPU time the one-core work; rs274 runs on one thread.
measure() {
  local rc=0
  /usr/bin/time -f "%U %S %M %e" -o "$WORK/time.txt" "$@" > "$WORK/stdout.txt" 2> "$WORK/stderr.txt" || rc=$?
  local planned
  planned=$(awk '/^  time  / { print $2; exit }' "$WORK/stdout.txt")
  awk -v p="${planned:--}" -v rc="$rc" '{ printf "%.3f %.1f %s %d %.3f\n", $1 + $2, $3 / 1024, p, rc, $4 }' "$WORK/time.txt"
}

median() { tr ' ' '\n' | grep . | sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }

row() {  # kind label file
  local kind=$1 label=$2 f=$3 now="" before="" peer="" rss=0 planned_now=- planned_before=- fails=0
  local now_wall="" before_wall="" peer_wall=""
  local peer_file=""
  case $kind in g1|g1brisk|rs274) peer_file=$(program rs274 "$BLOCKS") ;; arcs|arcs_rs274) peer_file=$(program arcs_rs274 "$BLOCKS") ;; esac
  for ((r = 0; r < REPS; r++)); do
    # Alternate the order so that a load change hits both binaries alike.
    local order="now before"
    ((r % 2)) && order="before now"
    for who in $order; do
      if [ "$who" = now ]; then
        read -r c m p rc w < <(measure "$DRYCUT" run -q "$f"); now="$now $c"; now_wall="$now_wall $w"; rss=$m; planned_now=$p
      elif [ -n "$BEFORE" ]; then
        read -r c m p rc w < <(measure "$BEFORE" run -q "$f"); before="$before $c"; before_wall="$before_wall $w"; planned_before=$p
      fi
      [ "$rc" -gt 1 ] && fails=$((fails + 1))
    done
    if [ "$PEER" = 1 ] && [ -n "$peer_file" ]; then
      read -r c m p rc w < <(measure sh -c "rs274 -g '$peer_file' '$WORK/rs274_calls.txt' < /dev/null")
      peer="$peer $c"; peer_wall="$peer_wall $w"
    fi
  done
  local mn mb mp
  mn=$(echo "$now" | median)
  mb=$([ -n "$before" ] && echo "$before" | median || echo -)
  mp=$([ -n "$peer" ] && echo "$peer" | median || echo -)
  local wn wb wp
  wn=$(echo "$now_wall" | median)
  wb=$([ -n "$before_wall" ] && echo "$before_wall" | median || echo -)
  wp=$([ -n "$peer_wall" ] && echo "$peer_wall" | median || echo -)
  awk -v l="$label" -v n="$BLOCKS" -v a="$mn" -v b="$mb" -v p="$mp" -v rss="$rss" -v pn="$planned_now" \
      -v pb="$planned_before" -v fails="$fails" -v wn="$wn" -v wb="$wb" -v wp="$wp" 'BEGIN {
    rate = n / a / 1e6
    eb = (b == "-") ? "-" : sprintf("%.2f", n / b / 1e6)
    up = (b == "-") ? "-" : sprintf("%.2fx", b / a)
    pr = (p == "-") ? "-" : sprintf("%.2f", n / p / 1e6)
    ratio = (p == "-") ? "-" : sprintf("%.2fx", p / a)
    change = (pb == "-" || pn == "-") ? "-" : sprintf("%+.4f%%", (pn - pb) / pb * 100)
    wrate = sprintf("%.2f", n / wn / 1e6)
    wearl = (wb == "-") ? "-" : sprintf("%.2f", n / wb / 1e6)
    wratio = (wp == "-") ? "-" : sprintf("%.2fx", wp / wn)
    printf "| %s | %s | %.2f | %s | %s | %.1f | %s | %s | %s | %s | %s | %s | %s |%s\n", l, eb, rate, up,
           (b == "-") ? "-" : b " / " a, rss, change, pr, ratio, pn, wearl, wrate, wratio, fails ? " FAILED RUNS: " fails : ""
  }' | tee -a "$OUT"
}

echo "drycut run, $BLOCKS blocks, median CPU s of $REPS alternating runs (M blocks/s = blocks / CPU s)" | tee -a "$OUT"
echo "| program | earlier M/s | now M/s | speed-up | CPU s earlier / now | peak RSS MB | planned time change | rs274 M/s | now / rs274 | planned s | earlier M/s wall | now M/s wall | now / rs274 wall |" | tee -a "$OUT"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|" | tee -a "$OUT"
for kind in $KINDS; do
  case $kind in
    g1) label="G1 G64 SOFT" ;;
    g1brisk) label="G1 G64 BRISK" ;;
    rs274) label="G1 RS274 file (G64 = BRISK)" ;;
    arcs) label="G2/G3 G64 SOFT" ;;
    arcs_rs274) label="G2/G3 RS274 file (BRISK)" ;;
    aspline|bspline|cspline) label="${kind^^} G64 SOFT" ;;
    *) echo "unknown kind $kind" >&2; exit 2 ;;
  esac
  row "$kind" "$label" "$(program "$kind" "$BLOCKS")"
done

if [ "$BIG" -gt 0 ]; then
  f=$(program g1 "$BIG")
  read -r c m p rc w < <(measure "$DRYCUT" run -q "$f")
  awk -v n="$BIG" -v c="$c" -v m="$m" -v rc="$rc" -v w="$w" 'BEGIN {
    printf "G1 G64 SOFT %d blocks: CPU %.2f s (%.2f M blocks/s), wall %.2f s (%.2f M blocks/s), peak RSS %.1f MB, exit %d\n",
           n, c, n / c / 1e6, w, n / w / 1e6, m, rc }' | tee -a "$OUT"
fi
echo "figures written to $OUT"
