#!/usr/bin/env python3
"""Benchmark (not a test): ANFO rate-stick size effect with the ICE deck
ICE/JWLpp8mmRS.ups (JWL++ rate, Murnaghan reactant, JWLC products, air).

Usage:
  tests/bench/rate_stick_size_effect.py BUILD_DIR run  R_MM DX_MM [OUT_ROOT]
  tests/bench/rate_stick_size_effect.py BUILD_DIR front R_MM DX_MM [OUT_ROOT]
  tests/bench/rate_stick_size_effect.py BUILD_DIR plot  RESULTS.csv PNG

R_MM = 0 is the "infinite-diameter" stick the manual describes: one cell
across, the y+ and z+ faces made symmetry planes, the whole cross-section
explosive (a 1-D planar detonation). Otherwise the deck is the unchanged
quarter-symmetry stick with its cylinder radius set to R, the transverse
box to 15/8 R (the deck's 15 mm for 8 mm) rounded up to whole cells, and
the cell size to DX (the deck: 1 mm). Everything else (impact initiation
at 90 m/s, first-order advection, `conservative` time step, the JWL++
constants) is the deck's. Only F and press_CC are saved, every 0.2 us.

Front: the largest x of an axis cell with F >= 0.5 (as in
jwlpp8mmrs_front.py); speed: least-squares slope of x_front(t) over the
outputs with t >= 10 us and x_front <= 0.09 m (the last 1 cm of the 0.1 m
stick is dropped so that the open x+ end does not enter).
Figures: docs/validation/rate-stick-size-effect.md.
"""
import collections
import csv
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "decks"))
DECK = os.path.join(DECKS, "inputs", "ICE", "JWLpp8mmRS.ups")

SYMMETRY_FACE = '<Face side = "{s}">\n <BCType id = "all" var = "symmetry" label = "Symmetric"> </BCType>\n</Face>'


def make_deck(r_mm, dx_mm):
    text = open(DECK, encoding="iso-8859-1").read()
    text = text.replace('href="inputs/', 'href="' + os.path.join(DECKS, "inputs") + "/")
    dx = dx_mm * 1e-3
    nx = int(round(0.1 / dx))
    if r_mm == 0:
        ny, width, radius = 1, dx, 1.0
        for s in ("y+", "z+"):
            text = re.sub(r'<Face side = "%s">.*?</Face>' % re.escape(s), SYMMETRY_FACE.format(s=s), text,
                          count=1, flags=re.S)
    else:
        ny = int(math.ceil(15.0 / 8.0 * r_mm / dx_mm - 1e-9))
        width, radius = ny * dx, r_mm * 1e-3
    text = re.sub(r"<upper>.*?</upper>", f"<upper> [1.e-1,{width!r},{width!r}] </upper>", text, count=1)
    text = re.sub(r"<resolution>.*?</resolution>", f"<resolution> [{nx}, {ny}, {ny}] </resolution>", text, count=1)
    text = re.sub(r"<radius>.*?</radius>", f"<radius> {radius!r} </radius>", text, count=1)
    saves = '<save label="F"/>\n<save label="press_CC"/>\n'
    text = re.sub(r"(<outputInterval>.*?</outputInterval>).*?(</DataArchiver>)", r"\1\n" + saves + r"\2", text,
                  count=1, flags=re.S)
    return text, nx, ny


def out_dir(root, r_mm, dx_mm):
    return os.path.join(root, f"R{r_mm:g}_dx{dx_mm:g}")


def extract_front(tephra, out, dx):
    y = 0.5 * dx
    cmd = [tephra, "extract", out, "--var", "F", "--material", "0", "--all-times",
           "--line", f"{y},{y},{y},{0.1 - y},{y},{y}"]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rows = collections.defaultdict(list)
    for r in csv.DictReader(text.splitlines()):
        rows[float(r["time"])].append((float(r["x"]), float(r["F"])))
    front = []
    for t in sorted(rows):
        xs = [x for x, f in rows[t] if f >= 0.5]
        if xs:
            front.append((t, max(xs)))
    return front


def fit_slope(pts):
    n = len(pts)
    mt = sum(t for t, _ in pts) / n
    mx = sum(x for _, x in pts) / n
    return sum((t - mt) * (x - mx) for t, x in pts) / sum((t - mt) ** 2 for t, _ in pts)


def front_speed(tephra, out, dx):
    front = extract_front(tephra, out, dx)
    window = [(t, x) for t, x in front if t >= 10e-6 - 1e-12 and x <= 0.09]
    late = [(t, x) for t, x in window if t >= 14e-6 - 1e-12]
    slope = lambda pts: fit_slope(pts) if len(pts) > 2 else float("nan")  # nan: no front (failed)
    return front, slope(window), slope(late)


def main():
    build, mode = sys.argv[1], sys.argv[2]
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "plot":
        return plot(sys.argv[3], sys.argv[4])
    r_mm, dx_mm = float(sys.argv[3]), float(sys.argv[4])
    root = sys.argv[5] if len(sys.argv) > 5 else "/tmp/rate_stick"
    out = out_dir(root, r_mm, dx_mm)
    if mode == "run":
        text, nx, ny = make_deck(r_mm, dx_mm)
        os.makedirs(root, exist_ok=True)
        deck = out + ".ups"
        open(deck, "w").write(text)
        subprocess.run([tephra, deck, "--output", out, "--quiet"], check=True)
    front, d10, d14 = front_speed(tephra, out, dx_mm * 1e-3)
    for t, x in front[::5]:
        print(f"t = {t * 1e6:6.2f} us  front = {x * 1e3:6.2f} mm")
    print(f"R = {r_mm:g} mm, dx = {dx_mm:g} mm: D(10 us..) = {d10:.0f} m/s, D(14 us..) = {d14:.0f} m/s")


def plot(results, png):
    """RESULTS.csv: R_mm,dx_mm,D (R_mm = 0: infinite)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    rows = [r for r in csv.DictReader(open(results))]
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    # Guilkey, Harman & Banerjee (2007) ICE simulations and Souers et al. ANFO
    # experiments, as quoted in issue 6 (Vaango theory manual 26.3.1).
    ax.plot([0, 0.05, 0.08, 0.125, 0.1667], [5760, 5404, 4906, 4624, 4087], "s--", color="gray",
            label="Guilkey et al. 2007 (simulation)")
    ax.plot([0.0, 0.09, 0.09, 0.154], [5890, 4533, 4742, 3672], "k^", label="Souers et al. (experiment)")
    for dx in sorted({float(r["dx_mm"]) for r in rows}):
        pts = sorted((1 / float(r["R_mm"]) if float(r["R_mm"]) > 0 else 0.0, float(r["D"]))
                     for r in rows if float(r["dx_mm"]) == dx)
        ax.plot(*zip(*pts), "o-", label=f"Tephra ICE, dx = {dx:g} mm")
    ax.axhline(5899, color="C3", lw=0.8, ls=":", label="D_CJ of the JWLC products (5899 m/s)")
    ax.set_xlabel("1/R (1/mm)")
    ax.set_ylabel("detonation speed D (m/s)")
    ax.set_title("ANFO rate stick (JWL++), size effect")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    main()
