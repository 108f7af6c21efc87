#!/usr/bin/env python3
"""Benchmark (not a test): the copper "cylinder test" MPMICE/QM100CuRS.ups
(decks README C5, Vaango manual sec. 26.3.2), run through `tephra`:
detonation front against time, front speed, and the copper wall's radial
velocity against time, with the Gurney estimate of its plateau.

Usage:
  tests/bench/qm100curs.py BUILD_DIR run     [OUT] [--end-time T]
  tests/bench/qm100curs.py BUILD_DIR analyse [OUT] [--png-dir DIR]
(run: the deck unchanged, from its folder, --threads 1; a long run is best
started by hand with nice -n 19 and continued with `tephra --restart OUT`.
analyse: prints the histories and writes DIR/qm100curs-wall-velocity.png,
DIR/qm100curs-front.png and DIR/qm100curs.csv; DIR defaults to OUT.)

The deck is 2-D planar (110 x 64 x 1 cells of 0.5 mm, x in [-5, 50] mm,
y in [0, 32] mm, symmetry at x-, y-, z+-): its "cylinders" are slabs: QM-100
(JWL++ reactant, Murnaghan, rho 1260) of half-thickness 25.4 mm from
x = 1 mm on, in a copper wall 25.4 to 30.6 mm (comp_neo_hook_plastic), air
outside; a 1 mm "whacker" of the explosive at 400 m/s starts it at x = 0.
Materials: 0 copper (MPM), 1 reactant, 2 product, 3 air.

Front: the largest x of an axis cell (y = z = dx/2) whose reacted fraction
F (saved on the reactant) is at least 0.5; speed: least-squares slope over
the outputs with t >= T_FIT until the front first passes X_FIT_END (the x+
face is at 50 mm). Lead shock: the largest axis x with press_CC above the
deck's ThresholdPressure (200 MPa), and the largest axis pressure: the
shock-to-detonation build-up before any cell reaches F = 0.5. Wall velocity: the mean v_y of the copper particles of
the outermost layer (initial y > 30.6 mm - dx/2) within 0.5 mm of
x = 10, 20, 30, 40 mm, at every output.

Gurney (symmetric sandwich, the planar form of the cylinder test):
  v = sqrt(2E) / sqrt(M/C + 1/3),   sqrt(2E) ~ D / 2.97 (Kamlet & Finger),
M = rho_Cu * 5.2 mm (wall, per unit area), C = rho_HE * 25.4 mm (half the
charge): M/C = 8930 * 5.2 / (1260 * 25.4) = 1.451. The 25 cm station of
the real test lies outside the deck's 50 mm domain.
"""
import collections
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from jwlppcurs2d import extract, plot_series, until_the_end  # noqa: E402
from rate_stick_size_effect import fit_slope  # noqa: E402

DECKS = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "decks"))
DECK_DIR = os.path.join(DECKS, "inputs", "MPMICE")
DECK = "QM100CuRS.ups"
DX = 0.5e-3
R_OUT = 30.6e-3
STATIONS = (0.010, 0.020, 0.030, 0.040)
T_FIT, X_FIT_END = 2e-6, 0.045
P_SHOCK = 2.0e8  # the deck's JWL++ ThresholdPressure: the lead shock starts the burn
M_OVER_C = 8930.0 * 5.2e-3 / (1260.0 * 25.4e-3)


def gurney_sandwich(d):
    return d / 2.97 / math.sqrt(M_OVER_C + 1.0 / 3.0)


def front_history(tephra, out, line=None, axis="x"):
    """Per output: (t, position of the reaction front (F >= 0.5) or None, of
    the lead shock (p > P_SHOCK) or None, the largest pressure on the line).
    line: the `tephra extract --line` of the axis cells (default this deck's
    axis row), axis: the coordinate along it ("x"; "y" for the axisymmetric
    deck of qm100curs_long.py)."""
    y = 0.5 * DX
    line = line or f"-0.00499,{y},{y},0.04999,{y},{y}"
    f_rows, p_rows = collections.defaultdict(list), collections.defaultdict(list)
    for r in extract(tephra, out, "F", 1, line):
        f_rows[float(r["time"])].append((float(r[axis]), float(r["F"])))
    for r in extract(tephra, out, "press_CC", 0, line):
        p_rows[float(r["time"])].append((float(r[axis]), float(r["press_CC"])))
    hist = []
    for t in sorted(f_rows):
        xf = [x for x, f in f_rows[t] if f >= 0.5]
        xp = [x for x, p in p_rows.get(t, []) if p > P_SHOCK]
        pmax = max([p for _, p in p_rows.get(t, [])] + [0.0])
        hist.append((t, max(xf) if xf else None, max(xp) if xp else None, pmax))
    return hist


def wall_history(tephra, out):
    rows = extract(tephra, out, "p.velocity", 0)
    if not rows:
        return {}
    t0 = min(float(r["time"]) for r in rows)
    start = {r["particle_id"]: (float(r["x"]), float(r["y"])) for r in rows if float(r["time"]) == t0}
    groups = {s: {i for i, (x, y) in start.items() if y > R_OUT - DX / 2 and abs(x - s) <= 0.5e-3}
              for s in STATIONS}
    hist = {s: collections.defaultdict(list) for s in STATIONS}
    for r in rows:
        for s in STATIONS:
            if r["particle_id"] in groups[s]:
                hist[s][float(r["time"])].append(float(r["p.velocity_y"]))
    return {s: sorted((t, sum(v) / len(v)) for t, v in hist[s].items()) for s in STATIONS}


