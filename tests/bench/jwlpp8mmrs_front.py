#!/usr/bin/env python3
"""Benchmark (not a test): the ICE rate stick ICE/JWLpp8mmRS.ups run through
`tephra`, its detonation front position against time and the front speed.

Usage: tests/bench/jwlpp8mmrs_front.py BUILD_DIR [OUT_DIR] [--no-run]
  (runs BUILD_DIR/bin/tephra on ../shared/decks/inputs/ICE/JWLpp8mmRS.ups
  from the decks directory unless --no-run, then extracts F along the stick.)

Front: the largest x of a cell on the axis row (y = z = 0.5 mm) with F >= 0.5;
also on the row at r = 7.5 mm (the outermost row of cells inside the 8 mm
radius). Speed: least-squares slope of x_front(t) over the given windows.
Figures of the last run are in docs/algorithms/ice.md ("JWLpp8mmRS").
"""
import csv
import collections
import os
import subprocess
import sys


def fit_slope(t, x):
    n = len(t)
    mt, mx = sum(t) / n, sum(x) / n
    return sum((a - mt) * (b - mx) for a, b in zip(t, x)) / sum((a - mt) ** 2 for a in t)


def extract(tephra, out, var, y, material=None):
    cmd = [tephra, "extract", out, "--var", var, "--all-times",
           "--line", f"0.0005,{y},0.0005,0.0995,{y},0.0005"]
    if material is not None:
        cmd += ["--material", str(material)]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rows = collections.defaultdict(list)
    for r in csv.DictReader(text.splitlines()):
        rows[float(r["time"])].append((float(r["x"]), float(r[var])))
    return rows


def main():
    build = sys.argv[1]
    out = sys.argv[2] if len(sys.argv) > 2 and not sys.argv[2].startswith("--") else "/tmp/jwlpp8mmrs_bench"
    tephra = os.path.join(build, "bin", "tephra")
    decks = os.path.join(os.path.dirname(__file__), "..", "..", "..", "shared", "decks")
    if "--no-run" not in sys.argv:
        subprocess.run([tephra, "inputs/ICE/JWLpp8mmRS.ups", "--output", out], check=True, cwd=decks)
    F_axis = extract(tephra, out, "F", 0.0005, 0)
    F_edge = extract(tephra, out, "F", 0.0075, 0)
    P_axis = extract(tephra, out, "press_CC", 0.0005)
    rows = []
    for t in sorted(F_axis):
        fa = max([x for x, f in F_axis[t] if f >= 0.5], default=None)
        fe = max([x for x, f in F_edge[t] if f >= 0.5], default=None)
        pm = max(P_axis[t], key=lambda a: a[1])
        rows.append((t, fa, fe, pm))
        print(f"t = {t * 1e6:6.2f} us  front(axis) = {fa * 1e3 if fa else float('nan'):5.1f} mm  "
              f"front(r = 7.5 mm) = {fe * 1e3 if fe else float('nan'):5.1f} mm  "
              f"p_max = {pm[1] / 1e9:5.2f} GPa at {pm[0] * 1e3:5.1f} mm")
    for a, b in [(10e-6, 20.1e-6), (14e-6, 20.1e-6), (16e-6, 20.1e-6)]:
        sa = [(t, fa) for t, fa, fe, pm in rows if fa is not None and a <= t <= b]
        se = [(t, fe) for t, fa, fe, pm in rows if fe is not None and a <= t <= b]
        if len(sa) > 2 and len(se) > 2:
            print(f"window {a * 1e6:.0f}-{b * 1e6:.0f} us: front speed axis {fit_slope(*zip(*sa)):.0f} m/s, "
                  f"r = 7.5 mm {fit_slope(*zip(*se)):.0f} m/s")


if __name__ == "__main__":
    main()
