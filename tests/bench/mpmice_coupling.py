#!/usr/bin/env python3
"""Benchmark (not a test): the cost of the MPMICE coupling on the rate-stick
deck MPMICE/JWLppCuRS2d.ups (decks README C4; 200 x 48 x 1 cells, 13 440
GIMP copper particles, three ICE materials), one thread, CPU time.

Usage:
  tests/bench/mpmice_coupling.py BUILD_DIR [--end-time T] [--out DIR]

Runs `tephra --threads 1 --end-time T` (default 2e-7 s, about 60 steps); the
phase table (core/base/PhaseTimers.h) carries the process CPU time of each
phase (with one thread, the thread's CPU: a loaded machine does not inflate
it, unlike the wall column), and prints

  * coupled cell-steps and particle-steps per CPU second of the step
    ("MPMICE: advance" + "stable time step"), and of the whole run;
  * the share of each phase in the step's CPU time;
  * the coupling's overhead over MPM + ICE alone, defined from the phase
    timers of the coupled run:
        alone    = sum of the "MPM: ..." phases + sum of the "ICE: ..." phases
                   + "stable time step"  (work each code does on its own: its
                   particles / its cells, with every material the coupled
                   problem has),
        coupling = the "MPMICE: ..." phases (nodes to cells, solid volume
                   fluxes, pressure to particles, cell changes to nodes) + the
                   rest of "MPMICE: advance" no phase covers (the hooks' glue,
                   the step-redo snapshot when the deck has <Models>),
        overhead = coupling / alone      (target < 30 %, issue 6).
    ICE's phases include the solid's share of the multi-material work
    (equilibration, exchange with one more material); that is counted as
    "alone" here, so the figure is the cost of the transfers between the two
    codes, not of having a fourth material.
"""
import os
import resource
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from jwlppcurs2d import make_deck  # noqa: E402  (the deck with absolute include paths)

CELLS = 200 * 48 * 1  # interior cells
PARTICLES = 13440     # copper particles (docs/performance.md "MPMICE"; none leaves the grid this early)


def parse_table(text):
    """Phase rows of the table printed at the end of the run: name -> (wall, calls, cpu)."""
    rows, on = {}, False
    for line in text.splitlines():
        if line.startswith("phase") and "wall [s]" in line:
            on = "CPU [s]" in line
            if not on:
                raise SystemExit("the phase table has no CPU column")
            continue
        if not on:
            continue
        name, rest = line[:44].strip(), line[44:].split()
        # columns: wall, share, calls, process CPU, main-thread CPU
        if name == "total" or len(rest) != 5:
            on = name != "total"
            continue
        rows[name] = (float(rest[0]), int(rest[2]), float(rest[3]))
    return rows


def main():
    args = sys.argv[1:]
    if not args:
        raise SystemExit(__doc__)
    build = args[0]
    end_time = "2e-7"
    out = "/tmp/mpmice_coupling"
    if "--end-time" in args:
        end_time = args[args.index("--end-time") + 1]
    if "--out" in args:
        out = args[args.index("--out") + 1]
    os.makedirs(out, exist_ok=True)
    deck = os.path.join(out, "JWLppCuRS2d.ups")
    with open(deck, "w", encoding="iso-8859-1") as f:
        f.write(make_deck("confined"))
    env = dict(os.environ)
    exe = os.path.join(build, "bin", "tephra")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    r = subprocess.run([exe, deck, "--threads", "1", "--end-time", end_time, "--output", os.path.join(out, "run")],
                       env=env, capture_output=True, text=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:] + r.stderr[-3000:])
        raise SystemExit("tephra exit %d" % r.returncode)
    run_cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    rows = parse_table(r.stdout)
    adv = rows["MPMICE: advance"]
    steps = adv[1]
    dt_phase = rows.get("stable time step", (0.0, 0, 0.0))
    step_cpu = adv[2] + dt_phase[2]
    mpm = sum(v[2] for k, v in rows.items() if k.startswith("MPM: "))
    ice = sum(v[2] for k, v in rows.items() if k.startswith("ICE: "))
    named = {k: v[2] for k, v in rows.items() if k.startswith("MPMICE: ") and k != "MPMICE: advance"}
    glue = adv[2] - mpm - ice - sum(named.values())
    alone = mpm + ice + dt_phase[2]
    coupling = sum(named.values()) + glue
    particles = PARTICLES
    load = os.getloadavg()
    print("JWLppCuRS2d, --threads 1, --end-time %s: %d steps; load average %.1f %.1f %.1f" % ((end_time, steps) + load))
    print("whole run (reading, init, output included): %.2f CPU-s" % run_cpu)
    print("step CPU (MPMICE: advance + stable time step): %.3f s = %.2f ms/step" % (step_cpu, 1e3 * step_cpu / steps))
    print("coupled cell-steps / CPU-s:     %10.0f  (%d cells)" % (CELLS * steps / step_cpu, CELLS))
    print("coupled particle-steps / CPU-s: %10.0f  (%d particles)" % (particles * steps / step_cpu, particles))
    print("\n%-44s %10s %7s" % ("phase (CPU of the step)", "cpu [s]", "share"))
    for k, v in rows.items():
        if k.startswith(("MPM: ", "ICE: ", "MPMICE: ")) and k != "MPMICE: advance" or k == "stable time step":
            print("%-44s %10.4f %6.1f%%" % (k, v[2], 100 * v[2] / step_cpu))
    print("%-44s %10.4f %6.1f%%" % ("(MPMICE: advance not in a phase)", glue, 100 * glue / step_cpu))
    print("\nMPM phases %.3f s, ICE phases %.3f s, stable time step %.3f s: alone = %.3f s" % (mpm, ice, dt_phase[2], alone))
    print("coupling = MPMICE phases %.3f s + unphased %.3f s = %.3f s" % (sum(named.values()), glue, coupling))
    print("overhead = coupling / alone = %.1f %%  (target < 30 %%)" % (100 * coupling / alone))


if __name__ == "__main__":
    main()
