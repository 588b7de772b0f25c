#!/usr/bin/env python3
"""Writes MOULD_4711_FINISH.MPF: a 3-axis ball-nose finishing pass over a freeform surface, in the
style of a CAM post-processor for SINUMERIK 840D (header, DEF variables, machine-data checks,
named tool, CYCLE832, G54 + TRANS/AROT, thousands of short G1 blocks, M30).

The part and the surface are invented for drycut. Python 3 standard library only; the output is
deterministic (the surface's bumps come from random.Random(SEED), whose sequence for an integer
seed is fixed across Python 3 versions).

The generator also computes, from the points exactly as written (rounded to 0.001 mm), what a
correct control must traverse, and writes it into the header:
  - MOTION BLOCKS: the number of generated motion blocks (between the markers);
  - PATH LENGTH: the sum of all straight segments in machine coordinates of the tool carrier,
    from the machine start position (0, 0, 100) through the frame chain G54 (zero on the default
    profile) * TRANS X50 Y40 * AROT Z15 plus the tool length 90 on Z (docs/controller-state.md);
  - G1 LENGTH: the same for the feed moves only (rotation and translation keep lengths).
tests/app/cam_finishing_test.cpp checks drycut's figures against these.

Usage: gen_cam_finishing.py [OUT.MPF]   (default: MOULD_4711_FINISH.MPF beside this script)
"""
import math
import os
import random
import sys

SEED = 4711
X_LEN, Y_LEN = 80.0, 60.0        # machined area in the workpiece system (mm)
STEPOVER = 0.75                  # between passes (Y)
STEP = 0.5                       # along a pass (X)
Z_SAFE, Z_CLEAR = 50.0, 5.0      # retract plane, clearance above the start point
F_PLUNGE, F_CUT = 800, 3000      # mm/min
TOOL_LENGTH = 90.0               # tools.csv: BALL_R3 D1
FRAME_TRANS = (50.0, 40.0, 0.0)  # TRANS X50 Y40 Z0
FRAME_ROT_DEG = 15.0             # AROT Z15
MACHINE_START = (0.0, 0.0, 100.0)
SUPA_Z = 280.0                   # tool change height in machine coordinates


def make_surface(seed):
    """A smooth mould-like surface: a base swell plus four Gaussian bumps from the seed."""
    rng = random.Random(seed)
    bumps = []
    for _ in range(4):
        bumps.append((rng.uniform(10, 70), rng.uniform(10, 50), rng.uniform(1.5, 4.0), rng.uniform(8, 16)))

    def z(x, y):
        v = 4.0 + 2.0 * math.sin(math.pi * x / X_LEN) * math.sin(math.pi * y / Y_LEN)
        for cx, cy, h, w in bumps:
            v += h * math.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * w * w))
        return v

    return z


def fmt(v):
    """CAM style: three decimals, trailing zeros dropped, '12.' for whole numbers, no '-0.'."""
    s = f"{v:.3f}".rstrip("0")
    return "0." if s in ("-0.", "0.") else s


def to_machine(p):
    """Workpiece point (tool tip) -> machine position of the tool carrier."""
    c, s = math.cos(math.radians(FRAME_ROT_DEG)), math.sin(math.radians(FRAME_ROT_DEG))
    x, y, z = p
    return (c * x - s * y + FRAME_TRANS[0], s * x + c * y + FRAME_TRANS[1], z + FRAME_TRANS[2] + TOOL_LENGTH)


def dist(a, b):
    return math.sqrt(sum((a[i] - b[i]) ** 2 for i in range(3)))


def raster_points(z):
    """Zig-zag in X, stepping over in Y; every point rounded as it is written."""
    n_pass = int(round(Y_LEN / STEPOVER)) + 1
    n_step = int(round(X_LEN / STEP))
    passes = []
    for j in range(n_pass):
        y = round(j * STEPOVER, 3)
        xs = [round(i * STEP, 3) for i in range(n_step + 1)]
        if j % 2:
            xs.reverse()
        passes.append([(x, y, round(z(x, y), 3)) for x in xs])
    return passes


