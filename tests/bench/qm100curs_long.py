#!/usr/bin/env python3
"""Benchmark (not a test): the copper cylinder test at 25 cm, axisymmetric
(issue 6, Vaango manual sec. 26.3.2; deck inputs/validation/qm100curs_axisym_long.ups,
the stock MPMICE/QM100CuRS.ups made axisymmetric and lengthened to 300 mm;
its header lists every change).

Usage:
  tests/bench/qm100curs_long.py BUILD_DIR run      OUT [--end-time T] [--dx 0.5e-3]
  tests/bench/qm100curs_long.py BUILD_DIR analyse  OUT [--png-dir DIR] [--dx 0.5e-3]

--dx: the cell size; the deck is at 1 mm (48 x 305 cells), and `run` with
--dx 0.5e-3 writes OUT.ups, the same deck with <resolution> scaled to
96 x 610 (particles per cell unchanged), and runs that. `analyse` needs the
same --dx (the axis column r = dx/2 and the outer copper row r > R_out - dx/2);
figures and CSV other than at 1 mm are named qm100curs-long-<dx>mm-*.
  tests/bench/qm100curs_long.py selftest           (the Gurney arithmetic against hand values)

Front: the largest axial y of a cell of the first radial column (r = dx/2)
whose reacted fraction F >= 0.5; D: least-squares slope over the outputs
with the front in [FIT_LO, FIT_HI]. Lead shock: the largest y with press_CC
above the JWL++ ThresholdPressure (200 MPa). Wall: the copper particles of
the outermost radial row (initial r > R_OUT - 0.5 mm) within 0.5 mm of each
station y_s; their mean radial velocity v_r and radial displacement
r - r_0 at every output.

Gurney (cylinder; Kennedy's form):  v = sqrt(2E) / sqrt(M/C + 1/2),
with M/C the wall-to-charge mass ratio per unit length,
  M/C = rho_Cu (R_out^2 - R_in^2) / (rho_HE R_in^2)
      = 8930 (30.6^2 - 25.4^2) / (1260 x 25.4^2) = 3.199,
and sqrt(2E) ~ D / 2.97 (Kamlet & Finger's rule for the Gurney velocity
from the detonation speed). The wall's "plateau" in a cylinder test is read
at a radial expansion of a few wall thicknesses (the standard reading of the
LLNL test is at R - R_0 = 6 and 19 mm for a 25.4 mm bore).
"""
import collections
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from jwlppcurs2d import extract, plot_series  # noqa: E402
from qm100curs import front_history  # noqa: E402
from rate_stick_size_effect import fit_slope  # noqa: E402

DECK = os.path.normpath(os.path.join(HERE, "..", "..", "inputs", "validation", "qm100curs_axisym_long.ups"))
DX = 1.0e-3  # the deck's cell size; --dx changes it
R_IN, R_OUT = 25.4e-3, 30.6e-3
RHO_CU, RHO_HE = 8930.0, 1260.0
STATIONS = (0.100, 0.150, 0.200, 0.250)
FIT_LO, FIT_HI = 0.150, 0.280
P_SHOCK = 2.0e8  # qm100curs.front_history's threshold too (the JWL++ ThresholdPressure)
EXPANSIONS = (0.005, 0.010, 0.015)  # R - R_0 at which v_r is read [m]


def m_over_c(r_in=R_IN, r_out=R_OUT):
    return RHO_CU * (r_out ** 2 - r_in ** 2) / (RHO_HE * r_in ** 2)


def gurney_cylinder(d, mc=None):
    mc = m_over_c() if mc is None else mc
    return d / 2.97 / math.sqrt(mc + 0.5)


