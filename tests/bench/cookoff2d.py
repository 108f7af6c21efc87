#!/usr/bin/env python3
"""Benchmark (not a test): the reduced fast-cookoff case
inputs/validation/cookoff2d.ups (Vaango theory manual sec. 26.3.3; issue 6),
run through `tephra`: mean container pressure and burned PBX mass against
time, and the first rupture of the steel container (time and place).

Usage:
  tests/bench/cookoff2d.py BUILD_DIR run     [OUT] [--axisym] [--end-time T] [--refine K] [--stability TYPE | --no-stability]
  tests/bench/cookoff2d.py BUILD_DIR analyse [OUT] [--png-dir DIR]
  tests/bench/cookoff2d.py selftest
(run: the deck, or with --refine K the deck with K x K times more cells in
the plane (cell size 1.27 mm / K, the z thickness and minimum_particle_mass
scaled with it), written to OUT/deck.ups and run with --threads 1; then
analyse; --stability TYPE sets the steel's <stability_check> (drucker_becker
in the deck) to TYPE: "none" (= --no-stability: only TEPLA, porosity and JC
damage, can fail a particle), "becker", "drucker", "acoustic". analyse: prints the histories and writes DIR/cookoff2d-pressure.png,
DIR/cookoff2d-burned.png, DIR/cookoff2d-failed.png, DIR/cookoff2d-map.png
(the steel at the last output, failed particles red) and DIR/cookoff2d.csv; DIR
defaults to OUT. selftest: the rupture-detection rules on hand-made
lattices; exit 0 when they hold (ctest runs it).)
--axisym (session 24): run inputs/validation/cookoff_axisym.ups instead (the
same section made axisymmetric, x = r, y = z); analyse recognises an
axisymmetric run from its input.ups (<axisymmetric>true), reports masses per
radian (x 2 pi for the whole container) and names its files cookoff_axisym*
(cookoff_axisym.csv, cookoff_axisym-pressure.png, ...). The rupture rules
are the same on the (r, z) lattice: the side wall is then the cylinder's
hoop-loaded mantle (mid-length at z = 0), the end cap a disc.

Geometry (the deck's header): planar section through the axis, x radial,
y axial, quarter with symmetry at x = 0 and y = 0; inner half-sizes
R_I = L_I = 50.8 mm, outer R_O = L_O = 57.15 mm (wall and cap 6.35 mm).

Definitions (reference configuration = a steel particle's position at the
first output; particles lie on a lattice of spacing s = h/2):
* place of a steel particle (reference X, Y): "corner" if its distance
  along the wall from the inner corner (R_I, L_I) is at most the wall
  thickness 6.35 mm (the junction of side wall and end cap, where the 3-D
  run first ruptured), else "side wall" (X >= R_I) or "end cap" (Y >= L_I);
  mid-length of the side wall is y = 0, the cap's centre x = 0.
* failed: p.localized = 1 (set by elastic_plastic: TEPLA (phi/phi_c)^2 + D^2
  > 1, the drucker_becker stability check, melting; erosion ZeroStress then
  zeroes its stress). First failure: the first output with a failed steel
  particle; reported with its place and reference position.
* through-wall crack: a set of failed particles connected through lattice
  neighbours (8-neighbour: |dX|, |dY| <= s in the reference lattice) that
  holds a particle of the inner layer (distance to the inner box
  [0, R_I] x [0, L_I] below s) and one of the outer layer (distance to the
  outer boundary x = R_O or y = L_O below s). Its place is that of the
  component's mean reference position. Time resolution: the output interval.
* mean container pressure: the mean press_CC of the cells whose centres lie
  in the inner box (the container's interior in the reference geometry),
  and the largest press_CC there.
* burned mass: initial PBX mass minus the PBX particle mass (sum p.mass of
  material 1) at each output; per metre of depth (the slab is one cell, h,
  thick) and as a fraction of the initial PBX.
"""
import csv
import math
import os
import re
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
DECK = os.path.join(ROOT, "inputs", "validation", "cookoff2d.ups")
DECK_AXI = os.path.join(ROOT, "inputs", "validation", "cookoff_axisym.ups")
R_I, R_O = 0.0508, 0.05715   # side wall: inner / outer radius [m]
L_I, L_O = 0.0508, 0.05715   # end cap: inner / outer half-length [m]
H0 = 1.27e-3                 # the deck's cell size


