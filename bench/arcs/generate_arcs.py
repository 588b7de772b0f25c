#!/usr/bin/env python3
"""Tangent-continuous random arc programs for the planner benchmark (issue 17).

Usage: generate_arcs.py KIND BLOCKS DIALECT FILE [SEED]
  KIND    = mixed   60 % G2/G3, 20 % helical G2/G3 (Z), 20 % G1
            helix   70 % helical, 20 % G2/G3, 10 % G1
            arcs    100 % G2/G3 in the plane (the element-kind table of bench/throughput)
  DIALECT = sinumerik  `G64 SOFT` header (drycut)
            rs274      plain RS274 header without SOFT (LinuxCNC rs274; drycut reads it too)
  SEED    = random seed (default 17): the same seed gives the same path in both dialects.

Every element starts in the direction the previous one ended (tangent-continuous in XY):
radii 1-20 mm, sweeps 5-300 degrees, helices climb or descend 0.2-3 mm, lines 0.5-15 mm.
Centres are written as incremental I J from the start point, which both dialects read the
same way. Coordinates are rounded to 4 decimals and the next element starts from the
rounded point, with the direction recomputed from the rounded centre, so the radius error
is below 1e-4 mm and the tangent error below 1e-4 rad. The path steers back to the origin
when it leaves a 200 mm circle (MCV 1210 travel is +-500 / +-400 / +-300 mm). The feed
changes every 100 blocks (F1500..F6000).
"""
import math
import random
import sys


def main():
    if len(sys.argv) < 5:
        sys.exit(__doc__)
    kind, blocks, dialect, path = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
    seed = int(sys.argv[5]) if len(sys.argv) > 5 else 17
    shares = {"mixed": (0.6, 0.2, 0.2), "helix": (0.2, 0.7, 0.1), "arcs": (1.0, 0.0, 0.0)}[kind]
    rng = random.Random(seed)
    out = []
    if dialect == "sinumerik":
        out.append("G54 G17 G90 G94")
        out.append("G64 SOFT")
    else:
        out.append("G17 G90 G64 G94")  # LinuxCNC defaults to mm; G21 is not SINUMERIK
    x, y, z = 0.0, 0.0, 0.0
    heading = 0.0
    out.append("G0 X0 Y0 Z5")
    out.append("G1 Z0 F3000")
    feed = 3000
    body = blocks - 5  # header lines, G0, G1 and M30 count as blocks too
    for n in range(body):
        if n % 100 == 0:
            feed = rng.choice((1500, 2000, 3000, 4000, 6000))
            fword = " F%d" % feed
        else:
            fword = ""
        r_pos = math.hypot(x, y)
        outward = math.cos(heading) * x + math.sin(heading) * y > 0
        u = rng.random()
        if u < shares[2] and not (r_pos > 200 and outward):
            length = rng.uniform(0.5, 15.0)
            x = round(x + length * math.cos(heading), 4)
            y = round(y + length * math.sin(heading), 4)
            out.append("G1 X%.4f Y%.4f%s" % (x, y, fword))
            continue
        helical = u >= shares[2] + shares[0]
        radius = rng.uniform(1.0, 20.0)
        sweep = math.radians(rng.uniform(5.0, 300.0))
        ccw = rng.random() < 0.5
        if r_pos > 200 and outward:
            # Turn towards the origin: the side where the origin lies, at least half a turn.
            cross = math.cos(heading) * (-y) - math.sin(heading) * (-x)
            ccw = cross > 0
            sweep = max(sweep, math.pi)
        side = 1.0 if ccw else -1.0
        # Centre to the left (G3) or right (G2) of the heading.
        i = round(-side * radius * math.sin(heading), 4)
        j = round(side * radius * math.cos(heading), 4)
        cx, cy = x + i, y + j
        start_angle = math.atan2(y - cy, x - cx)
        end_angle = start_angle + side * sweep
        rr = math.hypot(i, j)
        x = round(cx + rr * math.cos(end_angle), 4)
        y = round(cy + rr * math.sin(end_angle), 4)
        word = "G3" if ccw else "G2"
        if helical:
            dz = rng.uniform(0.2, 3.0)
            if z > 20 or (z > -20 and rng.random() < 0.5):
                dz = -dz
            z = round(z + dz, 4)
            out.append("%s X%.4f Y%.4f Z%.4f I%.4f J%.4f%s" % (word, x, y, z, i, j, fword))
        else:
            out.append("%s X%.4f Y%.4f I%.4f J%.4f%s" % (word, x, y, i, j, fword))
        # New heading: perpendicular to the rounded radius at the rounded end point.
        radial = math.atan2(y - cy, x - cx)
        heading = radial + side * math.pi / 2
    out.append("M30")
    with open(path, "w") as f:
        f.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