def selftest():
    # Hand values: 30.6^2 = 936.36, 25.4^2 = 645.16, difference 291.2;
    # 8930 x 291.2 / (1260 x 645.16) = 2600416 / 812901.6 = 3.19899.
    assert abs(m_over_c() - 2600416.0 / 812901.6) < 1e-12
    # D = 6502.5 m/s (jwlc_cj.py on the deck's JWLC products): sqrt(2E) =
    # 2189.4 m/s, v = 2189.4 / sqrt(3.69899) = 1138.4 m/s.
    v = gurney_cylinder(6502.5)
    assert abs(v - 6502.5 / 2.97 / math.sqrt(2600416.0 / 812901.6 + 0.5)) < 1e-9
    assert abs(v - 1138.4) < 0.1, v
    # The planar sandwich of the same wall (qm100curs.py) is faster: + 1/3, M/C = 1.451.
    assert gurney_cylinder(6502.5, 1.451) > v
    # --dx 0.5e-3: the deck with only <resolution> changed, to [96, 610, 1].
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        fine = open(scaled_deck(0.5e-3, os.path.join(tmp, "d.ups"))).read().splitlines()
    base = open(DECK).read().splitlines()
    changed = [(a, b) for a, b in zip(base, fine) if a != b]
    assert len(base) == len(fine) and len(changed) == 1 and "[96, 610, 1]" in changed[0][1], changed
    assert stem(DX) == "qm100curs-long" and stem(0.5e-3) == "qm100curs-long-0.5mm"
    print("qm100curs_long selftest: ok (M/C = %.5f, Gurney at D_CJ = %.1f m/s)" % (m_over_c(), v))


def axis_history(tephra, out, dx=DX):
    """(t, front y, lead-shock y) on the first radial column (qm100curs.front_history along y)."""
    y = 0.5 * dx
    line = f"{y},-0.0045,{y},{y},0.2995,{y}"
    return [(t, yf, ys) for t, yf, ys, _ in front_history(tephra, out, line, "y")]


def wall_history(tephra, out, dx=DX):
    rows = extract(tephra, out, "p.velocity", 0)
    pos = extract(tephra, out, "p.x", 0)
    t0 = min(float(r["time"]) for r in rows)
    start = {r["particle_id"]: (float(r["x"]), float(r["y"])) for r in rows if float(r["time"]) == t0}
    groups = {s: {i for i, (r, y) in start.items() if r > R_OUT - 0.5 * dx and abs(y - s) <= 0.5e-3}
              for s in STATIONS}
    where = {(r["time"], r["particle_id"]): float(r["x"]) for r in pos}
    acc = {s: collections.defaultdict(list) for s in STATIONS}
    for r in rows:
        for s in STATIONS:
            if r["particle_id"] in groups[s]:
                dr = where.get((r["time"], r["particle_id"]), start[r["particle_id"]][0]) - start[r["particle_id"]][0]
                acc[s][float(r["time"])].append((float(r["p.velocity_x"]), dr))
    out_h = {}
    for s in STATIONS:
        out_h[s] = [(t, sum(v for v, _ in vals) / len(vals), sum(d for _, d in vals) / len(vals), len(vals))
                    for t, vals in sorted(acc[s].items())]
    return out_h, {s: len(g) for s, g in groups.items()}


def at_expansion(h, dr):
    """v_r where the mean displacement first reaches dr (linear between outputs), or None."""
    for (t0, v0, d0, _), (t1, v1, d1, _) in zip(h, h[1:]):
        if d0 < dr <= d1:
            a = (dr - d0) / (d1 - d0)
            return v0 + a * (v1 - v0), t0 + a * (t1 - t0)
    return None


def stem(dx):
    return "qm100curs-long" if dx == DX else f"qm100curs-long-{dx * 1e3:g}mm"


def scaled_deck(dx, path):
    """The deck with <resolution> [48, 305, 1] scaled by DX/dx (an integer), written to path."""
    k = round(DX / dx)
    assert k >= 1 and abs(k * dx - DX) < 1e-12 * DX, f"--dx must divide {DX} m"
    text = open(DECK).read()
    old = "<resolution>   [48, 305, 1]"
    assert text.count(old) == 1, "deck's <resolution> line changed: update scaled_deck"
    with open(path, "w") as fh:
        fh.write(text.replace(old, f"<resolution>   [{48 * k}, {305 * k}, 1]"))
    return path


