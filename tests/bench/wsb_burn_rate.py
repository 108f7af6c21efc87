#!/usr/bin/env python3
"""Independent solution of the Ward-Son-Brewster (WSB) steady burn model.

M. J. Ward, S. F. Son, M. Q. Brewster, "Steady deflagration of HMX with
simple kinetics: a gas phase chain reaction model", Combust. Flame 114
(1998) 556. The two closed-form relations (written from the physics, see
docs/mpmice.md "The WSB rate at 0.24 MPa"):

  condensed phase (Lengelle's activation-energy asymptotics):
     m^2 = Ac R kc rho_c Ts^2 exp(-Ec/(R Ts)) / (Ec [Cp (Ts - T0) - Qc/2])
  gas phase (zero activation energy, reaction rate Bg (p W/R)^2 Y, Le = 1):
     the temperature above the surface relaxes as exp(-r x) with
     kg r^2 + m Cp r - Cp Bg p^2 W^2/R^2 = 0, and the surface heat balance
     kg r (Tf - Ts) = m Cp (Ts - T0 - Qc/Cp), Tf = T0 + (Qc + Qg)/Cp, gives
     Ts = T0 + Qc/Cp + (Qg/Cp) (s - m)/(s + m),  s = sqrt(m^2 + C3),
     C3 = 4 kg Bg W^2 p^2 / (Cp R^2).

The C++ code (mpmice/SteadyBurn.cpp) solves for Ts by bisection on
Ts = F(Ts); this script eliminates Ts instead and solves g(m) = 0 for the
mass flux m with mpmath at 40 digits (a different unknown, a different
method), then compares with the HMX strand-burner data of
orderAccuracy/MPMICE/ExpData.dat.

Usage: wsb_burn_rate.py [EXPDATA]   (default ../shared/decks/orderAccuracy/MPMICE/ExpData.dat)
"""
import os
import sys

import mpmath as mp

mp.mp.dps = 40

# HMX constants of BurnRate.ups (DDT1) and SteadyBurn_2dRT.ups (Steady_Burn) = WSB's Table 1.
HMX = dict(R=8.314, Ac=1.637e15, Ec=1.76e5, Bg=1.6e-3, Qc=4.0e5, Qg=3.018e6, kg=0.07, kc=0.2, Cp=1.4e3, W=0.0342)
RHO_C = 1832.0  # BurnRate.ups PBX9501 density [kg/m^3]
T0 = 298.0      # BurnRate.ups initial solid temperature [K]


def surface_temperature(m, p, T0, q=HMX):
    C3 = 4 * q["kg"] * q["Bg"] * q["W"] ** 2 * p ** 2 / (q["Cp"] * q["R"] ** 2)
    s = mp.sqrt(m * m + C3)
    return T0 + q["Qc"] / q["Cp"] + q["Qg"] / q["Cp"] * (s - m) / (s + m)


def condensed_flux_squared(Ts, T0, rho_c, q=HMX):
    return (q["Ac"] * q["R"] * q["kc"] * rho_c * Ts ** 2 * mp.exp(-q["Ec"] / (q["R"] * Ts))
            / (q["Ec"] * (q["Cp"] * (Ts - T0) - q["Qc"] / 2)))


def wsb(p, T0=T0, rho_c=RHO_C, q=HMX):
    """Mass flux m [kg/(m^2 s)] and surface temperature Ts [K]."""
    p, T0, rho_c = mp.mpf(p), mp.mpf(T0), mp.mpf(rho_c)

    def g(m):
        return m * m - condensed_flux_squared(surface_temperature(m, p, T0, q), T0, rho_c, q)

    # g(0) < 0 (the condensed flux at Ts(0) = T0 + (Qc+Qg)/Cp is positive);
    # g(m) > 0 for m large (Ts -> T0 + Qc/Cp, the condensed flux stays bounded).
    lo, hi = mp.mpf(0), mp.mpf(1)
    while g(hi) <= 0:
        hi *= 2
    m = mp.findroot(g, (lo, hi), solver="anderson")
    return m, surface_temperature(m, p, T0, q)


def rate_mm_s(p, T0=T0):
    m, _ = wsb(p, T0)
    return float(m / RHO_C * 1e3)


def read_data(path):
    pts = []
    with open(path) as f:
        for line in f:
            if line.strip():
                a, b = line.split()
                pts.append((float(a), float(b)))
    return pts


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    path = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        here, "..", "..", "..", "shared", "decks", "orderAccuracy", "MPMICE", "ExpData.dat")
    print("WSB with the HMX constants of BurnRate.ups, rho_c = %g kg/m^3, T0 = %g K" % (RHO_C, T0))
    for p in (0.24e6, 4.83e6):
        m, Ts = wsb(p)
        print("p = %.3g Pa: m = %.10g kg/(m^2 s), Ts = %.10g K, r = %.6g mm/s" % (p, m, Ts, m / RHO_C * 1e3))
    if os.path.exists(path):
        print("\n   p [MPa]   data [mm/s]   WSB [mm/s]   WSB/data - 1")
        for p, r in read_data(path):
            w = rate_mm_s(p)
            print("%9.3f %12.4f %12.4f %+12.1f %%" % (p / 1e6, r * 1e3, w, 100 * (w / (r * 1e3) - 1)))
    # The bulk temperature that would bring the model to the 0.24 MPa data point.
    target = mp.mpf("0.955e-3") * RHO_C
    T = mp.findroot(lambda t: wsb(0.24e6, t)[0] - target, (300, 500), solver="anderson")
    print("\nT0 for 0.955 mm/s at 0.24 MPa: %.2f K (the deck's solid starts at %g K)" % (T, T0))
    # Local pressure exponent n = d ln r / d ln p.
    for p in (0.24e6, 1e6, 4.83e6, 20e6):
        h = mp.mpf("1e-6")
        n = (mp.log(wsb(p * (1 + h))[0]) - mp.log(wsb(p * (1 - h))[0])) / (mp.log(1 + h) - mp.log(1 - h))
        print("n = d ln r/d ln p at %.3g MPa: %.4f" % (p / 1e6, n))


if __name__ == "__main__":
    main()
