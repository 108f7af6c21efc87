#!/usr/bin/env python3
"""Benchmark (not a test): the breathing tube of
inputs/mpmice/breathing_tube_axisym.ups (issue 6, docs/mpmice.md "Session 27:
radial solid motion"): an elastic tube (a = 45, b = 50 mm) released under
1.1 MPa inside, run axisymmetric and as a 3-D quarter section (Cartesian,
symmetry planes x = 0 and y = 0, one cell thick in z with symmetry faces) at
the given cell sizes; prints the mean radial displacement's peak and its time
for each run against the closed form, and draws the histories.

Usage: tests/bench/breathing_tube.py BUILD_DIR OUT [--cells 1e-3,0.5e-3] [--quarter 1e-3,0.5e-3] [--png FILE]
"""
import argparse, math, os, re, subprocess, sys
from collections import defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
DECK = os.path.join(HERE, "..", "..", "inputs", "mpmice", "breathing_tube_axisym.ups")
CYL = '<cylinder label="{l}"> <bottom>[0,0,-1]</bottom> <top>[0,0,1]</top> <radius>{r}</radius> </cylinder>'


def axisym_deck(h):
    s = open(DECK).read()
    s = s.replace("[0.001,0.001,0.001]", f"[{h},{h},{h}]").replace("[0.06,0.002,0.001]", f"[0.06,0.002,{h}]")
    return s


def quarter_deck(h):
    """The same tube as a 3-D quarter section: cylinders along z through the origin."""
    s = open(DECK).read().replace("<axisymmetric>true</axisymmetric>", "<axisymmetric>false</axisymmetric>")
    xplus = re.search(r'<Face side = "x\+">.*?</Face>', s, re.S).group(0)
    a, b = s.index('<Face side = "y-">'), s.index('<Face side = "z-">')
    s = (s[:a] + '<Face side = "y-">\n<BCType id = "all" label = "Symmetric" var = "symmetry"></BCType>\n</Face>\n'
         + xplus.replace("x+", "y+") + "\n" + s[b:])
    s = s.replace("[0.001,0.001,0.001]", f"[{h},{h},{h}]").replace("[0.06,0.002,0.001]", f"[0.06,0.06,{h}]")
    s = re.sub(r'<box label="tube">.*?</box>', "<difference>" + CYL.format(l="outer", r=0.05) +
               CYL.format(l="bore", r=0.045) + "</difference>", s, flags=re.S)
    s = re.sub(r'<box label="inside">.*?</box>', CYL.format(l="inside_gas", r=0.045), s, flags=re.S)
    s = re.sub(r'<box label="tube_and_inside">.*?</box>', CYL.format(l="tube_and_inside", r=0.05), s, flags=re.S)
    return s


def mean_radial_displacement(tephra, uda, quarter):
    out = subprocess.run([tephra, "extract", uda, "--var", "p.x", "--material", "0", "--all-times"],
                         check=True, capture_output=True, text=True).stdout
    by_t = defaultdict(list)
    for line in out.splitlines():
        f = line.split(",")
        if not f[0][:1].isdigit():
            continue
        x, y = float(f[2]), float(f[3])
        by_t[float(f[0])].append(math.hypot(x, y) if quarter else x)
    ts = sorted(by_t)
    r0 = by_t[ts[0]]
    return ts, [sum(r - q for r, q in zip(by_t[t], r0)) / len(r0) for t in ts]


def closed_form():
    """Plane-strain Lame static mean displacement (with / without the inner air's
    quasi-static stiffness) and the thin-shell half period (docs/mpmice.md)."""
    K, G, rho, a, b, p0, po, gam = 1.17e9, 4.38e8, 8900.0, 0.045, 0.05, 1.1e6, 101325.0, 1.4
    E, nu = 9 * K * G / (3 * K + G), (3 * K - 2 * G) / (2 * (3 * K + G))
    A = (1 + nu) * (1 - 2 * nu) * (p0 * a * a - po * b * b) / (E * (b * b - a * a))
    B = (1 + nu) * a * a * b * b * (p0 - po) / (E * (b * b - a * a))
    half_period = math.pi * math.sqrt((1 - nu * nu) * rho) * (a + b) / 2 / math.sqrt(E)
    return 2 * (A * (a + b) / 2 + B / ((a + b) / 2)), half_period


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("out")
    ap.add_argument("--cells", default="1e-3,0.5e-3")
    ap.add_argument("--quarter", default="1e-3")
    ap.add_argument("--png", default=None)
    o = ap.parse_args()
    tephra = os.path.join(o.build, "bin", "tephra")
    os.makedirs(o.out, exist_ok=True)
    runs = [("axisymmetric", float(h)) for h in o.cells.split(",") if h] + \
           [("3-D quarter", float(h)) for h in o.quarter.split(",") if h]
    peak_cf, half = closed_form()
    print(f"# closed form: peak 2 u_s ~ {peak_cf:.4e} m (no air stiffness), half period {half * 1e6:.1f} us")
    print("# run, h [mm], steps, peak mean radial displacement [m], at [us]")
    curves = []
    for kind, h in runs:
        name = f"{'axi' if kind == 'axisymmetric' else 'q3d'}_{h * 1e3:g}mm"
        deck = os.path.join(o.out, name + ".ups")
        open(deck, "w").write(axisym_deck(h) if kind == "axisymmetric" else quarter_deck(h))
        uda = os.path.join(o.out, name + ".uda")
        log = subprocess.run([tephra, deck, "--output", uda, "--threads", "1"], capture_output=True, text=True)
        if log.returncode != 0:
            print(f"{kind} {h * 1e3:g} mm: exit {log.returncode}: {log.stderr.strip().splitlines()[-1:]}")
            continue
        steps = re.search(r"after (\d+) steps", log.stderr + log.stdout)
        ts, u = mean_radial_displacement(tephra, uda, kind != "axisymmetric")
        k = max(range(len(u)), key=lambda i: u[i])
        print(f"{kind}, {h * 1e3:g}, {steps.group(1) if steps else '?'}, {u[k]:.5e}, {ts[k] * 1e6:.1f}")
        curves.append((f"{kind}, h = {h * 1e3:g} mm", ts, u))
    if o.png and curves:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(6, 4))
        for label, ts, u in curves:
            ax.plot([t * 1e6 for t in ts], [v * 1e3 for v in u], label=label)
        w = math.pi / half
        tt = [i * 1e-6 for i in range(801)]
        ax.plot([t * 1e6 for t in tt], [peak_cf / 2 * (1 - math.cos(w * t)) * 1e3 for t in tt], "k--",
                label="closed form (Lame, thin-shell period)")
        ax.set_xlabel("t [us]")
        ax.set_ylabel("mean radial displacement of the wall [mm]")
        ax.legend(fontsize=8)
        fig.tight_layout()
        fig.savefig(o.png, dpi=100)
        print(f"# wrote {o.png}")


if __name__ == "__main__":
    sys.exit(main())
