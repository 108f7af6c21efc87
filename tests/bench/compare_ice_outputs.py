#!/usr/bin/env python3
"""Benchmark helper (not a test): compare two ICE output directories field by
field with `tephra extract` (17 significant digits), every saved frame.

Usage: compare_ice_outputs.py TEPHRA DIR_A DIR_B [--materials N] [--vars a,b,...]
Prints, per label, the number of entries, how many differ, and the largest
relative difference |a - b| / max(|a|, |b|, tiny) (vectors per component).
Exit 0 always; "ALL BIT-IDENTICAL" when nothing differs.
"""
import os
import subprocess
import sys

VARS = ["press_CC", "rho_CC", "vol_frac_CC", "temp_CC", "vel_CC", "sp_vol_CC", "speedSound_CC", "F"]


def extract(tephra, d, var, m):
    cmd = [tephra, "extract", d, "--var", var, "--all-times"] + (["--material", str(m)] if m is not None else [])
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        return None
    lines = r.stdout.splitlines()
    # sorted by (time, i, j, k): runs with different patch layouts list the
    # cells in different orders
    rows = [l.split(",") for l in lines[1:]]
    return sorted(rows, key=lambda r: (float(r[0]), int(r[1]), int(r[2]), int(r[3])))


def main():
    tephra, a, b = sys.argv[1:4]
    nm = int(sys.argv[sys.argv.index("--materials") + 1]) if "--materials" in sys.argv else 3
    vars_ = sys.argv[sys.argv.index("--vars") + 1].split(",") if "--vars" in sys.argv else VARS
    any_diff = False
    for var in vars_:
        for m in list(range(nm)) + [None]:
            ra, rb = extract(tephra, a, var, m), extract(tephra, b, var, m)
            if ra is None or rb is None:
                continue
            if len(ra) != len(rb):
                print(f"{var} m={m}: different entry counts {len(ra)} vs {len(rb)}")
                any_diff = True
                continue
            ndiff, worst = 0, 0.0
            for x, y in zip(ra, rb):
                for u, v in zip(x[7:], y[7:]):
                    if u != v:
                        ndiff += 1
                        fu, fv = float(u), float(v)
                        worst = max(worst, abs(fu - fv) / max(abs(fu), abs(fv), 1e-300))
            any_diff |= ndiff > 0
            print(f"{var} m={m}: {len(ra)} rows, {ndiff} values differ, max rel diff {worst:.3e}")
            if m is None:
                break
    print("ALL BIT-IDENTICAL" if not any_diff else "DIFFERENCES (see above)")


if __name__ == "__main__":
    main()
