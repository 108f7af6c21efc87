#!/usr/bin/env python3
"""Benchmark (not a test): the copper-confined ANFO rate stick
MPMICE/JWLppCuRS2d.ups (decks README C4) and its unconfined twin, run
through `tephra`: detonation front against time, front speed, and the
copper wall's radial velocity against time.

Usage:
  tests/bench/jwlppcurs2d.py BUILD_DIR run     confined|unconfined [OUT_ROOT] [--end-time T]
  tests/bench/jwlppcurs2d.py BUILD_DIR analyse confined|unconfined [OUT_ROOT]
  tests/bench/jwlppcurs2d.py BUILD_DIR plot    both [OUT_ROOT] [--png-dir DIR]
(run: --threads 1 is passed: on a loaded machine two OpenMP threads spent
4.7x the CPU time of one, libgomp's spin-waits, docs/performance.md MPMICE;
plot: analyses OUT_ROOT/confined and OUT_ROOT/unconfined, whichever exist,
and writes DIR/jwlppcurs2d-wall-velocity.png (copper wall v_y against t at
the three stations), DIR/jwlppcurs2d-front.png (front x against t, both
sticks) and DIR/jwlppcurs2d.csv (the histories); DIR defaults to OUT_ROOT.)

The deck is 2-D planar (200 x 48 x 1 cells of 0.25 mm, x in [-10, 40] mm,
y in [0, 12] mm, symmetry at y = 0): a slab of ANFO of half-thickness 6 mm
in a copper wall 6 to 8 mm, initiated by a copper "whacker" at 120 m/s.
confined: the deck unchanged (its include paths made absolute).
unconfined: the copper wall removed (its outer radius set to the stick's
6 mm, so the difference is empty and the air fills r > 6 mm); the whacker
and everything else unchanged.

Front: as rate_stick_size_effect.py (the ICE helper's size-effect study,
whose fit_slope, D_CJ and reference points are imported, not copied): the
largest x of an axis cell (y = z = dx/2) with F >= 0.5, F the reacted
fraction saved on the reactant (material 1 here: copper is MPM material 0);
speed: least-squares slope over the outputs with t >= 8 us and
until the front first passes x = 35 mm (the x+ face is 5 mm further). Wall velocity: the mean
v_y of the copper particles of the outermost layer (initial y > 7.875 mm)
within 0.5 mm of x = 10, 20, 30 mm, at every output.
"""
import collections
import csv
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from rate_stick_size_effect import D_CJ, FONT, fit_slope, write_png  # noqa: E402

DECKS = os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "decks"))
DECK = os.path.join(DECKS, "inputs", "MPMICE", "JWLppCuRS2d.ups")
DX = 0.25e-3
STATIONS = (0.010, 0.020, 0.030)


def make_deck(kind):
    text = open(DECK, encoding="iso-8859-1").read()
    text = text.replace('href="inputs/', 'href="' + os.path.join(DECKS, "inputs") + "/")
    if kind == "unconfined":
        text, n = re.subn(r"<radius>\s*0\.008\s*</radius>", "<radius> 0.006 </radius>", text, count=1)
        assert n == 1, "copper radius not found"
    return text


def extract(tephra, out, var, material, line=None):
    cmd = [tephra, "extract", out, "--var", var, "--material", str(material), "--all-times"]
    if line:
        cmd += ["--line", line]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return list(csv.DictReader(text.splitlines()))


def until_the_end(front):
    """The outputs until the front first reaches its largest x (the x+ end):
    after that the axis cells hold no reactant and F reads 0, so the
    "front" of later outputs is not a detonation front."""
    xs = [x for _, x in front if x is not None]
    if not xs:
        return front
    top = max(xs)
    for k, (_, x) in enumerate(front):
        if x is not None and x >= top:
            return front[:k + 1]
    return front


def front_history(tephra, out):
    y = 0.5 * DX
    rows = collections.defaultdict(list)
    for r in extract(tephra, out, "F", 1, f"-0.00999,{y},{y},0.03999,{y},{y}"):
        rows[float(r["time"])].append((float(r["x"]), float(r["F"])))
    front = []
    for t in sorted(rows):
        xs = [x for x, f in rows[t] if f >= 0.5]
        front.append((t, max(xs) if xs else None))
    return front


