#!/usr/bin/env python3
"""Accuracy of the 24 progressive 3-D thesis programs, simulated by `drycut deviation`, next to
program size; and the knot-density sweep on the reference contour at the experiment's pass limit.

Usage: bench/thesis-accuracy/run.py [path/to/drycut [deviation options...]] > table.md
Reads the committed programs in programs/thesis (regenerate with programs/thesis/generate.sh).
"""
import json
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DRYCUT = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "build", "drycut")
EXTRA = sys.argv[2:]  # further `drycut deviation` options, e.g. --held-line-range 3
PROGRAMS = os.path.join(ROOT, "programs", "thesis")
SETS = [("EKVI", 90), ("EKVI", 45), ("EKVI", 15), ("POLAR", 1), ("POLAR", 5), ("POLAR", 15)]
METHODS = [("LIN", "linear"), ("A", "aspline"), ("B", "bspline"), ("C", "cspline")]


def sub_name(family, tag, number):
    return f"{family}_POSTUPNE{'' if tag == 'A' else '_' + tag}_{number}.SPF"


def fmt(value, digits=4):
    return "-" if value is None else f"{value:.{digits}f}"


def deviation(main):
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        run = subprocess.run([DRYCUT, "deviation", main, "--json", out.name] + EXTRA, capture_output=True, text=True)
        report = json.load(open(out.name)) if os.path.getsize(out.name) else None
    return run.returncode, report


def main():
    print("| set | method | sub bytes | main bytes | prog. max all loops mm | prog. max loop 2 mm "
          "| prog. CP MAE mm | tool-cut max loop 2 mm | tool-cut gouge mm | tool-cut CP MAE mm "
          "| CP without crossing prog./cut | alarms |")
    print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|")
    for family, number in SETS:
        for tag, method in METHODS:
            main_file = os.path.join(PROGRAMS, f"{family}_{tag}_{number}.MPF")
            sub_bytes = os.path.getsize(os.path.join(PROGRAMS, sub_name(family, tag, number)))
            main_bytes = os.path.getsize(main_file)
            code, r = deviation(main_file)
            loops = [p for p in r["passes"] if p["full_loop"]] if r else []
            bottom = next((p for p in r["passes"] if p["name"] == r["control_point_pass"]), None) if r else None
            all_max = max((p["programmed"]["max_mm"] for p in loops), default=None)
            cut = bottom["tool_cut"] if bottom else None
            summary = r.get("control_point_summary") if r else None
            missing = "-"
            if summary:
                tool = summary["tool_cut"]
                missing = f"{summary['programmed']['without_crossing']}/{'-' if tool is None else tool['without_crossing']}"
            elif r:  # a drycut before the held-line summary: the points without a difference
                rows = r["control_points"]
                missing = (f"{sum(c['programmed_difference_mm'] is None for c in rows)}/"
                           f"{sum(c['tool_cut_difference_mm'] is None for c in rows) if cut else '-'}")
            print(f"| {family}_{number} | {method} | {sub_bytes} | {main_bytes} | {fmt(all_max)} "
                  f"| {fmt(bottom['programmed']['max_mm'] if bottom else None)} | {fmt(r and r['control_point_mae_mm'])} "
                  f"| {fmt(cut and cut['max_mm'])} | {fmt(cut and cut['deepest_gouge_mm'])} "
                  f"| {fmt(r and r['tool_cut_control_point_mae_mm'])} | {missing} | {'; '.join(a.replace(ROOT + os.sep, '') for a in r['alarms']) if r else 'exit ' + str(code)} |")
    print()
    sys.stdout.flush()
    with tempfile.NamedTemporaryFile(suffix=".json") as out:
        subprocess.run([DRYCUT, "sweep", "--tolerance", "0.08", "--json", out.name], check=False,
                       stdout=subprocess.DEVNULL)
        sweep = json.load(open(out.name))
    print("Sweep on the reference contour, tolerance 0.08 mm (knots at equal arc length over the whole curve; "
          "2-D loop at Z=-6 with 3 overlap knots, seam included; time = planner on the 3-D program, after M0):")
    print()
    print("| method | knots per loop | spacing mm | max deviation mm | predicted time after M0 s | main + sub bytes | monotone nearby |")
    print("|---|---:|---:|---:|---:|---:|---|")
    for m in sweep["methods"]:
        if not m["found"]:
            print(f"| {m['method']} | not found | | | | | |")
            continue
        print(f"| {m['method']} | {m['knots']} | {m['spacing_mm']:.3f} | {m['max_deviation_mm']:.4f} "
              f"| {fmt(m['time_after_m0_s'], 2)} | {m['main_bytes'] + m['sub_bytes']} | {m['monotone_neighbourhood']} |")


if __name__ == "__main__":
    main()