def body_blocks(passes, first_n):
    """The generated G1 blocks: modal words left out as a post does. Returns (lines, points)."""
    lines, points = [], []
    n = first_n
    last = list(passes[0][0])
    first = True
    for k, p in enumerate(passes):
        for i, q in enumerate(p):
            if k == 0 and i == 0:
                continue  # the plunge block reaches the first point
            words = ""
            for axis, idx in (("X", 0), ("Y", 1), ("Z", 2)):
                if fmt(q[idx]) != fmt(last[idx]):
                    words += axis + fmt(q[idx])
            if not words:
                continue
            if first:
                words += f"F{F_CUT}"
                first = False
            lines.append(f"N{n}{words}")
            points.append(q)
            last = list(q)
            n += 2
    return lines, points, n


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                                              "MOULD_4711_FINISH.MPF")
    z = make_surface(SEED)
    passes = raster_points(z)
    start = passes[0][0]
    body, body_points, n_after = body_blocks(passes, 1000)

    # Path length in machine coordinates, move by move, as the program below traverses it.
    g0 = g1 = 0.0
    pos = MACHINE_START
    def move(target, rapid):
        nonlocal pos, g0, g1
        d = dist(pos, target)
        if rapid:
            g0 += d
        else:
            g1 += d
        pos = target
    move((pos[0], pos[1], SUPA_Z), True)                       # G0 SUPA Z280 D0
    m = to_machine((start[0], start[1], 0.0))
    move((m[0], m[1], SUPA_Z), True)                           # G0 X Y (Z not written: stays)
    move(to_machine((start[0], start[1], start[2] + Z_CLEAR)), True)  # G0 Z (tool length joins)
    move(to_machine(start), False)                             # G1 Z plunge
    for q in body_points:
        move(to_machine(q), False)
    move(to_machine((body_points[-1][0], body_points[-1][1], Z_SAFE)), True)  # G0 Z50
    move((pos[0], pos[1], SUPA_Z), True)                       # G0 SUPA Z280 D0

    head = f"""%_N_MOULD_4711_FINISH_MPF
;$PATH=/_N_WKS_DIR/_N_MOULD_4711_WPD
;==================================================================
; PART        : MOULD INSERT 4711 (invented example part)
; OPERATION   : FINISH_RASTER_BALL6 - 3 axis, zig-zag in X
; CAM         : gen_cam_finishing.py, seed {SEED} (drycut repository)
; POST        : SINUMERIK 840D sl, 3 axis, metric
; TOOL        : T="BALL_R3" D1  ball nose D6 R3, gauge length {TOOL_LENGTH:g}
; AREA        : X0..{X_LEN:g} Y0..{Y_LEN:g} (workpiece), stepover {STEPOVER:g}, step {STEP:g}
; TOLERANCE   : 0.01
; MOTION BLOCKS: {len(body)}
; PATH LENGTH : {g0 + g1:.4f} mm (G0 {g0:.4f} + G1 {g1:.4f}), machine coordinates
; G1 LENGTH   : {g1:.4f} mm
;==================================================================
N10 DEF REAL _TOL,_ZSAFE,_ZCLEAR
N12 DEF INT _NPASS
N14 DEF STRING[32] _OPNAME
N16 DEF REAL _EXT[3]
N18 _TOL=0.01 _ZSAFE={fmt(Z_SAFE)} _ZCLEAR={fmt(Z_CLEAR)}
N20 _NPASS={len(passes)}
N22 _OPNAME="FINISH_RASTER_BALL6"
N24 _EXT[0]={fmt(X_LEN)} _EXT[1]={fmt(Y_LEN)} _EXT[2]=15.
; the program is metric: on an inch machine switch geometry and feed to mm
IF $MN_SCALING_SYSTEM_IS_METRIC==0
  G710
ELSE
  G71
ENDIF
; part position TRANS X50 Y40 plus its extents must lie inside the software limits
IF ($MA_POS_LIMIT_PLUS[X1]<{fmt(FRAME_TRANS[0])}+_EXT[0]) OR ($MA_POS_LIMIT_PLUS[Y1]<{fmt(FRAME_TRANS[1])}+_EXT[0]+_EXT[1])
  SETAL(65000)
ENDIF
N30 MSG("OPERATION "<<_OPNAME)
N32 G0 SUPA Z{fmt(SUPA_Z)} D0
N34 T="BALL_R3" D1
N36 M6
N38 G17 G90 G94 G40 G60
N40 G54
N42 TRANS X{fmt(FRAME_TRANS[0])} Y{fmt(FRAME_TRANS[1])} Z{fmt(FRAME_TRANS[2])}
N44 AROT Z{fmt(FRAME_ROT_DEG)}
N46 CYCLE832(_TOL,1,1)
N48 G642 SOFT FFWON COMPCAD
N50 S12000 M3
N52G0X{fmt(start[0])}Y{fmt(start[1])}
N54Z={fmt(start[2])}+_ZCLEAR
N56G1Z{fmt(start[2])}F{F_PLUNGE}
; --- generated toolpath: {len(body)} blocks, {len(passes)} passes ---
"""
    tail = f"""; --- end of generated toolpath ---
N{n_after}G0Z=_ZSAFE
N{n_after + 2} FFWOF COMPOF M5
N{n_after + 4} CYCLE832()
N{n_after + 6} TRANS
N{n_after + 8} G0 SUPA Z{fmt(SUPA_Z)} D0
N{n_after + 10} MSG()
N{n_after + 12} M30
"""
    with open(out, "w", newline="\n") as f:
        f.write(head)
        f.write("\n".join(body) + "\n")
        f.write(tail)


if __name__ == "__main__":
    main()
