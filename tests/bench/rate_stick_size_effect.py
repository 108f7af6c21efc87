#!/usr/bin/env python3
"""Benchmark (not a test): ANFO rate-stick size effect with the ICE deck
ICE/JWLpp8mmRS.ups (JWL++ rate, Murnaghan reactant, JWLC products, air).

Usage:
  tests/bench/rate_stick_size_effect.py BUILD_DIR run  R_MM DX_MM [OUT_ROOT] [--slab]
  tests/bench/rate_stick_size_effect.py BUILD_DIR front R_MM DX_MM [OUT_ROOT] [--slab]
  tests/bench/rate_stick_size_effect.py BUILD_DIR plot  RESULTS.csv PNG   (pure Python PNG)

--slab: a 2-D planar slab of half-thickness R_MM (one cell along z, z+ a
symmetry plane) instead of the quarter-symmetric 3-D stick (ICE has no
axisymmetric form); output directory slabR..._dx....

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


def make_deck(r_mm, dx_mm, slab=False):
    """slab: a 2-D planar slab of half-thickness r_mm (one cell along z, the
    z+ face a symmetry plane, so the deck's cylinder about the x axis cuts
    the cells |y| < r_mm; ICE has no axisymmetric form), else the quarter-
    symmetric 3-D stick of radius r_mm."""
    text = open(DECK, encoding="iso-8859-1").read()
    text = text.replace('href="inputs/', 'href="' + os.path.join(DECKS, "inputs") + "/")
    dx = dx_mm * 1e-3
    nx = int(round(0.1 / dx))
    sym = ("y+", "z+") if r_mm == 0 else ("z+",) if slab else ()
    for s in sym:
        text = re.sub(r'<Face side = "%s">.*?</Face>' % re.escape(s), SYMMETRY_FACE.format(s=s), text,
                      count=1, flags=re.S)
    if r_mm == 0:
        ny, width, radius = 1, dx, 1.0
    else:
        ny = int(math.ceil(15.0 / 8.0 * r_mm / dx_mm - 1e-9))
        width, radius = ny * dx, r_mm * 1e-3
    nz, depth = (1, dx) if slab or r_mm == 0 else (ny, width)
    text = re.sub(r"<upper>.*?</upper>", f"<upper> [1.e-1,{width!r},{depth!r}] </upper>", text, count=1)
    text = re.sub(r"<resolution>.*?</resolution>", f"<resolution> [{nx}, {ny}, {nz}] </resolution>", text, count=1)
    text = re.sub(r"<radius>.*?</radius>", f"<radius> {radius!r} </radius>", text, count=1)
    saves = '<save label="F"/>\n<save label="press_CC"/>\n'
    text = re.sub(r"(<outputInterval>.*?</outputInterval>).*?(</DataArchiver>)", r"\1\n" + saves + r"\2", text,
                  count=1, flags=re.S)
    return text, nx, ny


def out_dir(root, r_mm, dx_mm, slab=False):
    return os.path.join(root, ("slab" if slab and r_mm > 0 else "") + f"R{r_mm:g}_dx{dx_mm:g}")


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
    args = [a for a in sys.argv[3:] if a != "--slab"]
    slab = "--slab" in sys.argv
    r_mm, dx_mm = float(args[0]), float(args[1])
    root = args[2] if len(args) > 2 else "/tmp/rate_stick"
    out = out_dir(root, r_mm, dx_mm, slab)
    if mode == "run":
        text, nx, ny = make_deck(r_mm, dx_mm, slab)
        os.makedirs(root, exist_ok=True)
        deck = out + ".ups"
        open(deck, "w").write(text)
        subprocess.run([tephra, deck, "--output", out, "--quiet"], check=True)
    front, d10, d14 = front_speed(tephra, out, dx_mm * 1e-3)
    for t, x in front[::5]:
        print(f"t = {t * 1e6:6.2f} us  front = {x * 1e3:6.2f} mm")
    print(f"R = {r_mm:g} mm, dx = {dx_mm:g} mm: D(10 us..) = {d10:.0f} m/s, D(14 us..) = {d14:.0f} m/s")


REFERENCE = {
    # Guilkey, Harman & Banerjee (2007) ICE simulations and Souers et al. ANFO
    # experiments, as quoted in issue 6 (Vaango theory manual 26.3.1).
    "guilkey2007": [(0, 5760), (0.05, 5404), (0.08, 4906), (0.125, 4624), (0.1667, 4087)],
    "souers": [(0.0, 5890), (0.09, 4533), (0.09, 4742), (0.154, 3672)],
}
D_CJ = 5899.3  # jwlc_cj.py on JWLEOSANFO.xml


def write_png(path, w, h, px):
    """8-bit RGB PNG (PNG spec: signature, IHDR, one zlib IDAT, IEND)."""
    import struct
    import zlib
    raw = b"".join(b"\x00" + bytes(px[y * w * 3:(y + 1) * w * 3]) for y in range(h))
    chunk = lambda t, d: struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)
    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))
    open(path, "wb").write(data)


def plot(results, png):
    """RESULTS.csv: R_mm,dx_mm,D (R_mm = 0: infinite; D empty: no detonation).
    Linear axes 1/R in [0, 0.25]/mm (ticks every 0.05) and D in [2000, 6500] m/s
    (ticks every 500), no text (key in docs/validation/rate-stick-size-effect.md):
    grey squares = Guilkey et al. 2007 simulation, black triangles = Souers
    et al. experiments, red dotted line = D_CJ, blue = Tephra dx = 2 mm,
    green = Tephra dx = 1 mm, orange = dx = 0.5 mm."""
    W, H, L, R, T, B = 720, 480, 60, 20, 20, 50
    px = bytearray([255] * (W * H * 3))
    X = lambda x: L + x / 0.25 * (W - L - R)
    Y = lambda d: H - B - (d - 2000) / 4500 * (H - T - B)

    def dot(x, y, c):
        if 0 <= x < W and 0 <= y < H:
            i = (int(y) * W + int(x)) * 3
            px[i:i + 3] = bytes(c)

    def line(x0, y0, x1, y1, c, dotted=False):
        n = int(max(abs(x1 - x0), abs(y1 - y0))) + 1
        for k in range(n + 1):
            if dotted and (k // 4) % 2:
                continue
            for o in (-1, 0, 1) if not dotted else (0,):
                dot(x0 + (x1 - x0) * k / n, y0 + (y1 - y0) * k / n + o, c)

    def marker(x, y, c, kind):
        for a in range(-4, 5):
            for b in range(-4, 5):
                if kind == "o" and a * a + b * b <= 16 or kind == "s" or kind == "^" and b >= 2 * abs(a) - 4:
                    dot(x + a, y + b, c)

    grey, black = (140, 140, 140), (0, 0, 0)
    for k in range(6):  # 1/R ticks and grid
        line(X(0.05 * k), T, X(0.05 * k), H - B, (225, 225, 225), dotted=True)
        line(X(0.05 * k), H - B, X(0.05 * k), H - B + 6, black)
    for k in range(10):  # D ticks and grid
        line(L, Y(2000 + 500 * k), W - R, Y(2000 + 500 * k), (225, 225, 225), dotted=True)
        line(L - 6, Y(2000 + 500 * k), L, Y(2000 + 500 * k), black)
    line(L, H - B, W - R, H - B, black)
    line(L, T, L, H - B, black)
    line(X(0), Y(D_CJ), X(0.25), Y(D_CJ), (200, 0, 0), dotted=True)
    ref = REFERENCE["guilkey2007"]
    for (a, d), (b, e) in zip(ref, ref[1:]):
        line(X(a), Y(d), X(b), Y(e), grey, dotted=True)
    for a, d in ref:
        marker(X(a), Y(d), grey, "s")
    for a, d in REFERENCE["souers"]:
        marker(X(a), Y(d), black, "^")
    colours = {2.0: (30, 90, 220), 1.0: (20, 160, 60), 0.5: (230, 130, 0)}
    rows = [r for r in csv.DictReader(open(results)) if r["D"].strip()]
    for dx, c in colours.items():
        pts = sorted((1 / float(r["R_mm"]) if float(r["R_mm"]) > 0 else 0.0, float(r["D"]))
                     for r in rows if float(r["dx_mm"]) == dx)
        for (a, d), (b, e) in zip(pts, pts[1:]):
            line(X(a), Y(d), X(b), Y(e), c)
        for a, d in pts:
            marker(X(a), Y(d), c, "o")
    write_png(png, W, H, px)


if __name__ == "__main__":
    main()
