#!/usr/bin/env python3
"""CAM finishing programs for the throughput and smoothing benchmark (issue 13).

Usage: generate_finishing.py KIND BLOCKS FILE [HEADER]
  KIND   = contour  the reference experiment's contour r = 18 + 4 cos 6θ cos 2θ (programs/thesis,
                    src/workload/thesis_programs.hpp), followed loop after loop while Z descends
                    evenly to -10 mm (a waterline finishing pass as one continuous ramp)
           surface  a free-form surface z = 2 sin(x/10) cos(y/15) + 0.5 sin(x/3 + y/7) over
                    X 0..100, Y 0..80 mm, zig-zag raster along X; the stepover is chosen so
                    that the program has BLOCKS blocks
  BLOCKS = number of lines (header, approach and M30 included)
  HEADER = text of one block written after `G64 SOFT` (e.g. G642, G645, COMPCAD,
           "CYCLE832(0.01,1)"); empty or absent: none
Chords are 0.02-0.2 mm (a golden-ratio sequence: irregular, reproducible), as CAM systems
write for a 0.001-0.01 mm chordal tolerance; three decimals; F3000 (F changes to F2000 and
back every 10,000 blocks).
"""
import math
import sys

GOLDEN = 0.6180339887


def chord(i):
    return 0.02 + 0.18 * ((i * GOLDEN) % 1.0)


def contour_radius(theta):
    return 18.0 + 4.0 * math.cos(6.0 * theta) * math.cos(2.0 * theta)


def contour_speed(theta):
    # |dP/dθ| of the polar curve r(θ): sqrt(r² + r'²).
    r = contour_radius(theta)
    dr = -4.0 * (6.0 * math.sin(6.0 * theta) * math.cos(2.0 * theta) + 2.0 * math.cos(6.0 * theta) * math.sin(2.0 * theta))
    return math.hypot(r, dr)


def feed_word(i):
    if i % 10000 == 0:
        return " F%d" % (3000 if (i // 10000) % 2 == 0 else 2000)
    return ""


def contour(body, out):
    # Mean chord 0.11 mm: the number of loops follows from BLOCKS and the loop length.
    n = 20000
    loop_length = sum(contour_speed(2.0 * math.pi * (k + 0.5) / n) for k in range(n)) * 2.0 * math.pi / n
    loops = max(1.0, body * 0.11 / loop_length)
    dz_per_rad = -10.0 / (loops * 2.0 * math.pi)
    theta = 0.0
    out.append("G0 X%.3f Y0 Z1" % contour_radius(0.0))
    out.append("G1 Z0 F1000")
    for i in range(body):
        theta += chord(i) / contour_speed(theta)
        r = contour_radius(theta)
        out.append("G1 X%.3f Y%.3f Z%.3f%s" % (r * math.cos(theta), r * math.sin(theta), theta * dz_per_rad, feed_word(i)))


def surface_z(x, y):
    return 2.0 * math.sin(x / 10.0) * math.cos(y / 15.0) + 0.5 * math.sin(x / 3.0 + y / 7.0)


def surface(body, out):
    length_x = 100.0
    per_line = length_x / 0.11
    lines = max(2, int(body / per_line))
    stepover = 80.0 / lines
    out.append("G0 X0 Y0 Z5")
    out.append("G1 Z%.3f F1000" % surface_z(0.0, 0.0))
    x, y, direction, i = 0.0, 0.0, 1.0, 0
    while i < body:
        x += direction * chord(i)
        if x > length_x or x < 0.0:
            # End of a raster line: clamp to the edge, then step over.
            x = min(max(x, 0.0), length_x)
            out.append("G1 X%.3f Y%.3f Z%.3f%s" % (x, y, surface_z(x, y), feed_word(i)))
            i += 1
            if i >= body:
                break
            y += stepover
            direction = -direction
        out.append("G1 X%.3f Y%.3f Z%.3f%s" % (x, y, surface_z(x, y), feed_word(i)))
        i += 1


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    kind, blocks, path = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    header = sys.argv[4] if len(sys.argv) > 4 else ""
    out = ["G54 G17 G90 G94", "G64 SOFT"]
    if header:
        out.append(header)
    body = blocks - len(out) - 3  # approach (2 blocks) and M30
    {"contour": contour, "surface": surface}[kind](body, out)
    out.append("M30")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