def analyse(tephra, out, png_dir, dx=DX):
    hist = axis_history(tephra, out, dx)
    nan = float("nan")
    for t, yf, ys in hist[::2]:
        print(f"t = {t * 1e6:6.2f} us  front (F >= 0.5) = {yf * 1e3 if yf else nan:6.1f} mm"
              f"  lead shock = {ys * 1e3 if ys else nan:6.1f} mm")
    pts = [(t, y) for t, y, _ in hist if y is not None and FIT_LO <= y <= FIT_HI]
    d = fit_slope(pts) if len(pts) > 2 else nan
    print(f"D = {d:.0f} m/s over {len(pts)} outputs (front in [{FIT_LO * 1e3:g}, {FIT_HI * 1e3:g}] mm)")
    g = gurney_cylinder(d) if d == d else nan
    print(f"Gurney (cylinder, sqrt(2E) = D/2.97, M/C = {m_over_c():.3f}): {g:.0f} m/s")
    wall, sizes = wall_history(tephra, out, dx)
    csv_rows = [("front_y_m", t, y) for t, y, _ in hist] + [("shock_y_m", t, y) for t, _, y in hist]
    for s, h in wall.items():
        vmax = max((v for _, v, _, _ in h), default=nan)
        reads = [(dr, at_expansion(h, dr)) for dr in EXPANSIONS]
        txt = ", ".join(f"R-R0 = {dr * 1e3:g} mm: " + (f"{r[0]:.0f} m/s at {r[1] * 1e6:.1f} us" if r else "not reached")
                        for dr, r in reads)
        last = h[-1] if h else (nan, nan, nan, 0)
        print(f"wall at y = {s * 1e3:.0f} mm ({sizes[s]} particles; {last[3]} left at the end): max v_r = {vmax:.0f} m/s;"
              f" {txt}; last output t = {last[0] * 1e6:.1f} us, v_r = {last[1]:.0f}, R-R0 = {last[2] * 1e3:.2f} mm")
        csv_rows += [(f"wall_vr_m_per_s_at_y_{s * 1e3:.0f}mm", t, v) for t, v, _, _ in h]
        csv_rows += [(f"wall_dr_m_at_y_{s * 1e3:.0f}mm", t, dr) for t, _, dr, _ in h]
    os.makedirs(png_dir, exist_ok=True)
    with open(os.path.join(png_dir, stem(dx) + ".csv"), "w") as fh:
        fh.write("quantity,time_s,value\n")
        for q, t, v in csv_rows:
            fh.write(f"{q},{t:.6e},{'' if v is None else f'{v:.6e}'}\n")
    colours = [(30, 90, 220), (20, 160, 60), (200, 120, 0), (200, 0, 0)]
    tmax = max(t for t, _, _ in hist)
    tt = 10.0 * (int(tmax * 1e6 / 10.0) + 1)
    xt = [10.0 * k for k in range(int(tt / 10) + 1)]
    series = [([(t * 1e6, v) for t, v, _, _ in h], colours[k]) for k, h in enumerate(wall.values())]
    legend = [(f"Y = {s * 1e3:.0f} MM", colours[k]) for k, s in enumerate(wall)]
    vt = 1400.0
    if g == g:
        series.append(([(0.0, g), (tt, g)], (0, 0, 0)))
        legend.append((f"GURNEY {g:.0f} M/S", (0, 0, 0)))
    plot_series(os.path.join(png_dir, stem(dx) + "-wall-velocity.png"), series, (0.0, tt), (0.0, vt), xt,
                [200.0 * k for k in range(8)], "T (US)", "WALL RADIAL VELOCITY V_R (M/S), OUTER COPPER ROW", legend)
    plot_series(os.path.join(png_dir, stem(dx) + "-front.png"),
                [([(t * 1e6, None if y is None else y * 1e3) for t, y, _ in hist], colours[0]),
                 ([(t * 1e6, None if y is None else y * 1e3) for t, _, y in hist], colours[3])],
                (0.0, tt), (0.0, 300.0), xt, [50.0 * k for k in range(7)], "T (US)", "Y (MM) ON THE AXIS",
                [("REACTION FRONT F >= 0.5", colours[0]), (f"LEAD SHOCK P > {P_SHOCK / 1e6:.0f} MPA", colours[3])])
    return d


def main():
    if sys.argv[1] == "selftest":
        return selftest()
    build, mode = sys.argv[1], sys.argv[2]
    args = list(sys.argv[3:])
    opts = {}
    for key in ("--end-time", "--png-dir", "--dx"):
        if key in args:
            i = args.index(key)
            opts[key] = args[i + 1]
            del args[i:i + 2]
    out = os.path.abspath(args[0] if args else "/tmp/qm100curs_long")
    tephra = os.path.join(build, "bin", "tephra")
    dx = float(opts.get("--dx", DX))
    if mode == "run":
        deck = DECK if dx == DX else scaled_deck(dx, out.rstrip("/") + ".ups")
        cmd = [tephra, deck, "--output", out, "--threads", "1", "--quiet"]
        if "--end-time" in opts:
            cmd += ["--end-time", opts["--end-time"]]
        subprocess.run(cmd, check=True)
    analyse(tephra, out, opts.get("--png-dir", out), dx)


if __name__ == "__main__":
    main()
