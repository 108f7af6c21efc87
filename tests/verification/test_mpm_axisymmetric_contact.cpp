// Axisymmetric contact (mpm/contact with the axisymmetric stencils: the
// normals are the in-plane mass gradients, mpm/contact/ContactNormals.cpp).
//
// Two coaxial rods of radius R = 0.5 m stacked along the axis, confined
// radially (symmetry face at r = R: u_r = 0, so the state is uniaxial strain
// and the hoop terms vanish), same hypoelastic material K = 6 MPa, G = 3 MPa,
// rho = 1000: rod A (0.125 <= z <= 0.5) moves at v = 1 m/s towards rod B
// (0.5 <= z <= 1.0) at rest. Separate materials in contact (single_velocity
// or friction, mu = 0.3).
//  - Axial momentum per radian sum m_p v_z is conserved to round-off: the
//    contact corrections are equal and opposite at each node and the internal
//    force sums to zero over the nodes (sum_g dS/dr = sum_g dS/dz = 0).
//  - Equal impedances: the interface moves at v/2 and the stress behind both
//    fronts is sigma_zz = -rho c_p v / 2, c_p = sqrt((K + 4G/3)/rho) = 100
//    m/s, until the fronts reach the far ends (0.375/c_p = 3.75 ms for A).
//    Checked at t = 2 ms on the particles within 0.1 m of the interface
//    (both fronts have run 0.2 m): mean sigma_zz within 3 % of rho c_p v / 2.
//  - The hoop velocity component (the grid's third direction) stays exactly
//    zero: the normals have no hoop part (without the in-plane mass gradient
//    the hoop factor S / r_p would enter the normal and the exchange would
//    set the particles spinning). The radial velocity is not zero: the
//    particle quadrature of the radial equilibrium (sigma_rr = sigma_thth
//    behind the fronts) is not exact; its largest value is printed.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

std::string contact_deck(const std::string& interp, const std::string& contact, double h) {
  std::ostringstream s;
  s.precision(17);
  auto material = [&](double z0, double z1, double v) {
    std::ostringstream m;
    m.precision(17);
    m << "<material><density>1000</density><thermal_conductivity>1</thermal_conductivity><specific_heat>1"
      << "</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e6</K><G>3e6</G></constitutive_model>"
      << "<geom_object><box label=\"rod" << (v > 0 ? "A" : "B") << "\"><min>[0," << z0 << ",0]</min><max>[0.5," << z1 << "," << h
      << "]</max></box><res>[2,2,1]</res><velocity>[0," << v << ",0]</velocity><temperature>300</temperature>"
      << "</geom_object></material>";
    return m.str();
  };
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator><axisymmetric>true</axisymmetric></MPM>"
    << "<MaterialProperties><MPM>" << material(0.125, 0.5, 1.0) << material(0.5, 1.0, 0.0) << "<contact><type>"
    << contact << "</type>" << (contact == "friction" ? "<mu>0.3</mu>" : "") << "<materials>[0,1]</materials>"
    << "</contact></MPM></MaterialProperties><Grid><BoundaryConditions>";
  for (const char* f : {"x-", "x+"})
    s << "<Face side=\"" << f << "\"><BCType id=\"all\" var=\"symmetry\" label=\"Symmetric\"></BCType></Face>";
  s << "</BoundaryConditions><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[0.5,1.125," << h
    << "]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box><spacing>[" << h << "," << h << ","
    << h << "]</spacing></Level></Grid></Uintah_specification>";
  return s.str();
}

struct Case {
  const char* interp;
  const char* contact;
};

class AxisymmetricContact : public ::testing::TestWithParam<Case> {};

TEST_P(AxisymmetricContact, CoaxialRodsConserveAxialMomentum) {
  set_thread_count(1);
  const double h = 1.0 / 32, v = 1.0, rho = 1000, cp = 100;
  auto deck = load_deck_from_string(contact_deck(GetParam().interp, GetParam().contact, h), "axi_contact.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  auto momentum = [&] {
    double pz = 0, vr = 0, vth = 0;
    for (const auto& m : c->materials())
      for (std::size_t i = 0; i < m.particles.size(); ++i) {
        pz += m.particles.mass[i] * m.particles.v[i][1];
        vr = std::max(vr, std::abs(m.particles.v[i][0]));
        vth = std::max(vth, std::abs(m.particles.v[i][2]));
      }
    return std::array<double, 3>{pz, vr, vth};
  };
  const double p0 = momentum()[0];
  const double t_end = 2e-3;
  double t = 0, worst_p = 0, worst_vr = 0, worst_vth = 0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.3 * c->stable_timestep(), t_end - t);
    c->advance(t, dt, ++step);
    t += dt;
    const auto m = momentum();
    worst_p = std::max(worst_p, std::abs(m[0] - p0) / std::abs(p0));
    worst_vr = std::max(worst_vr, m[1]);
    worst_vth = std::max(worst_vth, m[2]);
  }
  double s = 0;
  int n = 0;
  for (const auto& m : c->materials())
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
      const double z = m.particles.x[i][1];
      if (std::abs(z - 0.5) > 0.1) continue;
      s += m.particles.stress[i](1, 1);
      ++n;
    }
  s /= n;
  const double exact = -rho * cp * v / 2;
  std::printf("%s %s axisymmetric coaxial rods (%d steps): max |P_z - P_z0| / P_z0 = %.2e, max |v_r| = %.2e m/s, max |v_hoop| = %.1e, "
              "mean sigma_zz near the interface %.2f Pa vs -rho c v / 2 = %.2f Pa (%.2f %%)\n",
              GetParam().interp, GetParam().contact, step, worst_p, worst_vr, worst_vth, s, exact, 100 * (s / exact - 1));
  EXPECT_LT(worst_p, 1e-13);
  EXPECT_EQ(worst_vth, 0.0);
  EXPECT_NEAR(s / exact, 1.0, 0.03);
}

// gimp with friction (mu = 0.3): until session 16 this drifted the axial
// momentum by 1.5e-8 relative over 22 steps (|v_r| up to 0.07 m/s; the rim
// particles then reach the extra-node layer beyond the symmetry face r = R).
// On the session-17 main it conserves it to 2.3e-15 (the extra nodes carry
// 1.5e-8 of mass by step 22): the momentum a node change moves is m_g Delta v
// with the folded mass (the symmetry fold and the BC order of session 16, not
// bisected further). The bound 1e-13: each step's node sums and G2P round
// about 100 terms of size |P| at u = 1.1e-16, over 22 steps < 22*100*u = 2.4e-13
// in the worst case, 1e-13 in practice with margin 40 over the measured value.
INSTANTIATE_TEST_SUITE_P(Interpolators, AxisymmetricContact,
                         ::testing::Values(Case{"linear", "single_velocity"}, Case{"linear", "friction"},
                                           Case{"gimp", "single_velocity"}, Case{"cpdi", "single_velocity"}, Case{"gimp", "friction"}),
                         [](const auto& info) {
                           return std::string(info.param.interp) + "_" + info.param.contact;
                         });

}  // namespace
}  // namespace tephra
