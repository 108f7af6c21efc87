#!/usr/bin/env python3
"""Final length L(t) and foot radius R(t) of the Taylor-impact study runs at every output frame
(the measures of tests/bench/taylor_impact_study.py, docs/models/taylor-impact.md), to see whether
the 80 us values of the three spacings differ by discretisation or by where each rod is in its
residual elastic ringing when the run stops.

    python3 tests/bench/taylor_shape_history.py TEPHRA WORK [--since 40e-6]

WORK holds the study's run folders h1.0000, h0.7500, h0.5625 (rigid wall) and *_symmetry; prints
per run and frame t, L, R, KE/KE0, then over t >= --since: the mean, the half range (max - min)/2
of L and R, and the last value; and L at rest extrapolated from the last three frames: near the
stop the rod's top decelerates about uniformly, L(t) = L_rest + (a/2)(t_rest - t)^2, so the parabola
through the last three (t, L) has its vertex at (t_rest, L_rest) (reported when a > 0 and
t_rest > the last frame; otherwise the rod has stopped and L_rest = its minimum). No new run: it
reads the frames the study saved. Also the footprint radius of the first particle row at the
first and last frames (footprint_radius; docs/models/taylor-impact.md, session 16).
"""
import argparse
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import taylor_impact_study as study  # noqa: E402


frames = study.frames
footprint_radius = study.footprint_radius
rest_extrapolation = study.rest_extrapolation


def time_of(tephra, out, step):
    return study.frame_time(tephra, out, step)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tephra")
    ap.add_argument("work")
    ap.add_argument("--since", type=float, default=40e-6)
    a = ap.parse_args()
    summary = []
    for wall, suffix, rod in (("rigid", "", "1"), ("symmetry", "_symmetry", "0")):
        study.ROD = rod
        for h in (1.0, 0.75, 0.5625):
            out = os.path.join(a.work, f"h{h:.4f}{suffix}", "out")
            if not os.path.isdir(out):
                continue
            first = study.particle_table(a.tephra, out, 0)  # lengths in m; printed in mm
            ke = study.read_dat(os.path.join(out, "KineticEnergy.dat"))
            ke0 = ke[0][1]
            hist = []
            for s in frames(out):
                t = time_of(a.tephra, out, s)
                L, R = (1e3 * v for v in study.extents(study.particle_table(a.tephra, out, s), first, h * 1e-3)[:2])
                k = min(ke, key=lambda r: abs(r[0] - t))[1] / ke0
                hist.append((t, L, R, k))
                print(f"{wall:8s} h={h:<6} t={t * 1e6:7.2f} us  L={L:.4f} mm  R={R:.4f} mm  KE/KE0={k:.4%}", flush=True)
            late = [r for r in hist if r[0] >= a.since]
            Ls, Rs = [r[1] for r in late], [r[2] for r in late]
            tr, lr = rest_extrapolation(hist)
            last = study.particle_table(a.tephra, out, frames(out)[-1])
            ra0, ra1 = footprint_radius(first, first, h * 1e-3), footprint_radius(last, first, h * 1e-3)
            print(f"{wall:8s} h={h:<6} footprint radius: seeded {ra0 * 1e3:.4f} mm, last {ra1 * 1e3:.4f} mm, "
                  f"ratio {ra1 / ra0:.4f}", flush=True)
            summary.append((wall, h, sum(Ls) / len(Ls), (max(Ls) - min(Ls)) / 2, Ls[-1],
                            sum(Rs) / len(Rs), (max(Rs) - min(Rs)) / 2, Rs[-1], len(late), tr, lr))
    print(f"\nover t >= {a.since * 1e6:.0f} us (L0 = 32.4 mm, R0 = 3.2 mm):")
    print("wall     h [mm]  L mean  L half-range  L last   R mean  R half-range  R last  frames  t_rest [us]  L_rest")
    for w, h, lm, lr, ll, rm, rr, rl, n, tr, lrest in summary:
        print(f"{w:8s} {h:<7} {lm:7.4f} {lr:9.4f}    {ll:7.4f}  {rm:7.4f} {rr:9.4f}    {rl:7.4f}  {n:4d}"
              f"  {tr * 1e6:9.2f}  {lrest:7.4f}")


if __name__ == "__main__":
    main()