# ---------------------------------------------------------------- geometry

def corner_distance(X, Y):
    """Distance along the wall from the inner corner (R_I, L_I): L_I - Y on
    the side wall, R_I - X on the end cap, 0 in the corner square."""
    return max(L_I - Y, R_I - X, 0.0)


def place(X, Y):
    """Where a steel particle with reference position (X, Y) sits: "corner"
    within one wall thickness (R_O - R_I) of the inner corner along the wall
    (the junction of side wall and end cap), else "side wall" or "end cap"."""
    if corner_distance(X, Y) <= R_O - R_I:
        return "corner"
    return "side wall" if X >= R_I else "end cap"


def inner_distance(X, Y):
    """Distance of (X, Y) to the inner box [0, R_I] x [0, L_I] (0 inside)."""
    return math.hypot(max(X - R_I, 0.0), max(Y - L_I, 0.0))


def outer_distance(X, Y):
    """Distance of a wall point to the outer boundary (x = R_O or y = L_O)."""
    return min(R_O - X, L_O - Y)


def through_wall_cracks(failed, s):
    """failed: {id: (X, Y)} reference positions of the failed steel particles
    on a lattice of spacing s (at (k + 1/2) s, so floor(X/s) is the lattice
    index). Returns the components (lists of ids) that
    join the inner layer to the outer layer through 8-neighbours."""
    cell = {}
    for pid, (X, Y) in failed.items():
        cell.setdefault((math.floor(X / s), math.floor(Y / s)), []).append(pid)
    seen, cracks = set(), []
    for start in failed:
        if start in seen:
            continue
        comp, stack = [], [start]
        seen.add(start)
        while stack:
            pid = stack.pop()
            comp.append(pid)
            X, Y = failed[pid]
            i, j = math.floor(X / s), math.floor(Y / s)
            for di in (-1, 0, 1):
                for dj in (-1, 0, 1):
                    for q in cell.get((i + di, j + dj), ()):
                        if q not in seen:
                            seen.add(q)
                            stack.append(q)
        inner = any(inner_distance(*failed[p]) < s for p in comp)
        outer = any(outer_distance(*failed[p]) < s for p in comp)
        if inner and outer:
            cracks.append(sorted(comp))
    return cracks


# ---------------------------------------------------------------- reading

def extract(tephra, out, var, material):
    cmd = [tephra, "extract", out, "--var", var, "--material", str(material), "--all-times"]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    return list(csv.DictReader(text.splitlines()))


def deck_cell_size(out):
    """h from the run's deck copy (<upper>, <lower>, <resolution> in x)."""
    text = open(os.path.join(out, "input.ups")).read()
    num = lambda tag: [float(v) for v in re.search(rf"<{tag}>\s*\[([^\]]*)\]", text).group(1).split(",")]
    return (num("upper")[0] - num("lower")[0]) / num("resolution")[0]


def deck_is_axisymmetric(out):
    """Whether the run's deck copy has <MPM><axisymmetric>true."""
    text = open(os.path.join(out, "input.ups")).read()
    return re.search(r"<axisymmetric>\s*true\s*</axisymmetric>", text) is not None


def by_time(rows):
    series = {}
    for r in rows:
        series.setdefault(float(r["time"]), []).append(r)
    return series


# ---------------------------------------------------------------- analysis