def wall_history(tephra, out):
    pos = extract(tephra, out, "p.velocity", 0)  # columns time, particle_id, x, y, z, p.velocity_x/y/z
    vel = pos
    if not pos:
        return {}
    t0 = min(float(r["time"]) for r in pos)
    start = {r["particle_id"]: (float(r["x"]), float(r["y"])) for r in pos if float(r["time"]) == t0}
    groups = {s: {i for i, (x, y) in start.items() if y > 0.008 - DX / 2 and abs(x - s) <= 0.5e-3} for s in STATIONS}
    hist = {s: collections.defaultdict(list) for s in STATIONS}
    for r in vel:
        for s in STATIONS:
            if r["particle_id"] in groups[s]:
                hist[s][float(r["time"])].append(float(r["p.velocity_y"]))
    return {s: sorted((t, sum(v) / len(v)) for t, v in hist[s].items()) for s in STATIONS}


def analyse(tephra, out, kind):
    front = front_history(tephra, out)
    for t, x in front[::5]:
        print(f"t = {t * 1e6:6.2f} us  front = {x * 1e3 if x is not None else float('nan'):6.2f} mm")
    # The outputs from 8 us until the front first passes x = 35 mm (later
    # outputs are not a front: once the reactant is gone F reads 0 there).
    pts = []
    for t, x in front:
        if x is not None and x > 0.035:
            break
        if x is not None and t >= 8e-6 - 1e-12:
            pts.append((t, x))
    d = fit_slope(pts) if len(pts) > 2 else float("nan")
    print(f"{kind}: D = {d:.0f} m/s over {len(pts)} outputs (t >= 8 us, x_front <= 35 mm); "
          f"D/D_CJ = {d / D_CJ:.4f} (D_CJ = {D_CJ} m/s, 1-D CJ of the products)")
    if kind == "confined":
        wall = wall_history(tephra, out)
        for s, h in wall.items():
            print(f"wall v_y at x = {s * 1e3:.0f} mm (outer layer):")
            for t, v in h[::5]:
                print(f"   t = {t * 1e6:6.2f} us  v_y = {v:8.2f} m/s")
            if h:
                print(f"   max v_y = {max(v for _, v in h):.1f} m/s")
    return d


