#!/usr/bin/env bash
# The reference experiment's linear programs (programs/thesis/EKVI_LIN_<n>.MPF, G64 SOFT, G42)
# with a compressor added after SOFT (issue 13 proof item): the span after_dwell..contour_end
# that `drycut experiment` compares with the measured times, how many blocks were compressed,
# and the same once more without tool radius compensation (G42/G40 removed) to show what the
# compressor does to the programmed polygon itself. No measurement of these cases exists.
# Usage: bench/compressor/thesis_linear.sh [DRYCUT]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
drycut=$(realpath "${1:-$here/../../build/drycut}")
dir=${DIR:-/tmp/drycut_thesis_compressor}
rm -rf "$dir"; mkdir -p "$dir"
cp "$here/../../programs/thesis/"EKVI_*LIN* "$dir/"
cd "$dir"
printf "%-10s %-9s %-6s %9s   %s\n" program mode trc span_s compressed
for knots in 90 45 15; do
  for mode in COMPOF COMPON COMPCURV COMPCAD; do
    for trc in G42 none; do
      p=LIN_${knots}_${mode}_${trc}.MPF
      sed "s/^N50 SOFT/N50 SOFT\nN55 $mode/" "EKVI_LIN_$knots.MPF" > "$p"
      [ "$trc" = none ] && sed -i '/^N100 G42$/d; /^N140 G40$/d' "$p"
      "$drycut" run "$p" -q --span after_dwell..contour_end --json run.json > /dev/null 2>&1 || true
      summary=$("$drycut" run "$p" 2>/dev/null | awk '/^  compressor/ { $1 = ""; print }')
      python3 - "$knots" "$mode" "$trc" "${summary:- none}" <<'PY'
import json, sys
knots, mode, trc, summary = sys.argv[1:5]
s = json.load(open("run.json"))["summary"]
print("%-10s %-9s %-6s %9.2f  %s" % ("LIN_" + knots, mode, trc, s["span_s"], summary))
PY
    done
  done
done
