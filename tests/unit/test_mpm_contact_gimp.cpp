// Contact with the GIMP interpolator: the contact normals come from the mass
// gradient of the general (27-entry) stencils, and the phase-structured step
// must still conserve momentum.
//
// 1. Mass gradient from GIMP stencils (mpm/contact/ContactNormals.cpp):
//    sum_g grad S_gp = 0 for every particle whose support lies on the grid, so
//    sum_g g_g = 0 to round-off; on the node plane beyond a block's +x face
//    the gradient points out of the block (+x), on the plane beyond its -x
//    face it points -x; x_g = sum m_p x_p S_gp / m_g lies inside the block's
//    support.
// 2. Two blocks in free space, gimp interpolator (extraCells 1), A moving
//    towards B: with single_velocity and with friction contact the total
//    particle momentum is conserved to round-off (partition of unity of the
//    GIMP weights, sum_g grad S = 0, and contact's per-node equal and opposite
//    exchanges), and momentum actually reaches B.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/contact/ContactNormals.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

std::string box_material(double density, const Vec3& lo, const Vec3& hi, const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "<material><density>" << density << "</density><constitutive_model type='comp_neo_hook'><bulk_modulus>"
    << 1e4 * density << "</bulk_modulus><shear_modulus>" << 5e3 * density
    << "</shear_modulus></constitutive_model>"
    << "<thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
    << "<geom_object><box><min>[" << lo[0] << "," << lo[1] << "," << lo[2] << "]</min><max>[" << hi[0] << ","
    << hi[1] << "," << hi[2] << "]</max></box><res>[2,2,2]</res><velocity>[" << v[0] << "," << v[1] << "," << v[2]
    << "]</velocity><temperature>300</temperature></geom_object></material>";
  return s.str();
}

// Grid [0,0.8]x[0,0.4]x[0,0.05], 16x8x1 cells, one extra cell per side, gimp.
std::unique_ptr<MpmComponent> gimp_scene(const std::string& materials, const std::string& contact) {
  std::ostringstream s;
  s << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator><interpolator>gimp</interpolator>"
    << "</MPM><PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants><MaterialProperties><MPM>"
    << materials << contact << "</MPM></MaterialProperties><Grid><BoundaryConditions>"
    << "<Face side='z-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "<Face side='z+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "</BoundaryConditions><Level><Box><lower>[0,0,0]</lower><upper>[0.8,0.4,0.05]</upper>"
    << "<resolution>[16,8,1]</resolution><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches>"
    << "</Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "gimp_contact.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  return c;
}

struct Sums {
  Vec3 momentum = Vec3::Zero();
  double scale = 0;  // sum m |v|
};

Sums sums(const MpmMaterial& m) {
  Sums s;
  const Particles& p = m.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    s.momentum += p.mass[i] * p.v[i];
    s.scale += p.mass[i] * p.v[i].norm();
  }
  return s;
}

