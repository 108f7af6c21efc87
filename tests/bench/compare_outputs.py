#!/usr/bin/env python3
"""Compare two tephra output directories frame by frame (not a test): every
saved label of every material at every saved time, through `tephra extract`.
Prints, per label and material, BITS (the extracted text is identical) or
the largest relative difference |a - b| / max(|a|, |b|, floor) over all values.

Usage: tests/bench/compare_outputs.py TEPHRA DIR_A DIR_B LABEL [LABEL ...]
       [--materials 0,1,2,3] [--floor 1e-300]
"""
import subprocess
import sys


def extract(tephra, out, var, material):
    cmd = [tephra, "extract", out, "--var", var, "--material", str(material), "--all-times"]
    r = subprocess.run(cmd, capture_output=True, text=True)
    return r.stdout if r.returncode == 0 else None


def main():
    args = sys.argv[1:]
    mats, floor = [0, 1, 2, 3], 1e-300
    if "--materials" in args:
        i = args.index("--materials")
        mats = [int(m) for m in args[i + 1].split(",")]
        del args[i:i + 2]
    if "--floor" in args:
        i = args.index("--floor")
        floor = float(args[i + 1])
        del args[i:i + 2]
    tephra, a, b, labels = args[0], args[1], args[2], args[3:]
    all_bits = True
    for var in labels:
        for m in mats:
            ta, tb = extract(tephra, a, var, m), extract(tephra, b, var, m)
            if ta is None and tb is None:
                continue
            if ta == tb:
                print(f"{var:16s} mat {m}: BITS ({len(ta.splitlines()) - 1} values)")
                continue
            all_bits = False
            if ta is None or tb is None:
                print(f"{var:16s} mat {m}: present in one output only")
                continue
            la, lb = ta.splitlines(), tb.splitlines()
            if len(la) != len(lb) or la[0] != lb[0]:
                print(f"{var:16s} mat {m}: different rows/columns ({len(la)} vs {len(lb)})")
                continue
            worst = 0.0
            for ra, rb in zip(la[1:], lb[1:]):
                for x, y in zip(ra.split(","), rb.split(",")):
                    try:
                        fx, fy = float(x), float(y)
                    except ValueError:
                        continue
                    d = abs(fx - fy) / max(abs(fx), abs(fy), floor)
                    worst = max(worst, d)
            print(f"{var:16s} mat {m}: max rel diff {worst:.3e}")
    print("ALL BITS" if all_bits else "DIFFERENCES")


if __name__ == "__main__":
    main()
