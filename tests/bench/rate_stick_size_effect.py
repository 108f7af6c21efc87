#!/usr/bin/env python3
"""Benchmark (not a test): ANFO rate-stick size effect with the ICE deck
ICE/JWLpp8mmRS.ups (JWL++ rate, Murnaghan reactant, JWLC products, air).

Usage:
  tests/bench/rate_stick_size_effect.py BUILD_DIR run  R_MM DX_MM [OUT_ROOT] [--slab | --axisym]
  tests/bench/rate_stick_size_effect.py BUILD_DIR front R_MM DX_MM [OUT_ROOT] [--slab | --axisym]
  ... [--length L_MM]  (only with R_MM = 0: a stick and domain L_MM long, default the deck's 100)
  tests/bench/rate_stick_size_effect.py BUILD_DIR plot  RESULTS.csv PNG   (pure Python PNG)

--slab: a 2-D planar slab of half-thickness R_MM (one cell along z, z+ a
symmetry plane) instead of the quarter-symmetric 3-D stick; output
directory slabR..._dx....
--axisym: the cylinder of radius R_MM in axisymmetric ICE (session 21,
<MPM><axisymmetric>: x = r, y = the stick's axis, one cell in z): the
deck's x and y swapped (the stick along y, impact at -90 m/s along y onto
the y- symmetry plane, x- the axis), the cylinder piece replaced by the box
r < R (exact in (r, z)); output directory axiR..._dx....

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


def make_axisym_deck(r_mm, dx_mm):
    """The stick of radius r_mm as an axisymmetric run (x = r, y = axis)."""
    text = open(DECK, encoding="iso-8859-1").read()
    text = text.replace('href="inputs/', 'href="' + os.path.join(DECKS, "inputs") + "/")
    dx = dx_mm * 1e-3
    ny = int(round(0.1 / dx))                                  # along the axis (y)
    nr = int(math.ceil(15.0 / 8.0 * r_mm / dx_mm - 1e-9))      # radial (x)
    width = nr * dx
    # The deck's x- and y- are symmetry planes, x+ and y+ open: swapping x and
    # y keeps them (x- the axis, y- the impact wall); z+ becomes a symmetry plane.
    text = re.sub(r'<Face side = "z\+">.*?</Face>', SYMMETRY_FACE.format(s="z+"), text, count=1, flags=re.S)
    text = re.sub(r"<upper>.*?</upper>", f"<upper> [{width!r},1.e-1,{dx!r}] </upper>", text, count=1)
    text = re.sub(r"<resolution>.*?</resolution>", f"<resolution> [{nr}, {ny}, 1] </resolution>", text, count=1)
    text = re.sub(r'<cylinder label = "stick">\s*<bottom>.*?</cylinder>',
                  f'<box label = "stick"> <min> [-1.0, 0.0, -1.0] </min> <max> [{r_mm * 1e-3!r}, 0.1, 1.0] </max> </box>',
                  text, count=1, flags=re.S)
    text = text.replace('<cylinder label = "stick">             </cylinder>', '<box label = "stick"> </box>')
    text = re.sub(r"<velocity>\s*\[-90.0,0.0,0.0\]\s*</velocity>", "<velocity> [0.0,-90.0,0.0] </velocity>", text)
    text = text.replace("<Grid>", "<MPM> <axisymmetric> true </axisymmetric> </MPM>\n    <Grid>", 1)
    text = re.sub(r"<patches>.*?</patches>", "<patches> [1,1,1] </patches>", text, count=1)
    saves = '<save label="F"/>\n<save label="press_CC"/>\n'
    text = re.sub(r"(<outputInterval>.*?</outputInterval>).*?(</DataArchiver>)", r"\1\n" + saves + r"\2", text,
                  count=1, flags=re.S)
    return text, ny, nr


def make_deck(r_mm, dx_mm, slab=False, length_mm=100.0):
    """slab: a 2-D planar slab of half-thickness r_mm (one cell along z, the
    z+ face a symmetry plane, so the deck's cylinder about the x axis cuts
    the cells |y| < r_mm; ICE has no axisymmetric form), else the quarter-
    symmetric 3-D stick of radius r_mm."""
    text = open(DECK, encoding="iso-8859-1").read()
    text = text.replace('href="inputs/', 'href="' + os.path.join(DECKS, "inputs") + "/")
    dx = dx_mm * 1e-3
    length = length_mm * 1e-3
    nx = int(round(length / dx))
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
    text = re.sub(r"<upper>.*?</upper>", f"<upper> [{length!r},{width!r},{depth!r}] </upper>", text, count=1)
    if length_mm != 100.0:
        # A longer stick (R = 0 only): the cylinder's top at the domain's end and
        # the end time stretched by the extra length at 5 km/s (below D_CJ, so
        # the front always reaches the last cm).
        if r_mm != 0:
            raise SystemExit("--length is for the infinite-diameter stick (R_MM = 0) only")
        text = re.sub(r"<top>\s*\[0.1,0.0,0.0\]\s*</top>", f"<top> [{length!r},0.0,0.0] </top>", text, count=1)
        end = 2.0e-5 + (length - 0.1) / 5000.0
        text = re.sub(r"<maxTime>.*?</maxTime>", f"<maxTime> {end!r} </maxTime>", text, count=1)
    text = re.sub(r"<resolution>.*?</resolution>", f"<resolution> [{nx}, {ny}, {nz}] </resolution>", text, count=1)
    text = re.sub(r"<radius>.*?</radius>", f"<radius> {radius!r} </radius>", text, count=1)
    # One patch (the deck has [4,1,1]): one process, one thread, so the patches
    # only cost halo exchanges (16 % of the slab's step); the saved fields are
    # bit-identical (docs/performance.md, session 15).
    text = re.sub(r"<patches>.*?</patches>", "<patches> [1,1,1] </patches>", text, count=1)
    saves = '<save label="F"/>\n<save label="press_CC"/>\n'
    text = re.sub(r"(<outputInterval>.*?</outputInterval>).*?(</DataArchiver>)", r"\1\n" + saves + r"\2", text,
                  count=1, flags=re.S)
    return text, nx, ny


def out_dir(root, r_mm, dx_mm, slab=False, axisym=False, length_mm=100.0):
    prefix = "axi" if axisym else "slab" if slab and r_mm > 0 else ""
    suffix = "" if length_mm == 100.0 else f"_L{length_mm:g}"
    return os.path.join(root, prefix + f"R{r_mm:g}_dx{dx_mm:g}" + suffix)


def extract_front(tephra, out, dx, axisym=False, length=0.1):
    y = 0.5 * dx
    line = f"{y},{y},{y},{y},{length - y},{y}" if axisym else f"{y},{y},{y},{length - y},{y},{y}"
    cmd = [tephra, "extract", out, "--var", "F", "--material", "0", "--all-times", "--line", line]
    text = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    rows = collections.defaultdict(list)
    for r in csv.DictReader(text.splitlines()):
        rows[float(r["time"])].append((float(r["y" if axisym else "x"]), float(r["F"])))
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


def front_speed(tephra, out, dx, axisym=False, length=0.1):
    """Slopes over t >= 10 us and t >= 14 us (front below length - 1 cm), and
    over the second half of the stick (length/2 <= x <= length - 1 cm): on a
    long stick the last one is the steady speed the impact build-up reaches."""
    front = extract_front(tephra, out, dx, axisym, length)
    window = [(t, x) for t, x in front if t >= 10e-6 - 1e-12 and x <= length - 0.01]
    late = [(t, x) for t, x in window if t >= 14e-6 - 1e-12]
    half = [(t, x) for t, x in window if x >= 0.5 * length]
    slope = lambda pts: fit_slope(pts) if len(pts) > 2 else float("nan")  # nan: no front (failed)
    return front, slope(window), slope(late), slope(half)


def main():
    build, mode = sys.argv[1], sys.argv[2]
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "plot":
        return plot(sys.argv[3], sys.argv[4])
    argv = sys.argv[3:]
    length_mm = 100.0
    if "--length" in argv:
        k = argv.index("--length")
        length_mm = float(argv[k + 1])
        del argv[k:k + 2]
    args = [a for a in argv if a not in ("--slab", "--axisym")]
    slab = "--slab" in sys.argv
    axisym = "--axisym" in sys.argv
    if axisym and length_mm != 100.0:
        raise SystemExit("--length is for the infinite-diameter stick (R_MM = 0) only")
    r_mm, dx_mm = float(args[0]), float(args[1])
    root = args[2] if len(args) > 2 else "/tmp/rate_stick"
    out = out_dir(root, r_mm, dx_mm, slab, axisym, length_mm)
    if mode == "run":
        text, nx, ny = make_axisym_deck(r_mm, dx_mm) if axisym else make_deck(r_mm, dx_mm, slab, length_mm)
        os.makedirs(root, exist_ok=True)
        deck = out + ".ups"
        open(deck, "w").write(text)
        # One thread: on the shared 2-core machine a second OpenMP thread
        # spins at the row loops' barriers (session 15: the 1-patch 3-D stick
        # used 10x the CPU time of the serial run for the same steps).
        subprocess.run([tephra, deck, "--output", out, "--quiet", "--threads", "1"], check=True)
    front, d10, d14, dhalf = front_speed(tephra, out, dx_mm * 1e-3, axisym, length_mm * 1e-3)
    for t, x in front[::5]:
        print(f"t = {t * 1e6:6.2f} us  front = {x * 1e3:6.2f} mm")
    print(f"R = {r_mm:g} mm, dx = {dx_mm:g} mm: D(10 us..) = {d10:.0f} m/s, D(14 us..) = {d14:.0f} m/s, "
          f"D(second half of {length_mm:g} mm) = {dhalf:.0f} m/s")


REFERENCE = {
    # Guilkey, Harman & Banerjee (2007) ICE simulations and Souers et al. ANFO
    # experiments, as quoted in issue 6 (Vaango theory manual 26.3.1).
    "guilkey2007": [(0, 5760), (0.05, 5404), (0.08, 4906), (0.125, 4624), (0.1667, 4087)],
    "souers": [(0.0, 5890), (0.09, 4533), (0.09, 4742), (0.154, 3672)],
}
D_CJ = 5899.3  # jwlc_cj.py on JWLEOSANFO.xml


FONT = {  # 5x7 glyphs (rows top to bottom, bit 4 = leftmost column), tests/support/PngPlot.cpp's font
    '0': (14, 17, 19, 21, 25, 17, 14), '1': (4, 12, 4, 4, 4, 4, 14), '2': (14, 17, 1, 2, 4, 8, 31),
    '3': (31, 2, 4, 2, 1, 17, 14), '4': (2, 6, 10, 18, 31, 2, 2), '5': (31, 16, 30, 1, 1, 17, 14),
    '6': (6, 8, 16, 30, 17, 17, 14), '7': (31, 1, 2, 4, 8, 8, 8), '8': (14, 17, 17, 14, 17, 17, 14),
    '9': (14, 17, 17, 15, 1, 2, 12), 'A': (14, 17, 17, 31, 17, 17, 17), 'B': (30, 17, 17, 30, 17, 17, 30),
    'C': (14, 17, 16, 16, 16, 17, 14), 'D': (28, 18, 17, 17, 17, 18, 28), 'E': (31, 16, 16, 30, 16, 16, 31),
    'F': (31, 16, 16, 30, 16, 16, 16), 'G': (14, 17, 16, 23, 17, 17, 15), 'H': (17, 17, 17, 31, 17, 17, 17),
    'I': (14, 4, 4, 4, 4, 4, 14), 'J': (7, 2, 2, 2, 2, 18, 12), 'K': (17, 18, 20, 24, 20, 18, 17),
    'L': (16, 16, 16, 16, 16, 16, 31), 'M': (17, 27, 21, 21, 17, 17, 17), 'N': (17, 17, 25, 21, 19, 17, 17),
    'O': (14, 17, 17, 17, 17, 17, 14), 'P': (30, 17, 17, 30, 16, 16, 16), 'Q': (14, 17, 17, 17, 21, 18, 13),
    'R': (30, 17, 17, 30, 20, 18, 17), 'S': (15, 16, 16, 14, 1, 1, 30), 'T': (31, 4, 4, 4, 4, 4, 4),
    'U': (17, 17, 17, 17, 17, 17, 14), 'V': (17, 17, 17, 17, 17, 10, 4), 'W': (17, 17, 17, 21, 21, 21, 10),
    'X': (17, 17, 10, 4, 10, 17, 17), 'Y': (17, 17, 17, 10, 4, 4, 4), 'Z': (31, 1, 2, 4, 8, 16, 31),
    '.': (0, 0, 0, 0, 0, 12, 12), '-': (0, 0, 0, 31, 0, 0, 0), '+': (0, 4, 4, 31, 4, 4, 0),
    ':': (0, 12, 12, 0, 12, 12, 0), '/': (0, 1, 2, 4, 8, 16, 0), '(': (2, 4, 8, 8, 8, 4, 2),
    ')': (8, 4, 2, 2, 2, 4, 8), '^': (4, 10, 17, 0, 0, 0, 0), ',': (0, 0, 0, 0, 12, 4, 8),
    '=': (0, 0, 31, 0, 31, 0, 0), '_': (0, 0, 0, 0, 0, 0, 31), ' ': (0, 0, 0, 0, 0, 0, 0),
}


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
    """RESULTS.csv: R_mm,dx_mm,D[,geometry] (R_mm = 0: infinite; D empty: no detonation).
    Linear axes 1/R in [0, 0.25]/mm (ticks every 0.05) and D in [2000, 6500] m/s
    (ticks every 500), no text (key in docs/validation/rate-stick-size-effect.md):
    grey squares = Guilkey et al. 2007 simulation, black triangles = Souers
    et al. experiments, red dotted line = D_CJ, blue = Tephra dx = 2 mm,
    green = Tephra dx = 1 mm, orange = dx = 0.5 mm, purple = 0.25 mm; discs
    and solid lines = 3-D quarter sticks at 1/R, squares and dotted lines =
    2-D slabs (column geometry = slab, R_mm = half-thickness h) at 1/(2h);
    diamonds and solid lines = axisymmetric ICE sticks (geometry = axisym) at 1/R."""
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
                if (kind == "o" and a * a + b * b <= 16 or kind == "s" or kind == "^" and b >= 2 * abs(a) - 4
                        or kind == "d" and abs(a) + abs(b) <= 4):
                    dot(x + a, y + b, c)

    def text(x, y, s, c=(0, 0, 0)):
        for k, ch in enumerate(s.upper()):
            for row, bits in enumerate(FONT.get(ch, FONT[" "])):
                for col in range(5):
                    if bits & (0x10 >> col):
                        dot(x + 6 * k + col, y + row, c)

    grey, black = (140, 140, 140), (0, 0, 0)
    colours = {2.0: (30, 90, 220), 1.0: (20, 160, 60), 0.5: (230, 130, 0), 0.25: (160, 0, 160)}
    for k in range(6):  # 1/R ticks and grid
        line(X(0.05 * k), T, X(0.05 * k), H - B, (225, 225, 225), dotted=True)
        line(X(0.05 * k), H - B, X(0.05 * k), H - B + 6, black)
    for k in range(10):  # D ticks and grid
        line(L, Y(2000 + 500 * k), W - R, Y(2000 + 500 * k), (225, 225, 225), dotted=True)
        line(L - 6, Y(2000 + 500 * k), L, Y(2000 + 500 * k), black)
    for k in range(6):
        text(X(0.05 * k) - 12, H - B + 10, f"{0.05 * k:.2f}")
    for k in range(10):
        text(L - 34, Y(2000 + 500 * k) - 3, f"{2000 + 500 * k}")
    text((L + W) // 2 - 40, H - 18, "1/R (1/MM)")
    text(L + 4, 6, "D (M/S)")
    legend = [("GUILKEY 2007 SIM.", grey), ("SOUERS EXP.", black), ("D_CJ", (200, 0, 0))] + \
             [(f"DX = {dx:g} MM", c) for dx, c in colours.items()] + [("DISC: 3-D AT 1/R", black), ("SQUARE: SLAB AT 1/(2H)", black), ("DIAMOND: AXISYM. AT 1/R", black)]
    for k, (name, c) in enumerate(legend):
        text(W - R - 150, H - B - 121 + 11 * k, name, c)
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
    rows = [r for r in csv.DictReader(open(results)) if r["D"].strip()]
    # R = 0 rows with geometry = long (session 24: the second-half speed of a
    # 300-600 mm 1-D stick, run with --length) replace the 100 mm stick's
    # R = 0 row at the same dx: the 100 mm stick ends before the impact
    # build-up is over (docs/validation/rate-stick-size-effect.md §10).
    long_dx = {float(r["dx_mm"]) for r in rows if float(r["R_mm"]) == 0 and r.get("geometry", "").strip() == "long"}
    rows = [r for r in rows if not (float(r["R_mm"]) == 0 and float(r["dx_mm"]) in long_dx
                                    and r.get("geometry", "").strip() != "long")]
    # 3-D sticks (and R = 0, the 1-D stick) at 1/R: solid lines, discs. Slabs of
    # half-thickness h at 1/(2h) (the cylinder radius with the same front
    # curvature on the axis, docs/validation/rate-stick-size-effect.md):
    # dotted lines, squares; the 1-D point (R = 0) starts both series.
    # Axisymmetric ICE sticks (geometry = axisym, session 21) at 1/R: solid
    # lines, diamonds.
    for geo in ("", "slab", "axisym"):
        slab = geo == "slab"
        for dx, c in colours.items():
            pts = sorted((0.0 if float(r["R_mm"]) == 0 else 1 / ((2 if slab else 1) * float(r["R_mm"])), float(r["D"]))
                         for r in rows if float(r["dx_mm"]) == dx
                         and (float(r["R_mm"]) == 0 or r.get("geometry", "").strip() == geo))
            if geo and all(a == 0 for a, _ in pts):
                continue
            for (a, d), (b, e) in zip(pts, pts[1:]):
                line(X(a), Y(d), X(b), Y(e), c, dotted=slab)
            for a, d in pts:
                marker(X(a), Y(d), c, ("s" if slab else "d" if geo else "o") if a > 0 else "o")
    write_png(png, W, H, px)


if __name__ == "__main__":
    main()