TEST(MpmContactGimp, MassGradientFromGimpStencilsPointsOutOfTheBody) {
  // Block [0.2,0.4]x[0.1,0.3]x[0,0.05]: cells of 0.05, so node planes x = 0.2 and 0.4 are its faces.
  auto c = gimp_scene(box_material(1e3, Vec3(0.2, 0.1, 0), Vec3(0.4, 0.3, 0.05), Vec3::Zero()), "");
  const MpmMaterial& m = c->materials()[0];
  ASSERT_EQ(m.stencils.width, stencil_width(InterpolatorKind::Gimp));
  ASSERT_EQ(m.stencils.particles(), m.particles.size());
  std::vector<Vec3> grad, pos;
  mass_gradient(m.particles, m.stencils, m.grid, grad);
  mass_weighted_position(m.particles, m.stencils, m.grid, pos);
  ASSERT_EQ(grad.size(), m.grid.count());

  double mass = 0;
  for (double mp : m.particles.mass) mass += mp;
  Vec3 total = Vec3::Zero();
  for (const Vec3& g : grad) total += g;
  EXPECT_LT(total.norm(), 1e-12 * mass / m.grid.h[0]) << total.transpose();

  // Node planes just past the faces (GIMP half-width 1/4 cell: particles at
  // 1/4 cell from a face reach the node plane of the face only; the plane of
  // the face itself has mass on both sides of its support) and the face
  // planes: at y, z inside the block the gradient points out along x.
  const NodeGrid& g = m.grid;
  const int i_lo = g.extra[0] + 4, i_hi = g.extra[0] + 8;  // x = 0.2, 0.4
  int checked = 0;
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = g.extra[1] + 3; j <= g.extra[1] + 5; ++j) {  // y = 0.15 .. 0.25
      const std::size_t lo = g.index(i_lo, j, k), hi = g.index(i_hi, j, k);
      if (g.mass[lo] <= 0 || g.mass[hi] <= 0) continue;
      EXPECT_LT(grad[lo][0], 0.0) << "node " << i_lo << "," << j << "," << k;
      EXPECT_GT(grad[hi][0], 0.0) << "node " << i_hi << "," << j << "," << k;
      EXPECT_GT(std::abs(grad[hi][0]), 10 * std::abs(grad[hi][1])) << "normal not along x";
      ++checked;
    }
  EXPECT_GT(checked, 0);

  // x_g lies within the particles' reach of node g (half a cell past the
  // particle centres, plus the GIMP half-width).
  for (std::size_t n = 0; n < g.count(); ++n) {
    if (g.mass[n] <= 0) continue;
    EXPECT_GE(pos[n][0], 0.2 - 1e-12);
    EXPECT_LE(pos[n][0], 0.4 + 1e-12);
    EXPECT_GE(pos[n][1], 0.1 - 1e-12);
    EXPECT_LE(pos[n][1], 0.3 + 1e-12);
  }
}

// A (light) moves towards B (heavy, at rest); returns (|P - P0| / sum m|v|_0, |P_B|).
std::pair<double, double> gimp_impact(const std::string& contact, const Vec3& va) {
  const std::string mats = box_material(1e3, Vec3(0.125, 0.1, 0), Vec3(0.325, 0.275, 0.05), va) +
                           box_material(2e3, Vec3(0.35, 0.05, 0), Vec3(0.55, 0.35, 0.05), Vec3::Zero());
  auto c = gimp_scene(mats, contact);
  const Sums a0 = sums(c->materials()[0]), b0 = sums(c->materials()[1]);
  double t = 0;
  int step = 0;
  const double T = 0.06;
  while (t < T - 1e-15) {
    const double dt = std::min(0.4 * c->stable_timestep(), T - t);
    c->advance(t, dt, ++step);
    t += dt;
  }
  const Sums a = sums(c->materials()[0]), b = sums(c->materials()[1]);
  const Vec3 dP = (a.momentum + b.momentum) - (a0.momentum + b0.momentum);
  return {dP.norm() / (a0.scale + b0.scale), b.momentum.norm()};
}

TEST(MpmContactGimp, ClosedSystemsConserveMomentumToRoundOff) {
  const double pa = 1e3 * 0.2 * 0.175 * 0.05;  // mass of A
  const auto [single_error, single_transfer] =
      gimp_impact("<contact><type>single_velocity</type></contact>", Vec3(0.5, 0.0, 0.0));
  const Vec3 va(0.5, 0.3, 0.0);
  const auto [friction_error, friction_transfer] =
      gimp_impact("<contact><type>friction</type><mu>0.3</mu></contact>", va);
  std::printf("gimp: single_velocity |dP|/sum m|v| = %.3g, to B %.3g; friction %.3g, to B %.3g\n", single_error,
              single_transfer, friction_error, friction_transfer);
  EXPECT_LT(single_error, 1e-13);
  EXPECT_GT(single_transfer, 0.05 * pa * 0.5) << "no momentum reached B";
  EXPECT_LT(friction_error, 1e-13);
  EXPECT_GT(friction_transfer, 0.05 * pa * va.norm()) << "no momentum reached B";
}

}  // namespace
}  // namespace tephra
