#!/usr/bin/env python3
"""C10 MPMICE/BurnRate.ups (DDT1 strand burner) with explicit ICE.

The unchanged deck needs <ImplicitSolver> in MPMICE and the ICE initial value
<geom_object><volumeFraction> (both exit 3 today). This writes a copy with
the <ImplicitSolver> block and the product's <volumeFraction> line removed
(the product then fills the volume the PBX leaves), saving the DDT1
diagnostics every 100 steps, runs it and prints, per frame, the burning
cell, its WSB surface temperature, the gas pressure next to it and the
burned mass of the step (docs/mpmice.md, "BurnRate.ups: an explicit copy").

Usage: burnrate_explicit.py BUILD_DIR [STEPS] [OUT]
"""
import os
import re
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
deck = os.path.join(here, "..", "..", "..", "shared", "decks", "inputs", "MPMICE", "BurnRate.ups")


def explicit_copy(path_out):
    s = open(deck).read()
    s = re.sub(r"<ImplicitSolver>.*?</ImplicitSolver>", "", s, flags=re.S)
    s = re.sub(r"\s*<volumeFraction>\s*0\.0\s*</volumeFraction>\s*\n(\s*</geom_object>\s*\n\s*<geom_object>\s*\n\s*<difference>)",
               r"\n\1", s, count=1)
    s = s.replace('<save label="press_CC"/>', '<save label="press_CC"/>\n      <save label="temp_CC"/>\n'
                  '      <save label="burning"/>\n      <save label="surfaceTemp"/>')
    s = s.replace("<outputInterval> 1e-6</outputInterval>", "<outputTimestepInterval> 100 </outputTimestepInterval>")
    open(path_out, "w").write(s)


def main():
    build = sys.argv[1]
    steps = sys.argv[2] if len(sys.argv) > 2 else "400"
    out = sys.argv[3] if len(sys.argv) > 3 else "burnrate_explicit_out"
    tephra = os.path.join(build, "bin", "tephra")
    copy = out + ".ups"
    explicit_copy(copy)
    subprocess.run([tephra, copy, "--output", out, "--max-steps", steps, "--threads", "1", "--quiet"], check=True)
    burned = [l.split() for l in open(os.path.join(out, "totalMassBurned.dat")) if l.strip()]
    line = ["--line", "0.0005,0.0005,0.0005,0.1995,0.0005,0.0005"]
    for t, dm in burned[1:]:
        def col(var, mat=None):
            cmd = [tephra, "extract", out, "--var", var, "--time", t] + line + (["--material", mat] if mat else [])
            rows = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout.strip().split("\n")[1:]
            return [float(r.split(",")[-1]) for r in rows]
        burning, Ts, p = col("burning"), col("surfaceTemp"), col("press_CC")
        cells = [i for i, b in enumerate(burning) if b > 0]
        for i in cells:
            print("t = %s s: cell %d burning (%d), Ts = %.3f K, p(i-1) = %.6g Pa, dm = %s kg"
                  % (t, i, burning[i], Ts[i], p[i - 1], dm))


if __name__ == "__main__":
    main()
