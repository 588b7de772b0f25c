#!/usr/bin/env python3
"""Generates the compressor benchmark programs (bench/compressor/README.md) into a folder:
CIRCLE_<MODE>.MPF  a circle R20 in 0.05 mm chords, repeated to BLOCKS G1 blocks;
WAVY_<MODE>.MPF    a wavy free-form closed line r = 200 + 2 sin(25 t) + 0.7 sin(61 t),
                   about 0.1 mm per block, BLOCKS G1 blocks;
for MODE in COMPOF (plain G64), COMPON, COMPCURV, COMPCAD. Usage: generate.py DIR [BLOCKS]."""
import math
import os
import sys

MODES = ["COMPOF", "COMPON", "COMPCURV", "COMPCAD"]


def circle(blocks):
    n = int(math.ceil(2 * math.pi * 20 / 0.05))
    for i in range(1, blocks + 1):
        a = 2 * math.pi * (i % n) / n
        yield 20 * math.cos(a), 20 * math.sin(a)


def wavy(blocks):
    per_loop = int(2 * math.pi * 200 / 0.1)
    for i in range(1, blocks + 1):
        t = 2 * math.pi * (i % per_loop) / per_loop
        r = 200 + 2 * math.sin(25 * t) + 0.7 * math.sin(61 * t)
        yield r * math.cos(t), r * math.sin(t)


def write(path, mode, start, points):
    with open(path, "w") as f:
        f.write("N10 G90 G17 G0 X%.4f Y%.4f Z0\n" % start)
        f.write("N20 G64 SOFT %s F3000\n" % mode)
        for x, y in points:
            f.write("G1 X%.4f Y%.4f\n" % (x, y))
        f.write("M30\n")


def main():
    out = sys.argv[1]
    blocks = int(sys.argv[2]) if len(sys.argv) > 2 else 100000
    os.makedirs(out, exist_ok=True)
    for mode in MODES:
        write(os.path.join(out, "CIRCLE_%s.MPF" % mode), mode, (20.0, 0.0), circle(blocks))
        write(os.path.join(out, "WAVY_%s.MPF" % mode), mode, (200.0, 0.0), wavy(blocks))


if __name__ == "__main__":
    main()
