// Contact on a periodic grid (mpm/PeriodicGrid.h: the mass gradients summed
// over the node aliases, contact positions folded as offsets; every alias of
// a node sees the same m, v, normal, so the node-wise exchange agrees).
//
// A bar in uniaxial strain (periodic in y and z, one cell), two blocks of
// separate materials: A (0.625 <= x <= 0.9375) at v = +0.5 m/s, B
// (0 <= x <= 0.3125) at rest, same hypoelastic material (K = 6 kPa,
// G = 3 kPa, rho = 1000: c = 3.16 m/s). With x periodic (L = 1) A hits B
// across the periodic face x = 1 = 0 at t = 0.125 s; the run goes to t = 0.4 s.
// Reference: the same scene with A shifted by -L/2 and B by +L/2 (whole
// cells; the same positions modulo L) on a grid that is not periodic in x,
// so the collision happens in the middle, far from any face. Checked:
//  - every particle's position (minus the shift, wrapped) and velocity equal
//    the reference's to round-off (<= 1e-12 m, 1e-12 m/s);
//  - total x momentum conserved to round-off in the periodic run;
//  - the collision happened: B carries more than 30 % of the momentum at the end.
// friction_LR (linear and gimp) gathers each node's point cloud over its
// periodic aliases, positions relative to the alias each particle weights
// (mpm/contact/FrictionLRContact.cpp), so it takes the same path.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kH = 1.0 / 16;

// shift_a, shift_b: the blocks' shifts (the reference moves A by -L/2 and B
// by +L/2, the same positions modulo L).
std::string contact_deck(const std::string& interp, const std::string& contact, double shift_a, double shift_b,
                         bool periodic_x) {
  std::ostringstream s;
  s.precision(17);
  auto material = [&](double x0, double x1, double v, double shift) {
    std::ostringstream m;
    m.precision(17);
    m << "<material><density>1000</density><thermal_conductivity>1</thermal_conductivity><specific_heat>1"
      << "</specific_heat><constitutive_model type=\"hypo_elastic\"><K>6e3</K><G>3e3</G></constitutive_model>"
      << "<geom_object><box label=\"block" << (v > 0 ? "A" : "B") << "\"><min>[" << x0 + shift << ",0,0]</min><max>[" << x1 + shift << "," << kH << ","
      << kH << "]</max></box><res>[2,1,1]</res><velocity>[" << v << ",0,0]</velocity><temperature>300</temperature>"
      << "</geom_object></material>";
    return m.str();
  };
  s << "<Uintah_specification><SimulationComponent type=\"mpm\"/>"
    << "<MPM><interpolator>" << interp << "</interpolator></MPM>"
    << "<MaterialProperties><MPM>" << material(0.625, 0.9375, 0.5, shift_a) << material(0.0, 0.3125, 0.0, shift_b) << "<contact><type>"
    << contact << "</type>" << (contact == "friction" || contact == "approach" || contact == "friction_LR" ? "<mu>0.3</mu>" : "")
    << (contact == "friction_bard" ? "<mu>0.3</mu><separation_factor>0.9</separation_factor>" : "") << "<materials>[0,1]</materials>"
    << "</contact></MPM></MaterialProperties><Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[1," << kH
    << "," << kH << "]</upper><extraCells>[" << (periodic_x ? 0 : 1) << ",0,0]</extraCells><patches>[1,1,1]</patches>"
    << "</Box><spacing>[" << kH << "," << kH << "," << kH << "]</spacing><periodic>[" << (periodic_x ? 1 : 0)
    << ",1,1]</periodic></Level></Grid></Uintah_specification>";
  return s.str();
}

struct Case {
  const char* interp;
  const char* contact;
};

class PeriodicContact : public ::testing::TestWithParam<Case> {};

TEST_P(PeriodicContact, CollisionAcrossTheSeamEqualsTheUnwrappedOne) {
  set_thread_count(1);
  const double dt = 4e-3, t_end = 0.4;
  const int n = int(std::lround(t_end / dt));
  auto seam = make_mpm_component(*load_deck_from_string(
      contact_deck(GetParam().interp, GetParam().contact, 0.0, 0.0, true), "seam.ups", "."));
  auto middle = make_mpm_component(*load_deck_from_string(
      contact_deck(GetParam().interp, GetParam().contact, -0.5, 0.5, false), "middle.ups", "."));
  seam->initialize();
  middle->initialize();
  ASSERT_LT(dt, 0.5 * seam->stable_timestep());
  auto momentum = [](MpmComponent& c, int mat) {
    double px = 0;
    for (std::size_t m = 0; m < c.materials().size(); ++m) {
      if (mat >= 0 && int(m) != mat) continue;
      const Particles& p = c.materials()[m].particles;
      for (std::size_t i = 0; i < p.size(); ++i) px += p.mass[i] * p.v[i][0];
    }
    return px;
  };
  const double P0 = momentum(*seam, -1);
  double worst_P = 0;
  for (int step = 1; step <= n; ++step) {
    seam->advance((step - 1) * dt, dt, step);
    middle->advance((step - 1) * dt, dt, step);
    worst_P = std::max(worst_P, std::abs(momentum(*seam, -1) - P0) / P0);
  }
  double worst_x = 0, worst_v = 0;
  for (std::size_t m = 0; m < 2; ++m) {
    const Particles& a = seam->materials()[m].particles;
    const Particles& b = middle->materials()[m].particles;
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
      double dx = a.x[i][0] - (b.x[i][0] - 0.5);
      dx -= std::round(dx);  // positions modulo L = 1
      worst_x = std::max(worst_x, std::abs(dx));
      worst_v = std::max(worst_v, (a.v[i] - b.v[i]).norm());
    }
  }
  const double PB = momentum(*seam, 1);
  std::printf("%s %s periodic contact across the seam (%d steps): max |x - x_ref| = %.2e m, max |v - v_ref| = "
              "%.2e m/s, max |P - P0|/P0 = %.2e, B's share of the momentum %.3f\n",
              GetParam().interp, GetParam().contact, n, worst_x, worst_v, worst_P, PB / P0);
  EXPECT_LT(worst_x, 1e-12);
  EXPECT_LT(worst_v, 1e-12);
  EXPECT_LT(worst_P, 1e-13);
  EXPECT_GT(PB / P0, 0.3);
}

INSTANTIATE_TEST_SUITE_P(Interpolators, PeriodicContact,
                         ::testing::Values(Case{"linear", "single_velocity"}, Case{"gimp", "friction"},
                                           Case{"cpdi", "friction_bard"}, Case{"3rdorderBS", "approach"},
                                           Case{"linear", "friction_LR"}, Case{"gimp", "friction_LR"}),
                         [](const auto& info) {
                           return std::string(info.param.interp) + "_" + info.param.contact;
                         });

}  // namespace
}  // namespace tephra
