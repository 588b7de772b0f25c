#!/usr/bin/env bash
# Generates the scale-benchmark programs (CAM-style, one short move per line) into a folder.
# Usage: bench/scale/generate_programs.sh KIND BLOCKS FILE
#   KIND = g1       SINUMERIK G1 spiral (G64 SOFT), steps 0.05-0.5 mm, F1500..F3000
#          g1brisk  the same under G64 BRISK
#          rs274    the same moves in plain RS274 (accepted by drycut and LinuxCNC's rs274)
#          aspline  the same spiral as ASPLINE points (one spline of BLOCKS points)
#          bspline  the same points as BSPLINE control points (degree 3, chord knot spans)
#          cspline  the same points as CSPLINE points
# The spiral r = 20 + 0.1·θ/(2π) mm (0.1 mm pitch) stays inside the MCV 1210 travel (±400 mm in Y)
# up to 10 M steps (r < 300 mm); step lengths follow a golden-ratio sequence so they are
# irregular but reproducible. The file is only written when it does not exist yet.
set -euo pipefail
kind=$1; n=$2; file=$3
case $kind in g1|g1brisk|rs274|aspline|bspline|cspline) ;; *) echo "unknown kind $kind" >&2; exit 2 ;; esac
[ -s "$file" ] && exit 0
mkdir -p "$(dirname "$file")"
awk -v n="$n" -v kind="$kind" 'BEGIN {
  pi = 3.141592653589793
  if (kind == "rs274") print "G17 G90 G64 G94"   # LinuxCNC defaults to mm; G21 is not SINUMERIK
  else if (kind == "g1brisk") print "G54 G17 G90 G64 BRISK G94"
  else print "G54 G17 G90 G64 SOFT G94"
  theta = 0; r = 20
  printf "G0 X%.3f Y%.3f Z5\n", r, 0
  print "G1 Z0 F1500"
  spline = (kind == "aspline" || kind == "bspline" || kind == "cspline")
  if (spline) print toupper(kind)
  body = n - 4
  for (i = 0; i < body; i++) {
    ds = 0.05 + 0.45 * ((i * 0.6180339887) % 1)   # 0.05 .. 0.5 mm
    theta += ds / r
    r = 20 + theta * 0.1 / (2 * pi)                # 0.1 mm per turn
    x = r * cos(theta); y = r * sin(theta)
    g1 = spline ? "" : "G1 "
    if (i % 1000 == 0) printf "%sX%.3f Y%.3f F%d\n", g1, x, y, 1500 + 500 * (int(i / 1000) % 4)
    else printf "%sX%.3f Y%.3f\n", g1, x, y
  }
  print "M30"
}' > "$file.tmp"
mv "$file.tmp" "$file"
