#!/usr/bin/env python3
"""Benchmark (not a test): refinement study of the Taylor impact deck
MPM/Impact/cylinderImpact_A_JC.ups (decks README A5; docs/models/taylor-impact.md).

Usage:
  tests/bench/taylor_impact_study.py BUILD_DIR [--work DIR] [--h MM[,MM...]]
                                     [--end T] [--no-run] [--threads N] [--wall rigid|symmetry]

For each grid spacing h (mm; default 1.0,0.75,0.5625, ratio 4/3) it writes a variant of the
deck to WORK/h<h>/deck.ups, runs `BUILD_DIR/bin/tephra` on it (one thread unless
--threads), times it, and reduces the output. The variants change only:
  * the grid: isotropic spacing h on the box x, z in [0, 9] mm, y in [-3, 36] mm,
    each end rounded outwards to a multiple of h
    (a node on the wall face y = 0 and on the axis planes for every h; the deck's
    own grid is 0.5 x 1.057 x 0.5 mm on [0,10] x [-2,35] x [0,10] mm, with no node
    at y = 0). Particles per cell stay the deck's: 3 x 3 x 3 in the rod,
    1 x 1 x 1 in the wall;
  * maxTime (--end, default 80 us: the deck's) and the output: every
    --interval (default 2 us), the deck's reductions plus AccStrainEnergy and
    PlasticWork, and the particles' ids, F and plastic strain; no checkpoints;
  * the include paths (made absolute, so the variant can live outside decks/).
Everything else (materials, contact, multiplier 0.8, boundary conditions) is the
deck's.

Reduced figures (session 17: the converging measures first):
  * L_rest/L_seed: the final length at rest (the minimum of L(t) over the frames at t >= 60 us
    when the rod stopped inside the run, else the vertex of the parabola through the last three
    frames; see rest_length) over the seeded rod's length (same measure at t = 0);
  * R_A/R_A,seed: the footprint radius of the first particle row (footprint_radius) at the
    rest frame (the last frame when L_rest is extrapolated) over t = 0.
Then, each from the last output frame:
  * final length L = max_p (y_p + a_y,p) where a_y,p = (l0/2) sum_j |F_yj| is the
    half extent along y of the particle's deformed cube of side l0 = h/3
    (the wall face is y = 0); also from particle centres alone;
  * foot radius R = max_p (r_p + a_r,p), r = sqrt(x^2 + z^2),
    a_r = (l0/2) sum_j |e_r . F e_j|, over the particles seeded in the bottom
    layer of cells (y0 < h) -- the mushroom's rim; also from centres alone;
  * energy: KE0 = sum 1/2 m v0^2 of the rod (227 m/s), and at the end
    KE + SE + W_p (KineticEnergy, StrainEnergy, PlasticWork .dat files) and the
    deficit (KE0 - KE - SE - W_p)/KE0; also AccStrainEnergy (total stress work).
  * the kinetic-energy ledger (mpm/EnergyLedger.h, saved by every variant): wall
    capture C, grid-BC removal B, FLIP transfer loss T, grid-force work G, and the
    work mismatch M = -G - SE - W_p, so that the deficit = C + B + T + M exactly.
--wall symmetry: the wall material and its rigid contact removed and the grid's
y- symmetry face put at y = 0 (a frictionless rigid wall as a mirror plane;
rod = material 0); the default (rigid) is the deck's own wall.
Richardson (three spacings h1 > h2 > h3 with a common ratio r = h1/h2 = h2/h3):
  p = ln((f1 - f2)/(f2 - f3))/ln r,  f_inf = f3 + (f3 - f2)/(r^p - 1).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
DECKS = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "decks", "inputs", "MPM"))
DECK = os.path.join(DECKS, "Impact", "cylinderImpact_A_JC.ups")

X_MAX, Y_MIN, Y_MAX = 9.0e-3, -3.0e-3, 36.0e-3  # variant box, each end rounded outwards to a multiple of h
V0 = 227.0                                        # the deck's impact speed [m/s]
L0, R0 = 32.4e-3, 3.2e-3                          # the deck's rod [m]
RHO = 8930.0                                      # MaterialConstAnnCopper.xml [kg/m^3]
# The kinetic-energy ledger (mpm/EnergyLedger.h): summed over the steps, KE - KE0 =
# GridForceWork - ContactKineticEnergyRemoved - BoundaryKineticEnergyRemoved - TransferKineticEnergyLoss.
LEDGER = ("ContactKineticEnergyRemoved", "BoundaryKineticEnergyRemoved", "GridForceWork", "TransferKineticEnergyLoss")
KE_NOMINAL = 0.5 * RHO * math.pi * R0 ** 2 / 4.0 * L0 * V0 ** 2  # quarter rod, 59.96 J


ROD = "1"  # the rod's material index (0 with --wall symmetry: the wall material is removed)


def box(h, wall="rigid"):
    """[0, x1] x [y0, y1] x [0, x1]: X_MAX, Y_MIN, Y_MAX rounded outwards to multiples of h
    (so y = 0, the wall face, and the symmetry planes are grid lines). With the wall as
    the symmetry face y- (--wall symmetry) the grid starts at y = 0."""
    up = lambda v: h * math.ceil(v / h - 1e-9)
    y0 = -up(-Y_MIN) if wall == "rigid" else 0.0
    return up(X_MAX), y0, y0 + up(Y_MAX - y0)


def write_variant(h, end, path, interval=2e-6, wall="rigid"):
    """The deck with the grid, end time, output and include paths changed (module doc).
    wall = "symmetry": the rigid wall material and the rigid contact removed, the grid's
    y- face (the deck's symmetry BC) moved to y = 0: a frictionless rigid wall as a mirror
    plane (the deck's rigid contact constrains only v_y too, direction [0,1,0])."""
    text = open(DECK, encoding="latin-1").read()
    if wall == "symmetry":
        a = text.index("<material>")
        b = text.index("</material>", a) + len("</material>")
        text = text[:a] + text[b:]
        a = text.index("<contact>")
        b = text.index("</contact>", a) + len("</contact>")
        text = text[:a] + text[b:]
    text = text.replace('href="../MaterialData/', 'href="' + os.path.join(DECKS, "MaterialData") + "/")
    text = re.sub(r"<maxTime>[^<]*</maxTime>", f"<maxTime>{end:.6e}</maxTime>", text)
    # Output every `interval` (reductions and particles alike): only the particle
    # labels the reduction needs (positions come with every particle block).
    text = re.sub(r"<outputInterval>[^<]*</outputInterval>", f"<outputInterval>{interval:.6e}</outputInterval>", text)
    text = re.sub(r"\s*<checkpoint[^>]*/>", "", text)
    text = re.sub(r'\s*<save label = "g\.[^"]*"/>', "", text)
    for label in ("p.x", "p.velocity", "p.mass", "p.volume", "p.stress", "p.damage"):
        text = text.replace(f'<save label = "{label}"/>', "")
    text = text.replace('<save label = "StrainEnergy"/>',
                        '<save label = "StrainEnergy"/>\n    <save label = "AccStrainEnergy"/>\n'
                        '    <save label = "PlasticWork"/>\n    <save label = "p.particleID"/>\n'
                        + "".join(f'    <save label = "{l}"/>\n' for l in LEDGER))
    x1, y0, y1 = box(h, wall)
    nx, ny = int(round(x1 / h)), int(round((y1 - y0) / h))
    text = re.sub(r"<lower>[^<]*</lower>", f"<lower>[0.0,{y0:.9e},0.0]</lower>", text)
    text = re.sub(r"<upper>[^<]*</upper>", f"<upper>[{x1:.9e},{y1:.9e},{x1:.9e}]</upper>", text)
    text = re.sub(r"<resolution>[^<]*</resolution>", f"<resolution>[{nx},{ny},{nx}]</resolution>", text)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="latin-1") as f:
        f.write(text)


def read_dat(path):
    """Rows (t, values...) of a reduction .dat file."""
    rows = []
    for line in open(path):
        parts = line.replace("[", " ").replace("]", " ").replace(",", " ").split()
        if not parts or parts[0].startswith("#"):
            continue
        try:
            rows.append([float(v) for v in parts])
        except ValueError:
            continue
    return rows


def extract(tephra, out, var, step="last"):
    """{particle id: values} of material 1 (the rod) at the given output step."""
    text = subprocess.run([tephra, "extract", out, "--var", var, "--material", ROD, "--step", str(step)],
                          check=True, capture_output=True, text=True).stdout
    rdr = csv.reader(text.splitlines())
    head = next(rdr)
    return head, [r for r in rdr]


def particle_table(tephra, out, step):
    """id -> (x, y, z, F (9, row-major), mass, velocity) of the rod at an output step."""
    head, rows = extract(tephra, out, "p.deformationMeasure", step)
    ix = {k: i for i, k in enumerate(head)}
    pid = next(k for k in head if k in ("particle_id", "id", "particleID"))
    fcols = [k for k in head if k.startswith("p.deformationMeasure")]
    table = {}
    for r in rows:
        table[int(float(r[ix[pid]]))] = ([float(r[ix[k]]) for k in ("x", "y", "z")],
                                         [float(r[ix[k]]) for k in fcols])
    return table


def extents(table, first, h):
    """(L, R, L from centres, R from centres, y of the rim) of one frame (module doc)."""
    l0 = h / 3.0
    L_c = L_e = R_c = R_e = 0.0
    y_rim = 0.0
    for i, (x, F) in table.items():
        Fm = [F[0:3], F[3:6], F[6:9]]
        L_c = max(L_c, x[1])
        L_e = max(L_e, x[1] + 0.5 * l0 * sum(abs(v) for v in Fm[1]))
        if first[i][0][1] < h:  # seeded in the bottom layer of cells: the foot
            r = math.hypot(x[0], x[2])
            er = (x[0] / r, 0.0, x[2] / r) if r > 0 else (1.0, 0.0, 0.0)
            a_r = 0.5 * l0 * sum(abs(er[0] * Fm[0][j] + er[2] * Fm[2][j]) for j in range(3))
            R_c = max(R_c, r)
            if r + a_r > R_e:
                R_e, y_rim = r + a_r, x[1]
    return L_e, R_e, L_c, R_c, y_rim


def frames(out):
    """Output steps of the run's particle frames (out/frames/t<step>.h5), in order."""
    return sorted(int(m.group(1)) for f in os.listdir(os.path.join(out, "frames"))
                  if (m := re.match(r"t(\d+)\.h5$", f)))


def frame_time(tephra, out, step):
    head, rows = extract(tephra, out, "p.deformationMeasure", step)
    return float(rows[0][head.index("time")])


def footprint_radius(table, first, h):
    """R_A = sqrt(4 A / pi) [m] of the deformed footprint of the first particle row (seeded at
    y0 < h/3, the row on the wall): A = sum (h/3)^2 |cof(F)_yy| (cof(F)_yy = F_xx F_zz - F_xz F_zx,
    the deformed area of the particle's y-face); a quarter rod, so A is a quarter disc. An
    integral measure (the max-extent R of one rim particle is first order on its own; session 16)."""
    l = h / 3.0
    area = sum(l * l * abs(F[0] * F[8] - F[2] * F[6]) for i, (x, F) in table.items() if first[i][0][1] < l)
    return math.sqrt(4.0 * area / math.pi)


def rest_extrapolation(hist):
    """(t_rest, L_rest) from the parabola through the last three (t, L): near the stop the rod's
    top decelerates about uniformly, L(t) = L_rest + (a/2)(t_rest - t)^2, vertex (t_rest, L_rest).
    When the last three frames are not still falling and decelerating, the smallest of them."""
    (t1, l1), (t2, l2), (t3, l3) = [(r[0], r[1]) for r in hist[-3:]]
    # Divided differences: L = l3 + b (t - t3) + c (t - t3)(t - t2).
    d1, d2 = (l2 - l1) / (t2 - t1), (l3 - l2) / (t3 - t2)
    c = (d2 - d1) / (t3 - t1)
    b = d2 + c * (t3 - t2)  # L'(t3)
    if c <= 0 or b >= 0:
        return t3, min(l1, l2, l3)
    tv = t3 - b / (2 * c)  # L'(tv) = 0
    return tv, l3 + b * (tv - t3) + c * (tv - t3) ** 2


def rest_length(tephra, out, first, h, since):
    """Final length at rest: L(t) over the frames at t >= since; if its minimum lies before the
    last frame the rod stopped inside the run (the top's elastic spring-back follows) and
    L_rest = that minimum ("measured"); otherwise the rod is still shortening at the end and
    L_rest is the parabola's vertex through the last three frames ("extrapolated").
    Returns (L_rest, t_rest, how, [(t, L)], the output step of the rest frame (the last frame
    when extrapolated))."""
    hist, steps = [], []
    for s in frames(out):
        t = frame_time(tephra, out, s)
        if t < since:
            continue
        hist.append((t, extents(particle_table(tephra, out, s), first, h)[0]))
        steps.append(s)
    k = min(range(len(hist)), key=lambda i: hist[i][1])
    if k < len(hist) - 1:
        return hist[k][1], hist[k][0], "measured", hist, steps[k]
    tr, lr = rest_extrapolation(hist)
    return lr, tr, "extrapolated", hist, steps[-1]


def shape(tephra, out, h, since=60e-6):
    """Final length and foot radius (module doc) from the first and last frames; also the
    seeded rod's L and R (same measure at t = 0: the staircase seeding is O(h/3))."""
    first = particle_table(tephra, out, 0)
    last = particle_table(tephra, out, "last")
    L_e, R_e, L_c, R_c, y_rim = extents(last, first, h)
    L_0, R_0 = extents(first, first, h)[:2]
    L_rest, t_rest, how, _, rest_step = rest_length(tephra, out, first, h, since)
    # the footprint at the rest frame (measured) or the last frame (extrapolated: R_A is flat by then)
    RA_0, RA = footprint_radius(first, first, h), footprint_radius(particle_table(tephra, out, rest_step), first, h)
    return {"L_centres": L_c, "L": L_e, "R_centres": R_c, "R": R_e, "y_rim": y_rim, "particles": len(last),
            "L_seed": L_0, "R_seed": R_0, "L_rel": L_e / L_0, "R_rel": R_e / R_0,
            "L_rest": L_rest, "t_rest": t_rest, "rest_how": how, "L_rest_rel": L_rest / L_0,
            "RA": RA, "RA_seed": RA_0, "RA_rel": RA / RA_0}


def energy(out):
    ke = read_dat(os.path.join(out, "KineticEnergy.dat"))
    se = read_dat(os.path.join(out, "StrainEnergy.dat"))
    wp = read_dat(os.path.join(out, "PlasticWork.dat"))
    acc = read_dat(os.path.join(out, "AccStrainEnergy.dat"))
    return ke, se, wp, acc


def ledger(out):
    """The ledger's values at the last output, {label: J} (empty if the run did not save them)."""
    res = {}
    for l in LEDGER:
        path = os.path.join(out, l + ".dat")
        if os.path.exists(path):
            res[l] = read_dat(path)[-1][1]
    return res


def richardson(h, f):
    """Observed order and extrapolated value from three spacings with a common ratio."""
    r = h[0] / h[1]
    d1, d2 = f[0] - f[1], f[1] - f[2]
    if d1 == 0 or d2 == 0 or d1 / d2 <= 0:
        return float("nan"), float("nan")
    p = math.log(d1 / d2) / math.log(r)
    return p, f[2] + (f[2] - f[1]) / (r ** p - 1.0)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--work", default="/tmp/taylor_study")
    ap.add_argument("--h", default="1.0,0.75,0.5625")
    ap.add_argument("--end", type=float, default=80e-6)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--interval", type=float, default=2e-6)
    ap.add_argument("--no-run", action="store_true")
    ap.add_argument("--wall", choices=("rigid", "symmetry"), default="rigid")
    a = ap.parse_args()
    global ROD
    ROD = "1" if a.wall == "rigid" else "0"
    tephra = os.path.join(os.path.abspath(a.build), "bin", "tephra")
    hs = [float(v) * 1e-3 for v in a.h.split(",")]
    results = []
    for h in hs:
        d = os.path.join(a.work, f"h{h * 1e3:.4f}" + ("" if a.wall == "rigid" else "_symmetry"))
        deck, out = os.path.join(d, "deck.ups"), os.path.join(d, "out")
        wall = float("nan")
        if not a.no_run:
            write_variant(h, a.end, deck, a.interval, a.wall)
            t0 = time.time()
            with open(os.path.join(d, "log.txt"), "w") as log:
                rc = subprocess.run([tephra, deck, "--output", out, "--threads", str(a.threads)],
                                    stdout=log, stderr=subprocess.STDOUT).returncode
            wall = time.time() - t0
            with open(os.path.join(d, "wall.txt"), "w") as f:
                f.write(f"{wall:.1f} {rc}\n")
            if rc != 0:
                print(f"h = {h * 1e3:.4f} mm: tephra exit {rc} (see {d}/log.txt)")
                continue
        elif os.path.exists(os.path.join(d, "wall.txt")):
            wall = float(open(os.path.join(d, "wall.txt")).read().split()[0])
        s = shape(tephra, out, h)
        ke, se, wp, acc = energy(out)
        ke0 = ke[0][1] if ke[0][0] == 0.0 else None
        # KE0 of the rod from its particles' masses: M v0^2 / 2 (the wall is at rest).
        mass = read_dat(os.path.join(out, "TotalMass.dat"))
        # TotalMass includes the wall (rho = 1e9): the rod's mass is taken from KE at t = 0.
        ke0 = ke[0][1]
        t_end = ke[-1][0]
        budget = ke[-1][1] + se[-1][1] + wp[-1][1]
        deficit = (ke0 - budget) / ke0
        steps = len(ke)
        # the time the kinetic energy first falls below 1 % and 0.5 % of KE0
        t1 = next((r[0] for r in ke if r[1] < 0.01 * ke0), float("nan"))
        t05 = next((r[0] for r in ke if r[1] < 0.005 * ke0), float("nan"))
        d2 = (ke0 - ke[1][1] - se[1][1] - wp[1][1]) / ke0  # at the first output after t = 0
        worst = max(((ke0 - (k[1] + s_[1] + w[1])) / ke0 for k, s_, w in zip(ke, se, wp)), default=float("nan"))
        lg = ledger(out)
        res = dict(h=h, wall=wall, steps=steps, t_end=t_end, ke0=ke0, ke=ke[-1][1], se=se[-1][1], wp=wp[-1][1],
                   acc=acc[-1][1], deficit=deficit, deficit_first=d2, worst=worst, t1=t1, t05=t05, **s)
        results.append(res)
        print(f"h = {h * 1e3:.4f} mm: {s['particles']} rod particles, {steps} rows, wall {wall:.0f} s, "
              f"t_end {t_end * 1e6:.2f} us")
        print(f"  L = {s['L'] * 1e3:.3f} mm (centres {s['L_centres'] * 1e3:.3f}), L/L0 = {s['L'] / L0:.4f}; "
              f"R = {s['R'] * 1e3:.3f} mm (centres {s['R_centres'] * 1e3:.3f}, rim at y = {s['y_rim'] * 1e3:.3f} mm), "
              f"R/R0 = {s['R'] / R0:.4f}")
        print(f"  at rest ({s['rest_how']}, t_rest {s['t_rest'] * 1e6:.2f} us): L_rest = {s['L_rest'] * 1e3:.3f} mm, "
              f"L_rest/L_seed = {s['L_rest_rel']:.4f}, L_rest/L0 = {s['L_rest'] / L0:.4f}; footprint radius "
              f"R_A = {s['RA'] * 1e3:.3f} mm (seeded {s['RA_seed'] * 1e3:.3f} mm), R_A/R_A,seed = {s['RA_rel']:.4f}")
        print(f"  seeded rod: L {s['L_seed'] * 1e3:.3f} mm, R {s['R_seed'] * 1e3:.3f} mm; "
              f"L/L_seed = {s['L_rel']:.4f}, R/R_seed = {s['R_rel']:.4f}; "
              f"volume-equivalent radius {R0 * math.sqrt(ke0 / KE_NOMINAL) * 1e3:.3f} mm")
        print(f"  KE0 {ke0:.4f} J; end: KE {ke[-1][1]:.4f} SE {se[-1][1]:.4f} Wp {wp[-1][1]:.4f} "
              f"AccSE {acc[-1][1]:.4f} J; deficit (KE0-KE-SE-Wp)/KE0 = {deficit * 100:.3f} % "
              f"(largest over the run {worst * 100:.3f} %; {d2 * 100:.3f} % at {ke[1][0] * 1e6:.2f} us); KE < 1 % KE0 from {t1 * 1e6:.1f} us, "
              f"< 0.5 % from {t05 * 1e6:.1f} us")
        if len(lg) == len(LEDGER):
            c, b, g, tr = (lg[l] for l in LEDGER)
            mismatch = -g - se[-1][1] - wp[-1][1]  # work the node forces took from KE minus SE + Wp
            res.update(contact=c / ke0, boundary=b / ke0, transfer=tr / ke0, mismatch=mismatch / ke0,
                       acc_mismatch=(-g - acc[-1][1]) / ke0)
            print(f"  ledger (% of KE0): wall/contact {100 * c / ke0:.3f}, grid BCs {100 * b / ke0:.4f}, "
                  f"FLIP transfer {100 * tr / ke0:.4f}, grid-force work - (SE + Wp) {100 * mismatch / ke0:.4f} "
                  f"(- AccStrainEnergy: {100 * (-g - acc[-1][1]) / ke0:.4f}); sum {100 * (c + b + tr + mismatch) / ke0:.3f} "
                  f"vs deficit {100 * deficit:.3f}; identity KE - KE0 - (G - C - B - T) = "
                  f"{(ke[-1][1] - ke0 - (g - c - b - tr)) / ke0:.2e} KE0")
    if len(results) == 3:
        hh = [r["h"] for r in results]
        print("Richardson (ratio %.4f):" % (hh[0] / hh[1]))
        for key, scale, unit in (("L_rest_rel", 1, ""), ("RA_rel", 1, ""), ("L_rest", 1e3, "mm"), ("RA", 1e3, "mm"),
                                 ("L", 1e3, "mm"), ("R", 1e3, "mm"), ("L_centres", 1e3, "mm"),
                                 ("R_centres", 1e3, "mm"), ("L_rel", 1, ""), ("R_rel", 1, ""), ("deficit", 100, "%"),
                                 ("deficit_first", 100, "%"), ("contact", 100, "%"), ("transfer", 100, "%"),
                                 ("mismatch", 100, "%")):
            if not all(key in r for r in results):
                continue
            f = [r[key] for r in results]
            p, finf = richardson(hh, f)
            print(f"  {key}: {' -> '.join(f'{v * scale:.4f}' for v in f)} {unit}; observed order {p:.2f}, "
                  f"extrapolated {finf * scale:.4f} {unit}")


if __name__ == "__main__":
    sys.exit(main())
