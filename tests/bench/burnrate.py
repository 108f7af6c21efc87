#!/usr/bin/env python3
"""C10 MPMICE/BurnRate.ups (DDT1 strand burner): run it and compare its burn
rate against pressure with the HMX strand-burner data (ExpData.dat).

  burnrate.py BUILD run OUT [--end-time T] [--max-steps N]
      writes OUT.ups = the deck with extra <save> labels only (rho_CC,
      temp_CC, vel_CC, burning, surfaceTemp; physics unchanged) and runs
      `nice -n 19 tephra OUT.ups --output OUT --threads 1`.
  burnrate.py BUILD analyse OUT [CSV [PNG]]
      per pair of consecutive output frames: the burn rate
        r = (B(t2) - B(t1)) / (t2 - t1) / (rho_HE SA),
      B(t) = product mass in the domain - its initial mass (every product
      gram comes from the PBX: the box is closed by symmetry planes),
      rho_HE = 1832 kg/m^3 and SA = dy dz = 1 mm^2 (compare_burn_rates.m:
      -rho_CC 1832, SA = dx dy of the 1-D strand); against the average
      pressure of the gas region (cells with product volume fraction > 0.5),
      the mean over the two frames. Uintah's compare_burn_rates.m takes the
      burned mass of one step over that step's dt at each output time
      (Uintah writes totalMassBurned every step; Tephra writes reductions at
      output times only), and its average pressure from `puda -jacquie`
      (the gas region; its exact cell criterion is not in the script).
      Prints the table and the data comparison, writes CSV and a PNG
      (log-log: red crosses = ExpData.dat, blue discs = Tephra, green line =
      the WSB model at T0 = 298 K from wsb_burn_rate.py).
"""
import math
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
shared = os.path.join(here, "..", "..", "..", "shared", "decks")
deck = os.path.join(shared, "inputs", "MPMICE", "BurnRate.ups")
expdata = os.path.join(shared, "orderAccuracy", "MPMICE", "ExpData.dat")
RHO_HE, SA, V = 1832.0, 1e-6, 1e-9
LINE = ["--line", "0.0005,0.0005,0.0005,0.1995,0.0005,0.0005"]


def write_copy(path_out):
    s = open(deck).read()
    s = s.replace('<save label="press_CC"/>', '<save label="press_CC"/>\n      <save label="rho_CC"/>\n'
                  '      <save label="temp_CC"/>\n      <save label="vel_CC"/>\n'
                  '      <save label="burning"/>\n      <save label="surfaceTemp"/>')
    open(path_out, "w").write(s)


def extract(tephra, out, var, mat=None):
    """{time: [value per cell along x]}"""
    cmd = [tephra, "extract", out, "--var", var, "--all-times"] + LINE + (["--material", str(mat)] if mat is not None else [])
    rows = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip().split("\n")[1:]
    frames = {}
    for r in rows:
        f = r.split(",")
        frames.setdefault(float(f[0]), []).append(float(f[-1]))
    return frames


def analyse(tephra, out):
    rho = extract(tephra, out, "rho_CC", 1)
    theta = extract(tephra, out, "vol_frac_CC", 1)
    press = extract(tephra, out, "press_CC")
    times = sorted(rho)
    mass = {t: sum(rho[t]) * V for t in times}
    pgas = {}
    for t in times:
        cells = [p for p, th in zip(press[t], theta[t]) if th > 0.5]
        pgas[t] = sum(cells) / len(cells)
    rows = []
    for t1, t2 in zip(times, times[1:]):
        r = (mass[t2] - mass[t1]) / (t2 - t1) / (RHO_HE * SA)
        rows.append((0.5 * (t1 + t2), 0.5 * (pgas[t1] + pgas[t2]), r, mass[t2] - mass[times[0]]))
    return rows


