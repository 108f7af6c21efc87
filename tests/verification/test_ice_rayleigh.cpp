// Viscous ICE: Stokes' first problem (Rayleigh), Vaango's
// orderAccuracy/ICE/rayleigh.ups. Air at rest (mu = 1e-4 Pa s, rho =
// 1.17929 kg/m^3) above the wall y = 0, which moves at U = 10 m/s in x from
// t = 0 (Dirichlet velocity on y-). The flow is uniform in x, so div u = 0,
// the pressure stays uniform and the x momentum obeys u_t = nu u_yy exactly,
// nu = mu/rho. Exact solution (semi-infinite fluid):
//   u(y, t) = U erfc(y / (2 sqrt(nu t))).
// Test edits: x is made non-periodic with zero-gradient (Neumann) faces (ICE
// has no periodic grids yet; for an x-uniform field this is equivalent), one
// cell in x, the height cut to 2 mm (the boundary layer 2 sqrt(nu t) is
// 0.26 mm at t = 0.2 ms, erfc < 1e-7 at the top), and the implicit-solver
// and time-step-control blocks removed (explicit ICE). The L1 error over the
// cells at t = 0.2 ms falls at the observed order asserted below.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

#include "core/grid/Loop.h"
#include "tests/support/IceRuns.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

std::string rayleigh_deck(int ny) {
  std::ifstream in(test::shared_dir() + "/decks/orderAccuracy/ICE/rayleigh.ups");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  auto replace = [&](const std::string& re, const std::string& by) {
    const std::string before = s;
    s = std::regex_replace(s, std::regex(re), by);
    if (s == before) throw std::runtime_error("rayleigh.ups edit did not apply: " + re);
  };
  replace(R"(<periodic>\s*\[1,0,0\]\s*</periodic>)", "");
  replace(R"(<extraCells>\s*\[0,1,1\]\s*</extraCells>)", "<extraCells>[1,1,1]</extraCells>");
  replace(R"(<resolution>\s*\[10,100,1\]\s*</resolution>)", "<resolution>[1," + std::to_string(ny) + ",1]</resolution>");
  replace(R"(<upper>\s*\[0.01,0.01,0.01\]\s*</upper>)", "<upper>[0.01,0.002,0.01]</upper>");
  replace(R"(<TimestepControl>[\s\S]*</TimestepControl>)", "");
  replace(R"(<ImplicitSolver>[\s\S]*</ImplicitSolver>)", "");
  std::string xfaces;
  for (const char* side : {"x-", "x+"})
    xfaces += std::string("<Face side=\"") + side +
              "\">"
              "<BCType id=\"0\" label=\"Pressure\" var=\"Neumann\"><value>0</value></BCType>"
              "<BCType id=\"0\" label=\"Velocity\" var=\"Neumann\"><value>[0,0,0]</value></BCType>"
              "<BCType id=\"0\" label=\"Temperature\" var=\"Neumann\"><value>0</value></BCType>"
              "<BCType id=\"0\" label=\"Density\" var=\"Neumann\"><value>0</value></BCType>"
              "<BCType id=\"0\" label=\"SpecificVol\" var=\"computeFromDensity\"><value>0</value></BCType>"
              "</Face>";
  replace(R"(<Face side = "y-">)", xfaces + "<Face side = \"y-\">");
  return s;
}

struct RayleighResult {
  double l1 = 0, max_v = 0, max_dp = 0;
  int steps = 0;
};

RayleighResult run_rayleigh(int ny, double t_end) {
  test::IceRun r;
  r.deck = load_deck_from_string(rayleigh_deck(ny), "rayleigh.ups", test::shared_dir() + "/decks/orderAccuracy/ICE");
  r.ice = make_ice_component(*r.deck);
  r.ice->initialize();
  test::run_to(r, t_end);
  const double mu = 1e-4, rho0 = 1.1792946927374306, U = 10.0;
  const double nu = mu / rho0, delta = 2.0 * std::sqrt(nu * r.time);
  const Grid& g = r.ice->grid();
  RayleighResult out;
  out.steps = r.steps;
  const auto& u = r.ice->fields()[0].vel_CC[0];
  const auto& p = r.ice->press_CC()[0];
  const double p0 = p(0, 0, 0);
  for (int j = 0; j < g.cells[1]; ++j) {
    const double y = (j + 0.5) * g.dx[1];
    out.l1 += std::abs(u(0, j, 0)[0] - U * std::erfc(y / delta)) * g.dx[1];
    out.max_v = std::max(out.max_v, std::abs(u(0, j, 0)[1]));
    out.max_dp = std::max(out.max_dp, std::abs(p(0, j, 0) - p0));
  }
  out.l1 /= U * delta;  // relative to the boundary-layer "area" U * delta
  return out;
}

TEST(IceRayleigh, ViscousBoundaryLayerConvergesToErfc) {
  set_thread_count(1);
  const double t_end = 2e-4;
  const int n[3] = {20, 40, 80};
  double e[3];
  for (int i = 0; i < 3; ++i) {
    const RayleighResult r = run_rayleigh(n[i], t_end);
    e[i] = r.l1;
    std::printf("Rayleigh ny=%d steps=%d L1/(U delta)=%.4e max|v|=%.2e max|dp|=%.2e\n", n[i], r.steps, r.l1, r.max_v,
                r.max_dp);
    // x-uniform shear flow: no transverse velocity, no pressure change.
    EXPECT_LT(r.max_v, 1e-9);
    EXPECT_LT(r.max_dp, 1e-6);
  }
  const double order1 = std::log2(e[0] / e[1]), order2 = std::log2(e[1] / e[2]);
  std::printf("Rayleigh observed orders %.3f %.3f\n", order1, order2);
  EXPECT_LT(e[2], 0.01);
  EXPECT_GT(order2, 1.8);
}

}  // namespace
}  // namespace tephra