def plot_series(png, series, xr, yr, xticks, yticks, xlabel, ylabel, legend):
    """Line plot, linear axes: series = [(points [(x, y)], colour)],
    xr/yr = (lo, hi), ticks = lists of values, labels drawn with the 5x7 font."""
    W, H, L, R, T, B = 720, 480, 70, 20, 20, 50
    px = bytearray([255] * (W * H * 3))
    X = lambda x: L + (x - xr[0]) / (xr[1] - xr[0]) * (W - L - R)
    Y = lambda y: H - B - (y - yr[0]) / (yr[1] - yr[0]) * (H - T - B)

    def dot(x, y, c):
        if 0 <= x < W and 0 <= y < H:
            i = (int(y) * W + int(x)) * 3
            px[i:i + 3] = bytes(c)

    def line(x0, y0, x1, y1, c, dotted=False):
        n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for k in range(n + 1):
            if dotted and (k // 4) % 2:
                continue
            dot(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n, c)
            if not dotted:
                dot(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n + 1, c)

    def text(x, y, s, c=(0, 0, 0)):
        for k, ch in enumerate(s.upper()):
            for row, bits in enumerate(FONT.get(ch, FONT[" "])):
                for col in range(5):
                    if bits & (0x10 >> col):
                        dot(x + 6 * k + col, y + row, c)

    black, grid = (0, 0, 0), (225, 225, 225)
    for v in xticks:
        line(X(v), T, X(v), H - B, grid, dotted=True)
        line(X(v), H - B, X(v), H - B + 6, black)
        text(X(v) - 9, H - B + 10, f"{v:g}")
    for v in yticks:
        line(L, Y(v), W - R, Y(v), grid, dotted=True)
        line(L - 6, Y(v), L, Y(v), black)
        text(L - 40, Y(v) - 3, f"{v:g}")
    text((L + W) // 2 - 3 * len(xlabel), H - 18, xlabel)
    text(L + 4, 6, ylabel)
    line(L, H - B, W - R, H - B, black)
    line(L, T, L, H - B, black)
    for pts, c in series:
        pts = [(x, y) for x, y in pts if y is not None]
        for (a, b), (u, v) in zip(pts, pts[1:]):
            line(X(a), Y(b), X(u), Y(v), c)
    for k, (name, c) in enumerate(legend):
        text(L + 12, T + 8 + 11 * k, name, c)
    write_png(png, W, H, px)


def plot_all(tephra, root, png_dir):
    colours = [(30, 90, 220), (20, 160, 60), (200, 0, 0)]
    fronts, wall = {}, {}
    for kind in ("confined", "unconfined"):
        out = os.path.join(root, kind)
        if os.path.isdir(out):
            fronts[kind] = front_history(tephra, out)
            if kind == "confined":
                wall = wall_history(tephra, out)
    rows = []
    for kind, f in fronts.items():
        rows += [(kind, "front_x_m", t, x) for t, x in f]
    for st, h in wall.items():
        rows += [("confined", f"wall_vy_m_per_s_at_x_{st * 1e3:.0f}mm", t, v) for t, v in h]
    with open(os.path.join(png_dir, "jwlppcurs2d.csv"), "w") as fh:
        fh.write("run,quantity,time_s,value\n")
        for r in rows:
            fh.write(f"{r[0]},{r[1]},{r[2]:.6e},{'' if r[3] is None else f'{r[3]:.6e}'}\n")
    tmax = max([t for f in fronts.values() for t, _ in f] + [1e-6])
    tt = 2.0 * (int(tmax * 1e6 / 2.0) + 1)
    xt = [2.0 * k for k in range(int(tt / 2) + 1)]
    if wall:
        vmax = max([v for h in wall.values() for _, v in h] + [100.0])
        vt = 100.0 * (int(vmax / 100.0) + 1)
        plot_series(os.path.join(png_dir, "jwlppcurs2d-wall-velocity.png"),
                    [([(t * 1e6, v) for t, v in h], colours[k]) for k, h in enumerate(wall.values())],
                    (0.0, tt), (min(0.0, min(v for h in wall.values() for _, v in h)), vt), xt,
                    [100.0 * k for k in range(int(vt / 100) + 1)][::max(1, int(vt / 100) // 10)],
                    "T (US)", "WALL RADIAL VELOCITY V_Y (M/S), OUTER COPPER LAYER",
                    [(f"X = {st * 1e3:.0f} MM", colours[k]) for k, st in enumerate(wall)])
    plot_series(os.path.join(png_dir, "jwlppcurs2d-front.png"),
                [([(t * 1e6, None if x is None else x * 1e3) for t, x in until_the_end(f)], colours[k])
                 for k, f in enumerate(fronts.values())],
                (0.0, tt), (0.0, 40.0), xt, [5.0 * k for k in range(9)], "T (US)",
                "DETONATION FRONT X (MM), AXIS CELLS WITH F AT LEAST 0.5",
                [(kind.upper(), colours[k]) for k, kind in enumerate(fronts)])


def main():
    build, mode, kind = sys.argv[1], sys.argv[2], sys.argv[3]
    args = [a for a in sys.argv[4:]]
    end = None
    if "--end-time" in args:
        i = args.index("--end-time")
        end = args[i + 1]
        del args[i:i + 2]
    png_dir = None
    if "--png-dir" in args:
        i = args.index("--png-dir")
        png_dir = args[i + 1]
        del args[i:i + 2]
    root = args[0] if args else "/tmp/jwlppcurs2d"
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "plot":
        plot_all(tephra, root, png_dir or root)
        return
    out = os.path.join(root, kind)
    if mode == "run":
        os.makedirs(root, exist_ok=True)
        deck = out + ".ups"
        open(deck, "w").write(make_deck(kind))
        cmd = [tephra, deck, "--output", out, "--threads", "1"]
        if end:
            cmd += ["--end-time", end]
        subprocess.run(cmd, check=True)
    analyse(tephra, out, kind)


if __name__ == "__main__":
    main()
