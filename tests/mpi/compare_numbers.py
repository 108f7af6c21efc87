#!/usr/bin/env python3
"""Numeric comparison of two output directories (ctest mpi_cli_mpm, compare_ranks_mpm.cmake).

usage: compare_numbers.py A B REL ABS [EXTRACT_A EXTRACT_B ...]
Every .dat file of A must exist in B with the same number of rows and columns;
each value must satisfy |a - b| <= REL * max|a over the file| + ABS.
Further arguments come in pairs of text files (`tephra extract` output):
their tokens must match, numbers within the same bound (scale: the file's max).
Prints the worst relative difference; exit 1 on a mismatch.
"""
import glob
import os
import re
import sys


def numbers(text):
    out = []
    for tok in re.split(r"[\s,]+", text.strip()):
        try:
            out.append(float(tok))
        except ValueError:
            out.append(tok)
    return out


def compare(name, ta, tb, rel, ab):
    a, b = numbers(ta), numbers(tb)
    if len(a) != len(b):
        sys.exit(f"{name}: {len(a)} tokens vs {len(b)}")
    scale = max([abs(x) for x in a if isinstance(x, float)] + [0.0])
    worst = 0.0
    for x, y in zip(a, b):
        if isinstance(x, float) != isinstance(y, float):
            sys.exit(f"{name}: token {x!r} vs {y!r}")
        if not isinstance(x, float):
            if x != y:
                sys.exit(f"{name}: token {x!r} vs {y!r}")
            continue
        d = abs(x - y)
        if d > rel * scale + ab:
            sys.exit(f"{name}: {x!r} vs {y!r} (scale {scale})")
        if scale > 0:
            worst = max(worst, d / scale)
    return worst


def main():
    a_dir, b_dir, rel, ab = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
    dats = sorted(glob.glob(os.path.join(a_dir, "*.dat")))
    if not dats:
        sys.exit(f"{a_dir} has no .dat files")
    worst = 0.0
    for path in dats:
        other = os.path.join(b_dir, os.path.basename(path))
        if not os.path.exists(other):
            sys.exit(f"{other} missing")
        worst = max(worst, compare(os.path.basename(path), open(path).read(), open(other).read(), rel, ab))
    extra = sys.argv[5:]
    for fa, fb in zip(extra[0::2], extra[1::2]):
        ta = open(fa).read()
        if not ta.strip():
            sys.exit(f"{fa} is empty")
        worst = max(worst, compare(os.path.basename(fa), ta, open(fb).read(), rel, ab))
    print(f"{len(dats)} .dat files and {len(extra) // 2} extracts agree; worst relative difference {worst:.3g}")


main()
