#!/usr/bin/env python3
"""C10 MPMICE/BurnRate.ups (DDT1 strand burner): run it and compare its burn
rate against pressure with the HMX strand-burner data (ExpData.dat).

  burnrate.py BUILD run OUT [--end-time T] [--max-steps N]
      writes OUT.ups = the deck with extra <save> labels only (rho_CC,
      temp_CC, vel_CC, burning, surfaceTemp; physics unchanged) and runs
      `nice -n 19 tephra OUT.ups --output OUT --threads 1`.
  burnrate.py BUILD curve OUTDIR [CSV [PNG]] [--end-time T] [--rerun]
      the burn-rate curve: for each pressure of ExpData.dat from 0.24 to
      4.83 MPa, the deck with its initial gas state moved to that pressure
      (both product <density> values scaled by p/p_deck at the deck's
      temperatures, p_deck = omega rho Cv T = 0.45 x 1.38934929 x 594.96 x
      3000 = 1.1159 MPa for the JWL product at this density, whose exponential
      terms vanish; every other line unchanged), run to T (default 6e-6 s,
      one at a time, nice 19; a run whose output exists is reused unless
      --rerun), rate and mean gas pressure as in `analyse`
      over the frames after the first microsecond. Prints per pressure the
      simulation, the WSB model at the run's gas pressure (wsb_burn_rate.py)
      and the data (mean of ExpData.dat at that pressure), writes CSV and a
      PNG (the analyse plot with one disc per run).
      Uintah's Compare_burn_rates configurations (orderAccuracy/
      test_config_files/MPMICE/Compare_burn_rates/) vary the exchange
      coefficients, resolution, particles per cell, the MPM/ICE volume
      fractions and T0, not the initial pressure: their curve is one long
      run of a closed box whose pressure rises as the strand burns
      (DeterminingBurnRate.ups: 0.1 m, gas 0.69467 kg/m^3 at 3000 K = 0.558
      MPa, 0.01 s); compare_burn_rates.m takes the burned mass per step over
      dt / (rho SA) against the mean gas pressure at each output. Here the
      box's pressure barely moves in the microseconds affordable (1.116 to
      1.117 MPa in 30 us), so each pressure is its own run.
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


P_DECK = 0.45 * 1.38934929 * 594.96 * 3000.0  # the deck's initial gas pressure (JWL product, see curve)


def write_copy(path_out, pressure=None):
    s = open(deck).read()
    if pressure is not None:  # scale the product densities: p = omega rho Cv T at the deck's temperatures
        f = pressure / P_DECK
        for rho in ("13.8934929", "1.38934929"):
            s = re.sub(r"<density>\s*" + rho + r"\s*</density>", f"<density> {float(rho) * f:.9g} </density>", s)
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


def analyse(tephra, out, t_skip=0.0):
    rho = extract(tephra, out, "rho_CC", 1)
    theta = extract(tephra, out, "vol_frac_CC", 1)
    press = extract(tephra, out, "press_CC")
    times = [t for t in sorted(rho) if t >= t_skip - 1e-12]
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


def curve(tephra, outdir, csv, png, end_time):
    sys.path.insert(0, here)
    import wsb_burn_rate
    data = [tuple(map(float, l.split())) for l in open(expdata) if l.strip()]
    pressures = sorted({p for p, _ in data if 0.23e6 <= p <= 4.84e6})
    os.makedirs(outdir, exist_ok=True)
    table = []
    for p in pressures:
        out = os.path.join(outdir, f"p{p / 1e6:.2f}MPa")
        if not os.path.exists(os.path.join(out, "tephra.xdmf")) or "--rerun" in sys.argv:
            write_copy(out + ".ups", p)
            with open(out + ".log", "w") as log:
                subprocess.run(["nice", "-n", "19", tephra, out + ".ups", "--output", out, "--threads", "1",
                                "--end-time", str(end_time)], check=True, stdout=log, stderr=log)
        rows = analyse(tephra, out, t_skip=1e-6)
        pg = sum(r[1] for r in rows) / len(rows)
        r_sim = sum(r[2] for r in rows) / len(rows)
        spread = (max(r[2] for r in rows) - min(r[2] for r in rows)) / r_sim
        r_wsb = float(wsb_burn_rate.rate_mm_s(pg)) * 1e-3
        pts = [r for q, r in data if q == p]
        r_dat = sum(pts) / len(pts)
        table.append((p, pg, r_sim, spread, r_wsb, r_dat, min(pts), max(pts), len(pts)))
    print("p_data [MPa], p_gas run [MPa], r_sim [mm/s] (spread over frames), r_WSB(p_gas) [mm/s], sim/WSB - 1,"
          " data mean [mm/s] (n), sim/data - 1, within 10 %")
    for p, pg, rs, sp, rw, rd, lo, hi, n in table:
        dev = rs / rd - 1
        print(f"{p / 1e6:.2f}, {pg / 1e6:.4f}, {rs * 1e3:.4f} ({sp * 100:.2f} %), {rw * 1e3:.4f}, {(rs / rw - 1) * 100:+.2f} %,"
              f" {rd * 1e3:.4f} ({n}), {dev * 100:+.1f} %, {'yes' if abs(dev) <= 0.10 else 'no'}")
    if csv:
        with open(csv, "w") as f:
            f.write("p_data_Pa,p_gas_Pa,r_sim_m_per_s,r_sim_spread_rel,r_wsb_m_per_s,r_data_mean_m_per_s,"
                    "r_data_min,r_data_max,n_data,sim_over_wsb_minus_1,sim_over_data_minus_1\n")
            for p, pg, rs, sp, rw, rd, lo, hi, n in table:
                f.write(",".join(f"{v:.9g}" for v in (p, pg, rs, sp, rw, rd, lo, hi, n, rs / rw - 1, rs / rd - 1)) + "\n")
    if png:
        model = [(q, float(wsb_burn_rate.rate_mm_s(q)) * 1e-3) for q in (10 ** (5 + 0.05 * k) for k in range(51))]
        plot([(0, pg, rs, 0) for _, pg, rs, *_ in table], png, model)


def main():
    build, mode, out = sys.argv[1], sys.argv[2], sys.argv[3]
    tephra = os.path.join(build, "bin", "tephra")
    if mode == "curve":
        rest, args, end = sys.argv[4:], [], 6e-6
        while rest:
            a = rest.pop(0)
            if a == "--end-time":
                end = float(rest.pop(0))
            elif a != "--rerun":
                args.append(a)
        curve(tephra, out, args[0] if args else None, args[1] if len(args) > 1 else None, end)
        return
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