def analyse(tephra, out, png_dir):
    hist = front_history(tephra, out)
    for t, xf, xs, pm in hist:
        nan = float("nan")
        print(f"t = {t * 1e6:6.2f} us  reaction front (F >= 0.5) = {xf * 1e3 if xf is not None else nan:6.2f} mm"
              f"  shock (p > {P_SHOCK:.0e} Pa) = {xs * 1e3 if xs is not None else nan:6.2f} mm"
              f"  max axis p = {pm:.3g} Pa")
    front = [(t, xf) for t, xf, _, _ in hist]
    shock = [(t, xs) for t, _, xs, _ in hist]
    for name, series in (("shock", shock), ("reaction front", front)):
        prev = None
        for t, x in series:
            if x is not None and prev is not None and t > prev[0]:
                print(f"   {name} speed {t * 1e6:6.2f} us: {(x - prev[1]) / (t - prev[0]):7.0f} m/s")
            prev = (t, x) if x is not None else prev
    pts = []
    for t, x in front:
        if x is not None and x > X_FIT_END:
            break
        if x is not None and t >= T_FIT - 1e-12:
            pts.append((t, x))
    d = fit_slope(pts) if len(pts) > 2 else float("nan")
    print(f"D = {d:.0f} m/s over {len(pts)} outputs (t >= {T_FIT * 1e6:g} us, x_front <= {X_FIT_END * 1e3:g} mm)")
    if d == d:
        print(f"Gurney sandwich estimate with this D: {gurney_sandwich(d):.0f} m/s (M/C = {M_OVER_C:.3f})")
    wall = wall_history(tephra, out)
    for s, h in wall.items():
        print(f"wall v_y at x = {s * 1e3:.0f} mm (outer layer):")
        for t, v in h:
            print(f"   t = {t * 1e6:6.2f} us  v_y = {v:8.2f} m/s")
    rows = [("front_x_m", t, x) for t, x in front] + [("shock_x_m", t, x) for t, x in shock]
    rows += [("max_axis_pressure_Pa", t, pm) for t, _, _, pm in hist]
    for s, h in wall.items():
        rows += [(f"wall_vy_m_per_s_at_x_{s * 1e3:.0f}mm", t, v) for t, v in h]
    os.makedirs(png_dir, exist_ok=True)
    with open(os.path.join(png_dir, "qm100curs.csv"), "w") as fh:
        fh.write("quantity,time_s,value\n")
        for q, t, v in rows:
            fh.write(f"{q},{t:.6e},{'' if v is None else f'{v:.6e}'}\n")
    colours = [(30, 90, 220), (20, 160, 60), (200, 0, 0), (150, 0, 150)]
    tmax = max([t for t, _ in front] + [1e-6])
    tt = 2.0 * (int(tmax * 1e6 / 2.0) + 1)
    xt = [2.0 * k for k in range(int(tt / 2) + 1)]
    if wall and any(wall.values()):
        vals = [v for h in wall.values() for _, v in h]
        vt = 100.0 * (int(max(vals + [100.0]) / 100.0) + 1)
        series = [([(t * 1e6, v) for t, v in h], colours[k]) for k, h in enumerate(wall.values())]
        legend = [(f"X = {s * 1e3:.0f} MM", colours[k]) for k, s in enumerate(wall)]
        if d == d:
            g = gurney_sandwich(d)
            series.append(([(0.0, g), (tt, g)], (0, 0, 0)))
            legend.append((f"GURNEY {g:.0f} M/S", (0, 0, 0)))
            vt = max(vt, 100.0 * (int(g / 100.0) + 1))
        plot_series(os.path.join(png_dir, "qm100curs-wall-velocity.png"), series,
                    (0.0, tt), (min(0.0, min(vals)), vt), xt,
                    [100.0 * k for k in range(int(vt / 100) + 1)][::max(1, int(vt / 100) // 10)],
                    "T (US)", "WALL RADIAL VELOCITY V_Y (M/S), OUTER COPPER LAYER", legend)
    plot_series(os.path.join(png_dir, "qm100curs-front.png"),
                [([(t * 1e6, None if x is None else x * 1e3) for t, x in until_the_end(front)], colours[0]),
                 ([(t * 1e6, None if x is None else x * 1e3) for t, x in until_the_end(shock)], colours[2])],
                (0.0, tt), (0.0, 50.0), xt, [5.0 * k for k in range(11)], "T (US)",
                "X (MM) ON THE AXIS ROW", [("REACTION FRONT F >= 0.5", colours[0]),
                                          (f"LEAD SHOCK P > {P_SHOCK / 1e6:.0f} MPA", colours[2])])
    return d


def main():
    build, mode = sys.argv[1], sys.argv[2]
    args = list(sys.argv[3:])
    opts = {}
    for key in ("--end-time", "--png-dir"):
        if key in args:
            i = args.index(key)
            opts[key] = args[i + 1]
            del args[i:i + 2]
    out = os.path.abspath(args[0] if args else "/tmp/qm100curs")
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "run":
        cmd = [tephra, DECK, "--output", out, "--threads", "1"]
        if "--end-time" in opts:
            cmd += ["--end-time", opts["--end-time"]]
        subprocess.run(cmd, check=True, cwd=DECK_DIR)
    analyse(tephra, out, opts.get("--png-dir", out))


if __name__ == "__main__":
    main()