def analyse(tephra, out, png_dir):
    h = deck_cell_size(out)
    s = 0.5 * h
    axi = deck_is_axisymmetric(out)
    # Mass unit of the burned column: per metre of depth (planar slab, one
    # cell h thick) or per radian (axisymmetric: the particles' masses).
    per = 1.0 if axi else h
    unit = "kg/rad" if axi else "kg/m"
    steel = by_time(extract(tephra, out, "p.localized", 0))
    damage = {(float(r["time"]), r["particle_id"]): float(r["p.damage"])
              for r in extract(tephra, out, "p.damage", 0)}
    porosity = {(float(r["time"]), r["particle_id"]): float(r["p.porosity"])
                for r in extract(tephra, out, "p.porosity", 0)}
    pbx = by_time(extract(tephra, out, "p.mass", 1))
    press = by_time(extract(tephra, out, "press_CC", 0))
    times = sorted(steel)
    t0 = times[0]
    ref = {r["particle_id"]: (float(r["x"]), float(r["y"])) for r in steel[t0]}
    m0 = sum(float(r["p.mass"]) for r in pbx[t0])

    hist, first, first_crack = [], None, None
    first_in, crack_in, wall_u = {}, {}, []  # place -> (t, reference position) of its first failure / crack
    for t in times:
        failed = {r["particle_id"]: ref[r["particle_id"]] for r in steel[t] if float(r["p.localized"]) >= 0.5}
        counts = {"side wall": 0, "end cap": 0, "corner": 0}
        for X, Y in failed.values():
            counts[place(X, Y)] += 1
            first_in.setdefault(place(X, Y), (t, X, Y))
        if failed and first is None:
            first = (t, sorted(failed.items(), key=lambda kv: kv[1]))
        cracks = through_wall_cracks(failed, s)
        if cracks and first_crack is None:
            first_crack = (t, [(len(c), [sum(failed[p][k] for p in c) / len(c) for k in (0, 1)]) for c in cracks])
        for c in cracks:
            X, Y = (sum(failed[p][k] for p in c) / len(c) for k in (0, 1))
            crack_in.setdefault(place(X, Y), (t, X, Y))
        inside = [float(r["press_CC"]) for r in press.get(t, [])
                  if 0.0 < float(r["x"]) < R_I and 0.0 < float(r["y"]) < L_I and float(r["k"]) == 0]
        p_mean = sum(inside) / len(inside) if inside else float("nan")
        p_max = max(inside) if inside else float("nan")
        burned = m0 - sum(float(r["p.mass"]) for r in pbx.get(t, []))
        # Outward displacement of the side wall at mid-length (Y < s) and of the cap at its centre (X < s).
        u_side = [float(r["x"]) - ref[r["particle_id"]][0] for r in steel[t] if ref[r["particle_id"]][1] < s]
        u_cap = [float(r["y"]) - ref[r["particle_id"]][1] for r in steel[t] if ref[r["particle_id"]][0] < s]
        wall_u.append((sum(u_side) / max(len(u_side), 1), sum(u_cap) / max(len(u_cap), 1)))
        hist.append((t, p_mean, p_max, burned, len(failed), counts, len(cracks)))

    if axi:
        print(f"# {out} (axisymmetric): h = {h * 1e3:.4g} mm, {len(ref)} steel particles, PBX {m0:.6g} kg/rad "
              f"({2 * math.pi * m0:.6g} kg in the half container), {len(times)} outputs to t = {times[-1] * 1e3:.4g} ms")
    else:
        print(f"# {out}: h = {h * 1e3:.4g} mm, {len(ref)} steel particles, PBX {m0:.6g} kg "
              f"({m0 / h:.6g} kg per metre of depth), {len(times)} outputs to t = {times[-1] * 1e3:.4g} ms")
    print(f"# t[ms]  p_mean[MPa]  p_max[MPa]  burned[{unit}]  burned/PBX  failed(side,cap,corner)  cracks"
          "  u_side_mid[mm]  u_cap_centre[mm]")
    for (t, pm, px, b, n, c, nc), (us, uc) in zip(hist, wall_u):
        print(f"{t * 1e3:7.4f} {pm / 1e6:11.4g} {px / 1e6:11.4g} {b / per:12.5g} {b / m0:10.4g}  "
              f"{n:5d} ({c['side wall']},{c['end cap']},{c['corner']})  {nc}  {us * 1e3:8.4g} {uc * 1e3:8.4g}")
    if first is None:
        print("first failure: none in the run")
    else:
        t, parts = first
        print(f"first failure: t = {t * 1e3:.4g} ms, {len(parts)} particle(s):")
        for pid, (X, Y) in parts[:10]:
            D, phi = damage.get((t, pid), float("nan")), porosity.get((t, pid), float("nan"))
            tepla = (phi / 0.3) ** 2 + D ** 2
            print(f"  id {pid}: {place(X, Y)} ({corner_distance(X, Y) * 1e3:.2f} mm from the inner corner), "
                  f"reference ({'r, z' if axi else 'x, y'}) = ({X * 1e3:.3f}, {Y * 1e3:.3f}) mm, "
                  f"D = {D:.4g}, phi = {phi:.4g}, TEPLA (phi/0.3)^2 + D^2 = {tepla:.4g}")
    if first_crack is None:
        print("through-wall crack: none in the run")
    else:
        t, cracks = first_crack
        for n, (X, Y) in cracks:
            print(f"through-wall crack: t = {t * 1e3:.4g} ms, {n} failed particles, "
                  f"mean reference ({'r, z' if axi else 'x, y'}) = ({X * 1e3:.2f}, {Y * 1e3:.2f}) mm: {place(X, Y)}")
    for name in ("corner", "side wall", "end cap"):
        for what, d in (("first failed particle", first_in), ("first through-wall crack", crack_in)):
            if name in d:
                t, X, Y = d[name]
                print(f"{name:9s}: {what} at t = {t * 1e3:.4g} ms, reference ({'r, z' if axi else 'x, y'}) = "
                      f"({X * 1e3:.2f}, {Y * 1e3:.2f}) mm, "
                      f"{corner_distance(X, Y) * 1e3:.2f} mm from the inner corner")
            else:
                print(f"{name:9s}: {what}: none")
    write_outputs(hist, per, m0, png_dir, steel[times[-1]], ref, "cookoff_axisym" if axi else "cookoff2d", axi)
    return hist, first, first_crack


