// The WSB steady burn rate (mpmice/SteadyBurn.h) with the HMX/PBX 9501
// constants of MPMICE/BurnRate.ups and SteadyBurn_2dRT.ups (DDT1 and
// Steady_Burn blocks: R 8.314, Ac 1.637e15, Ec 1.76e5, Bg 1.6e-3, Qc 4e5,
// Qg 3.018e6, kg 0.07, kc 0.2, Cp 1.4e3, W 0.0342), rho_c = 1832 kg/m^3
// (BurnRate.ups), T0 = 298 K (its initial temperature).
//
// Oracles: (1) the returned (m, Ts) solve both WSB equations (the residual
// Ts - F(Ts) vanishes and m is the condensed-phase flux at Ts, recomputed
// here from the formula); (2) the linear burn rate m/rho_c against the HMX
// strand-burner data of orderAccuracy/MPMICE/ExpData.dat (the issue's
// points: 0.955 mm/s at 0.24 MPa, 8.36 mm/s at 4.83 MPa), within 10 %.
// Measured: 0.669 mm/s at 0.24 MPa (-30 %), 8.23 mm/s at 4.83 MPa (-1.6 %).
// The low-pressure point misses the data by 30 %: that is the WSB model with
// these constants, not the solver. An independent solution
// (tests/bench/wsb_burn_rate.py: the gas-phase relation substituted into the
// condensed-phase one and solved for m with mpmath at 40 digits, a different
// unknown and method than the bisection on Ts here) gives m = 1.22501413
// kg/(m^2 s), Ts = 685.4051693 K at 0.24 MPa (r = 0.668676 mm/s), and
// m = 15.0747451, Ts = 820.9758842 K at 4.83 MPa; g(m) has one sign change
// on 1e-6 < m < 1e3 (one solution branch). The model would need a bulk
// temperature T0 = 357.7 K to give 0.955 mm/s at 0.24 MPa. So the test at
// 0.24 MPa checks the model value (oracle (3)), and the -30 % against the
// strand data is documented (docs/mpmice.md, "The WSB rate against the
// strand-burner data"), not asserted.
#include <gtest/gtest.h>

#include <cmath>

#include "mpmice/SteadyBurn.h"

namespace tephra {
namespace {

WsbParams hmx() {
  WsbParams q;
  q.R = 8.314;
  q.Ac = 1.637e15;
  q.Ec = 1.76e5;
  q.Bg = 1.6e-3;
  q.Qc = 4.0e5;
  q.Qg = 3.018e6;
  q.kg = 0.07;
  q.kc = 0.2;
  q.Cp = 1.4e3;
  q.W = 0.0342;
  return q;
}

constexpr double kRho = 1832.0, kT0 = 298.0;

TEST(WsbBurnRate, SolvesBothWsbEquations) {
  const WsbParams q = hmx();
  for (double p : {1e5, 0.24e6, 4.83e6, 1e8}) {
    const WsbState s = wsb_burn_rate(q, p, kT0, 1 / kRho);
    EXPECT_LT(std::abs(wsb_residual(q, p, kT0, 1 / kRho, s.surface_temperature)), 1e-8) << p;
    // m^2 = Ac R kc Ts^2 exp(-Ec/(R Ts)) / (Ec Cp vc (Ts - T0 - Qc/(2 Cp))).
    const double Ts = s.surface_temperature;
    const double m2 = q.Ac * q.R * q.kc * kRho * Ts * Ts * std::exp(-q.Ec / (q.R * Ts)) /
                      (q.Ec * q.Cp * (Ts - kT0 - q.Qc / (2 * q.Cp)));
    EXPECT_NEAR(s.mass_flux, std::sqrt(m2), 1e-12 * std::sqrt(m2));
    EXPECT_GT(Ts, kT0 + q.Qc / q.Cp);  // above C4
  }
  // The rate rises with pressure.
  EXPECT_LT(wsb_burn_rate(q, 1e6, kT0, 1 / kRho).mass_flux, wsb_burn_rate(q, 2e6, kT0, 1 / kRho).mass_flux);
}

TEST(WsbBurnRate, HmxStrandDataAt4p83MPa) {
  const double rate = wsb_burn_rate(hmx(), 4.83e6, kT0, 1 / kRho).mass_flux / kRho;
  EXPECT_NEAR(rate, 8.36e-3, 0.10 * 8.36e-3);
}

// Oracle (3): the independent mpmath solution of tests/bench/wsb_burn_rate.py
// (10 significant digits printed; the bisection stops at 1e-12 relative in Ts).
TEST(WsbBurnRate, MatchesTheIndependentSolutionAt0p24And4p83MPa) {
  const WsbState lo = wsb_burn_rate(hmx(), 0.24e6, kT0, 1 / kRho);
  EXPECT_NEAR(lo.mass_flux, 1.22501413, 1e-8 * 1.22501413);
  EXPECT_NEAR(lo.surface_temperature, 685.4051693, 1e-9 * 685.4);
  const WsbState hi = wsb_burn_rate(hmx(), 4.83e6, kT0, 1 / kRho);
  EXPECT_NEAR(hi.mass_flux, 15.0747451, 1e-8 * 15.0747451);
  EXPECT_NEAR(hi.surface_temperature, 820.9758842, 1e-9 * 821.0);
  // Against the strand data (0.955 mm/s): -30 %, outside the 10 %.
  // Recorded here so a change of the model shows up; not a pass criterion
  // for the data (docs/mpmice.md).
  const double rate = lo.mass_flux / kRho;
  EXPECT_NEAR(rate / 0.955e-3 - 1, -0.300, 0.001);
}

}  // namespace
}  // namespace tephra