def plot(rows, png, model=None):
    sys.path.insert(0, here)
    from rate_stick_size_effect import FONT, write_png
    W, H, L, R, T, B = 720, 480, 60, 20, 20, 50
    px = bytearray([255] * (W * H * 3))
    # log10 p in [5, 7.5] (Pa), log10 r in [-4, -1.5] (m/s)
    X = lambda p: L + (math.log10(p) - 5.0) / 2.5 * (W - L - R)
    Y = lambda r: H - B - (math.log10(r) + 4.0) / 2.5 * (H - T - B)

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

    def text(x, y, s, c=(0, 0, 0)):
        for k, ch in enumerate(s.upper()):
            for row, bits in enumerate(FONT.get(ch, FONT[" "])):
                for col in range(5):
                    if bits & (0x10 >> col):
                        dot(x + 6 * k + col, y + row, c)

    black, grey = (0, 0, 0), (225, 225, 225)
    for e in range(6):  # decades and half decades of p
        x = X(10 ** (5 + 0.5 * e))
        line(x, T, x, H - B, grey, dotted=True)
        text(x - 14, H - B + 10, f"1E{5 + 0.5 * e:g}")
    for e in range(6):
        y = Y(10 ** (-4 + 0.5 * e))
        line(L, y, W - R, y, grey, dotted=True)
        text(4, y - 3, f"1E{-4 + 0.5 * e:g}")
    line(L, H - B, W - R, H - B, black)
    line(L, T, L, H - B, black)
    text((L + W) // 2 - 60, H - 18, "GAS PRESSURE (PA)")
    text(L + 4, 6, "BURN RATE (M/S)")
    for k, (name, c) in enumerate([("EXPDATA.DAT HMX 298 K", (200, 0, 0)), ("TEPHRA BURNRATE.UPS", (30, 90, 220)),
                                   ("WSB MODEL T0 = 298 K", (20, 160, 60))]):
        text(L + 20, T + 10 + 11 * k, name, c)
    for p, r in (tuple(map(float, l.split())) for l in open(expdata) if l.strip()):
        for a in range(-4, 5):
            dot(X(p) + a, Y(r) + a, (200, 0, 0))
            dot(X(p) + a, Y(r) - a, (200, 0, 0))
    if model:
        for (p1, r1), (p2, r2) in zip(model, model[1:]):
            line(X(p1), Y(r1), X(p2), Y(r2), (20, 160, 60))
    for _, p, r, _ in rows:
        if r > 0:
            for a in range(-3, 4):
                for b in range(-3, 4):
                    if a * a + b * b <= 9:
                        dot(X(p) + a, Y(r) + b, (30, 90, 220))
    write_png(png, W, H, px)


def main():
    build, mode, out = sys.argv[1], sys.argv[2], sys.argv[3]
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "run":
        copy = out + ".ups"
        write_copy(copy)
        extra = sys.argv[4:]
        subprocess.run(["nice", "-n", "19", tephra, copy, "--output", out, "--threads", "1"] + extra, check=True)
        return
    rows = analyse(tephra, out)
    data = [tuple(map(float, l.split())) for l in open(expdata) if l.strip()]
    print("t_mid [s], p_gas [Pa], r [mm/s], burned [kg]")
    for t, p, r, b in rows:
        print(f"{t:.4e}, {p:.5e}, {r * 1e3:.4f}, {b:.4e}")
    if len(sys.argv) > 4:
        with open(sys.argv[4], "w") as f:
            f.write("t_mid_s,p_gas_Pa,r_m_per_s,burned_kg\n")
            for row in rows:
                f.write(",".join(f"{v:.9g}" for v in row) + "\n")
    if len(sys.argv) > 5:
        model = None
        try:
            sys.path.insert(0, here)
            import wsb_burn_rate
            model = [(p, float(wsb_burn_rate.rate_mm_s(p)) * 1e-3) for p in (10 ** (5 + 0.05 * k) for k in range(51))]
        except Exception as e:  # the plot without the model line
            print("no WSB line:", e)
        plot(rows, sys.argv[5], model)


if __name__ == "__main__":
    main()