def write_outputs(hist, h, m0, png_dir, last_rows, ref, stem="cookoff2d", axi=False):
    """h: the burned column's divisor (the slab depth, or 1 for per radian)."""
    from jwlppcurs2d import plot_series
    from rate_stick_size_effect import write_png, FONT
    os.makedirs(png_dir, exist_ok=True)
    with open(os.path.join(png_dir, f"{stem}.csv"), "w") as f:
        f.write(f"t_s,p_mean_Pa,p_max_Pa,burned_kg_per_{'rad' if axi else 'm'},burned_fraction,failed,failed_side,"
                "failed_cap,failed_corner,cracks\n")
        for t, pm, px, b, n, c, nc in hist:
            f.write(f"{t:.6e},{pm:.6e},{px:.6e},{b / h:.6e},{b / m0:.6e},{n},{c['side wall']},"
                    f"{c['end cap']},{c['corner']},{nc}\n")
    tmax = hist[-1][0] * 1e3
    xt = [round(0.05 * k, 2) for k in range(int(tmax / 0.05) + 2)]
    def nice_top(v):
        """The smallest of 1, 2, 5 x 10^k at or above v."""
        k = 10 ** math.floor(math.log10(v))
        return next(m * k for m in (1, 2, 5, 10) if m * k >= v)
    top = nice_top(max([px for _, _, px, *_ in hist if px == px] + [1e-3]) / 1e6)
    plot_series(os.path.join(png_dir, f"{stem}-pressure.png"),
                [([(t * 1e3, pm / 1e6) for t, pm, *_ in hist], (200, 30, 30)),
                 ([(t * 1e3, px / 1e6) for t, _, px, *_ in hist], (30, 30, 200))],
                (0, xt[-1]), (0, top), xt, [top * k / 5 for k in range(6)],
                "T [MS]", "PRESSURE INSIDE THE CONTAINER [MPA]",
                [("MEAN OVER THE INNER BOX", (200, 30, 30)), ("LARGEST CELL", (30, 30, 200))])
    btop = nice_top(max([b / h * 1e3 for _, _, _, b, *_ in hist] + [1e-6]))
    plot_series(os.path.join(png_dir, f"{stem}-burned.png"),
                [([(t * 1e3, b / h * 1e3) for t, _, _, b, *_ in hist], (30, 30, 200))],
                (0, xt[-1]), (0, btop), xt, [btop * k / 5 for k in range(6)],
                "T [MS]", "BURNED PBX [G PER RADIAN]" if axi else "BURNED PBX [G PER M OF DEPTH]",
                [("HALF CONTAINER" if axi else "QUARTER SECTION", (30, 30, 200))])
    nmax = max([n for *_, n, _, _ in hist] + [1])
    plot_series(os.path.join(png_dir, f"{stem}-failed.png"),
                [([(t * 1e3, c["side wall"]) for t, *_, c, _ in hist], (30, 30, 200)),
                 ([(t * 1e3, c["end cap"]) for t, *_, c, _ in hist], (200, 30, 30)),
                 ([(t * 1e3, c["corner"]) for t, *_, c, _ in hist], (30, 150, 30))],
                (0, xt[-1]), (0, nmax), xt, [round(nmax * k / 5) for k in range(6)],
                "T [MS]", "FAILED STEEL PARTICLES",
                [("SIDE WALL", (30, 30, 200)), ("END CAP", (200, 30, 30)), ("CORNER", (30, 150, 30))])
    # Map of the steel at the last output: current positions, failed red, intact grey.
    W, H, M = 480, 480, 20
    px = bytearray([255] * (W * H * 3))
    span = 0.066
    for r in last_rows:
        x, y = float(r["x"]), float(r["y"])
        c = (220, 20, 20) if float(r["p.localized"]) >= 0.5 else (120, 120, 120)
        i, j = int(M + x / span * (W - 2 * M)), int(H - M - y / span * (H - 2 * M))
        for di in (0, 1):
            for dj in (0, 1):
                if 0 <= i + di < W and 0 <= j + dj < H:
                    k = ((j + dj) * W + i + di) * 3
                    px[k:k + 3] = bytes(c)
    write_png(os.path.join(png_dir, f"{stem}-map.png"), W, H, px)


