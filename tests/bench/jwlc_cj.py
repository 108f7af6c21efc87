#!/usr/bin/env python3
"""Chapman-Jouguet state of the JWLC detonation products of a deck (offline
check of the figures that tests/verification/test_ice_reactions.cpp derives
in C++).

Usage: tests/bench/jwlc_cj.py [JWLC_INCLUDE.xml] [p0]
  default: ../shared/decks/inputs/ICE/EOSData/JWLEOSANFO.xml, p0 = 101325 Pa.

JWLC (Uintah's JWLC EOS, no energy term): with V = rho0/rho,
  p(V) = A exp(-R1 V) + B exp(-R2 V) + C V^-(1 + om).
Since p does not depend on the internal energy, the products' Hugoniot from
any initial state is this curve itself. The Rayleigh line from the
unreacted state (V = 1, p0), p - p0 = rho0 D^2 (1 - V), touches it at the CJ
point (the sonic point):
  rho0 D^2 = -p'(V)   and   p(V) - p0 = -p'(V) (1 - V),
one equation in V (bisection on [0.3, 0.99]); D_CJ = sqrt(-p'(V_CJ)/rho0),
u_CJ = D (1 - V_CJ).
ANFO (the deck's JWLEOSANFO.xml): V_CJ = 0.748, p_CJ = 10.2 GPa,
D_CJ = 5899 m/s.
"""
import math
import os
import re
import sys


def read_jwlc(path):
    text = open(path, encoding="iso-8859-1").read()
    get = lambda tag: float(re.search(r"<%s>\s*([^<]+?)\s*</%s>" % (tag, tag), text).group(1))
    return {k: get(k) for k in ("A", "B", "C", "R1", "R2", "om", "rho0")}


def cj_state(e, p0):
    p = lambda V: e["A"] * math.exp(-e["R1"] * V) + e["B"] * math.exp(-e["R2"] * V) + e["C"] * V ** (-1 - e["om"])
    dp = lambda V: (-e["R1"] * e["A"] * math.exp(-e["R1"] * V) - e["R2"] * e["B"] * math.exp(-e["R2"] * V)
                    - (1 + e["om"]) * e["C"] * V ** (-2 - e["om"]))
    f = lambda V: p(V) - p0 + dp(V) * (1 - V)
    a, b = 0.3, 0.99
    assert f(a) < 0 < f(b), "no tangent point in [0.3, 0.99]"
    for _ in range(200):
        m = 0.5 * (a + b)
        a, b = (m, b) if f(m) < 0 else (a, m)
    V = 0.5 * (a + b)
    D = math.sqrt(-dp(V) / e["rho0"])
    return V, p(V), D, D * (1 - V)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "..", "shared", "decks", "inputs", "ICE", "EOSData", "JWLEOSANFO.xml")
    p0 = float(sys.argv[2]) if len(sys.argv) > 2 else 101325.0
    V, p, D, u = cj_state(read_jwlc(path), p0)
    print(f"{os.path.basename(path)}: V_CJ = {V:.4f}, p_CJ = {p / 1e9:.3f} GPa, D_CJ = {D:.1f} m/s, u_CJ = {u:.1f} m/s")


if __name__ == "__main__":
    main()