# ---------------------------------------------------------------- self-test

def selftest():
    """The rupture rules on hand-made lattices (s = 0.635 mm, the deck's)."""
    s = 0.5 * H0
    wall = {}  # the side wall's lattice: X = R_I + (i + 1/2) s, 10 columns; Y rows
    for i in range(10):
        for j in range(20):
            wall[(i, j)] = (R_I + (i + 0.5) * s, 0.02 + (j + 0.5) * s)
    ok = True

    def check(name, cond):
        nonlocal ok
        print(("ok   " if cond else "FAIL ") + name)
        ok = ok and cond

    check("place: side wall, end cap, corner",
          place(0.052, 0.01) == "side wall" and place(0.01, 0.052) == "end cap" and place(0.052, 0.052) == "corner")
    check("corner zone: within one wall thickness of the inner corner",
          place(0.052, L_I - 0.006) == "corner" and place(0.052, L_I - 0.0066) == "side wall"
          and place(R_I - 0.006, 0.052) == "corner" and place(R_I - 0.0066, 0.052) == "end cap")
    check("inner/outer distances", abs(inner_distance(R_I + 1e-4, 0.01) - 1e-4) < 1e-15
          and inner_distance(0.01, 0.01) == 0.0 and abs(outer_distance(R_O - 2e-4, 0.01) - 2e-4) < 1e-15)
    # (a) a straight row across the wall (all 10 columns at row 5): one crack.
    straight = {f"{i},5": wall[(i, 5)] for i in range(10)}
    c = through_wall_cracks(straight, s)
    check("straight row across the wall is a crack", len(c) == 1 and len(c[0]) == 10)
    # (b) the same row one column short of the outer surface: none.
    short = {f"{i},5": wall[(i, 5)] for i in range(9)}
    check("row ending one particle short of the outer surface is not", through_wall_cracks(short, s) == [])
    # (c) one short of the inner surface: none.
    short_in = {f"{i},5": wall[(i, 5)] for i in range(1, 10)}
    check("row starting one particle off the inner surface is not", through_wall_cracks(short_in, s) == [])
    # (d) a diagonal staircase (corner-to-corner neighbours only): a crack (8-neighbour rule).
    diag = {f"{i},{i}": wall[(i, i)] for i in range(10)}
    check("diagonal staircase is a crack", len(through_wall_cracks(diag, s)) == 1)
    # (e) a row with a gap of one particle: two pieces, none joins both layers.
    gap = {f"{i},5": wall[(i, 5)] for i in range(10) if i != 4}
    check("row with a one-particle gap is not", through_wall_cracks(gap, s) == [])
    # (f) a jump of two rows between columns 4 and 5 breaks the path.
    jump = {f"{i},{5 if i < 5 else 7}": wall[(i, 5 if i < 5 else 7)] for i in range(10)}
    check("rows two lattice steps apart do not connect", through_wall_cracks(jump, s) == [])
    # (g) across the end cap near the axis.
    cap = {f"c{j}": (0.01, L_I + (j + 0.5) * s) for j in range(10)}
    c = through_wall_cracks(cap, s)
    check("a column across the end cap is a crack", len(c) == 1 and place(0.01, L_I + 5 * s) == "end cap")
    return 0 if ok else 1


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "selftest":
        sys.exit(selftest())
    build, mode = sys.argv[1], sys.argv[2]
    args = list(sys.argv[3:])
    opts = {}
    axisym = "--axisym" in args
    if axisym:
        args.remove("--axisym")
    if "--no-stability" in args:
        args.remove("--no-stability")
        opts["--stability"] = "none"
    for key in ("--end-time", "--png-dir", "--refine", "--stability"):
        if key in args:
            i = args.index(key)
            opts[key] = args[i + 1]
            del args[i:i + 2]
    out = os.path.abspath(args[0] if args else "/tmp/cookoff2d")
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "run":
        os.makedirs(out, exist_ok=True)
        k = int(opts.get("--refine", "1"))
        text = open(DECK_AXI if axisym else DECK).read()
        if k != 1:
            n = 52 * k
            text = text.replace("[ 52, 52, 1]", f"[ {n}, {n}, 1]")
            text = text.replace("-0.000635]", f"-{0.000635 / k:.8g}]").replace(" 0.000635]", f" {0.000635 / k:.8g}]")
            text = text.replace("3.e-10", f"{3e-10 / k ** 3:.3g}")
        if "--stability" in opts:
            before = text
            text = text.replace('<stability_check     type="drucker_becker"/>',
                                f'<stability_check     type="{opts["--stability"]}"/>')
            assert text != before, "stability_check not found in the deck"
        deck = os.path.join(out, "deck.ups")
        if axisym and "--end-time" in opts:  # the deck's maxTime bounds the run: raise it to the end time
            text = re.sub(r"<maxTime>[^<]*</maxTime>", f"<maxTime> {opts['--end-time']} </maxTime>", text)
        open(deck, "w").write(text)
        cmd = [tephra, deck, "--output", out, "--threads", "1"]
        if "--end-time" in opts:
            cmd += ["--end-time", opts["--end-time"]]
        subprocess.run(cmd, check=True, cwd=out)
    analyse(tephra, out, opts.get("--png-dir", out))


if __name__ == "__main__":
    main()
