// Multi-material MPM with contact: scenes built in the test, run in-process.
//
// 1. Block on an inclined plane. A heavy elastic slab (material 0, rho = 1e4,
//    held by zero-velocity nodes on z- for material 0 only) and a block on it
//    (material 1, rho = 1e3); gravity tilted by theta = 0.3 rad:
//    b = g (sin theta, 0, -cos theta), g = 10. Friction contact.
//    * mu = 0: the contact normal at the interface nodes is the slab's (its
//      mass gradient is the larger one, Vaango's rule), i.e. exactly +z, so a
//      frictionless exchange changes no x momentum; sum f_int,x over the nodes
//      of one body is 0 (partition of unity), hence the block's x momentum
//      grows by M g sin(theta) dt per step, as long as the slab's surface stays
//      flat. It does not quite: the block indents the slab by ~rho g H / E
//      ~ 1e-5 of a cell, which tilts the slab's mass gradient at the interface
//      nodes by a comparable angle, and a frictionless normal tilted by eps
//      moves a fraction ~eps of the normal impulse into x. Tolerance 1e-7
//      relative (observed 1.8e-9 with the P2G-referenced acceleration).
//    * mu = 0.5 > tan(theta) = 0.309: the block sticks. The interface nodes
//      stick; the block's interior only flexes elastically, so its mean
//      velocity stays a small fraction of the frictionless g sin(theta) t.
//      Bound: |u_x| < 1e-3 g sin(theta) T (observed 1.6e-4).
// 2. Friction heating (<do_contact_friction_heating>): a block slides on the
//    held slab under gravity g (straight down) with friction mu, from u0.
//    The normal force is the weight N = M g (on average over the block's
//    elastic bounce), so the block decelerates at mu g and the heat is the
//    friction force times the slip distance, Q = mu M g d, d the block's
//    displacement; the kinetic energy it loses, M (u0^2 - u^2)/2 = mu M g d
//    as well. Measured in the test's output; tolerances stated there.
// 3. Closed systems (no gravity, no wall reached): total momentum is conserved
//    to round-off with friction contact (oblique impact, mu = 0.3) and with
//    single_velocity (head-on impact), and momentum is actually transferred.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

std::string box_material(double density, double K, double G, const Vec3& lo, const Vec3& hi, const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "<material><density>" << density << "</density><constitutive_model type='comp_neo_hook'><bulk_modulus>" << K
    << "</bulk_modulus><shear_modulus>" << G << "</shear_modulus></constitutive_model>"
    << "<thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
    << "<geom_object><box><min>[" << lo[0] << "," << lo[1] << "," << lo[2] << "]</min><max>[" << hi[0] << ","
    << hi[1] << "," << hi[2] << "]</max></box><res>[2,2,2]</res><velocity>[" << v[0] << "," << v[1] << "," << v[2]
    << "]</velocity><temperature>300</temperature></geom_object></material>";
  return s.str();
}

std::unique_ptr<MpmComponent> scene(const std::string& materials, const std::string& contact, const Vec3& gravity,
                                    const Vec3& upper, const IntVec3& cells, const std::string& bcs,
                                    const std::string& flags = "") {
  std::ostringstream s;
  s.precision(17);
  s << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator>" << flags << "</MPM>"
    << "<PhysicalConstants><gravity>[" << gravity[0] << "," << gravity[1] << "," << gravity[2]
    << "]</gravity></PhysicalConstants><MaterialProperties><MPM>" << materials << contact
    << "</MPM></MaterialProperties><Grid><BoundaryConditions>" << bcs << "</BoundaryConditions><Level><Box>"
    << "<lower>[0,0,0]</lower><upper>[" << upper[0] << "," << upper[1] << "," << upper[2] << "]</upper>"
    << "<resolution>[" << cells[0] << "," << cells[1] << "," << cells[2] << "]</resolution>"
    << "<extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "scene.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  return c;
}

struct Sums {
  double mass = 0;
  Vec3 momentum = Vec3::Zero();
  double scale = 0;  // sum m |v|
};

Sums sums(const MpmMaterial& m) {
  Sums s;
  const Particles& p = m.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    s.mass += p.mass[i];
    s.momentum += p.mass[i] * p.v[i];
    s.scale += p.mass[i] * p.v[i].norm();
  }
  return s;
}

// Runs to time T with dt = 0.4 * the stable step; returns the time reached.
double run(MpmComponent& c, double T) {
  double t = 0;
  int step = 0;
  while (t < T - 1e-15) {
    const double dt = std::min(0.4 * c.stable_timestep(), T - t);
    c.advance(t, dt, ++step);
    t += dt;
  }
  return t;
}

const double kTheta = 0.3, kG = 10.0;

std::unique_ptr<MpmComponent> inclined_plane(double mu, const std::string& type = "friction") {
  const double h = 0.025;
  const std::string mats = box_material(1e4, 1e8, 5e7, Vec3(0, 0, 0), Vec3(0.4, h, h), Vec3::Zero()) +
                           box_material(1e3, 1e7, 5e6, Vec3(0.1, 0, h), Vec3(0.2, h, 3 * h), Vec3::Zero());
  std::ostringstream contact;
  contact << "<contact><type>" << type << "</type><mu>" << mu << "</mu><materials>[0,1]</materials></contact>";
  const std::string bcs =
      "<Face side='z-'><BCType id='0' var='Dirichlet' label='Velocity'><value>[0,0,0]</value></BCType></Face>"
      "<Face side='y-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
      "<Face side='y+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>";
  return scene(mats, contact.str(), kG * Vec3(std::sin(kTheta), 0, -std::cos(kTheta)), Vec3(0.4, h, 4 * h),
               IntVec3(16, 1, 4), bcs);
}

TEST(MpmContact, FrictionlessBlockSlidesDownTheInclineAtGSinTheta) {
  auto c = inclined_plane(0.0);
  const double T = run(*c, 0.05);
  const Sums b = sums(c->materials()[1]);
  const double u_exact = kG * std::sin(kTheta) * T;
  const Vec3 u = b.momentum / b.mass;
  std::printf("mu = 0: u_x = %.12g, g sin(theta) t = %.12g, u_z = %.3g\n", u[0], u_exact, u[2]);
  EXPECT_NEAR(u[0], u_exact, 1e-7 * u_exact) << "u_x = " << u[0] << ", g sin(theta) t = " << u_exact;
  // Held by the slab: no fall (free fall would give g cos(theta) T = 0.48 m/s).
  EXPECT_LT(std::abs(u[2]), 0.05 * kG * std::cos(kTheta) * T) << "u_z = " << u[2];
}

TEST(MpmContact, BlockSticksWhenMuExceedsTanTheta) {
  ASSERT_GT(0.5, std::tan(kTheta));
  auto c = inclined_plane(0.5);
  const double T = run(*c, 0.05);
  const Sums b = sums(c->materials()[1]);
  const Vec3 u = b.momentum / b.mass;
  std::printf("mu = 0.5: u = (%.3g, %.3g, %.3g), g sin(theta) T = %.3g\n", u[0], u[1], u[2],
              kG * std::sin(kTheta) * T);
  // Observed 1.6e-4 of g sin(theta) T (1.2e-2 before session 18's mirrored
  // normals at the symmetry faces); the same bound as friction_LR.
  EXPECT_LT(std::abs(u[0]), 1e-3 * kG * std::sin(kTheta) * T) << "u_x = " << u[0];
  EXPECT_LT(std::abs(u[2]), 0.05 * kG * std::cos(kTheta) * T) << "u_z = " << u[2];
}

// friction_LR (logistic-regression separation, Nairn et al. 2020): the same
// two oracles on the same incline. Frictionless, the block reaches
// u_x = 0.14622 against g sin(theta) T = 0.14776 (1.04% low), not to
// round-off as with friction's grid normal: at the interface nodes near the
// block's two ends the point cloud is a corner (slab particles on both sides
// in x, block particles on one), and the regression plane there tilts from
// the slab's surface, so a frictionless normal exchange there also takes x
// momentum (a likely cause, not isolated further). Bound: 2%, and below the
// exact value (contact must not accelerate the block). Sticking is tighter
// than with friction: |u_x| = 2.3e-5 against 1.7e-3.
TEST(MpmContact, FrictionLRFrictionlessBlockSlidesAtGSinTheta) {
  auto c = inclined_plane(0.0, "friction_LR");
  const double T = run(*c, 0.05);
  const Sums b = sums(c->materials()[1]);
  const double u_exact = kG * std::sin(kTheta) * T;
  const Vec3 u = b.momentum / b.mass;
  std::printf("friction_LR mu = 0: u_x = %.12g, g sin(theta) t = %.12g, u_z = %.3g\n", u[0], u_exact, u[2]);
  EXPECT_NEAR(u[0], u_exact, 0.02 * u_exact);
  EXPECT_LT(u[0], u_exact);
  EXPECT_LT(std::abs(u[2]), 0.05 * kG * std::cos(kTheta) * T) << "u_z = " << u[2];
}

TEST(MpmContact, FrictionLRBlockSticksWhenMuExceedsTanTheta) {
  auto c = inclined_plane(0.5, "friction_LR");
  const double T = run(*c, 0.05);
  const Sums b = sums(c->materials()[1]);
  const Vec3 u = b.momentum / b.mass;
  std::printf("friction_LR mu = 0.5: u = (%.3g, %.3g, %.3g), g sin(theta) T = %.3g\n", u[0], u[1], u[2],
              kG * std::sin(kTheta) * T);
  EXPECT_LT(std::abs(u[0]), 1e-3 * kG * std::sin(kTheta) * T) << "u_x = " << u[0];  // observed 1.5e-4 of it
  EXPECT_LT(std::abs(u[2]), 0.05 * kG * std::cos(kTheta) * T) << "u_z = " << u[2];
}

struct Slide {
  double heat = 0;       // sum over both bodies of m c_v (T - T0) [J]
  double distance = 0;   // block's mass-weighted x displacement [m]
  double ke_lost = 0;    // block's kinetic energy lost [J]
  double mass = 0, u = 0;
};

Slide slide(const std::string& type, double mu, double u0, double T) {
  const double h = 0.025;
  const std::string mats = box_material(1e4, 1e8, 5e7, Vec3(0, 0, 0), Vec3(0.4, h, h), Vec3::Zero()) +
                           box_material(1e3, 1e7, 5e6, Vec3(0.05, 0, h), Vec3(0.15, h, 3 * h), Vec3(u0, 0, 0));
  std::ostringstream contact;
  contact << "<contact><type>" << type << "</type><mu>" << mu << "</mu><materials>[0,1]</materials></contact>";
  const std::string bcs =
      "<Face side='z-'><BCType id='0' var='Dirichlet' label='Velocity'><value>[0,0,0]</value></BCType></Face>"
      "<Face side='y-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
      "<Face side='y+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>";
  auto c = scene(mats, contact.str(), Vec3(0, 0, -kG), Vec3(0.4, h, 4 * h), IntVec3(16, 1, 4), bcs,
                 "<do_contact_friction_heating>true</do_contact_friction_heating>");
  auto thermal = [&] {
    double e = 0;
    for (const MpmMaterial& m : c->materials())
      for (std::size_t i = 0; i < m.particles.size(); ++i) e += m.particles.mass[i] * m.specific_heat * m.particles.temperature[i];
    return e;
  };
  auto block = [&](double& ke) {
    const Particles& p = c->materials()[1].particles;
    double mx = 0, m = 0;
    ke = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      mx += p.mass[i] * p.x[i][0];
      m += p.mass[i];
      ke += 0.5 * p.mass[i] * p.v[i].squaredNorm();
    }
    return mx / m;
  };
  Slide r;
  const double E0 = thermal();
  double ke0 = 0, ke1 = 0;
  const double x0 = block(ke0);
  run(*c, T);
  r.heat = thermal() - E0;
  r.distance = block(ke1) - x0;
  r.ke_lost = ke0 - ke1;
  r.mass = sums(c->materials()[1]).mass;
  r.u = sums(c->materials()[1]).momentum[0] / r.mass;
  return r;
}

TEST(MpmContact, FrictionHeatIsMuWeightTimesSlipDistance) {
  const double mu = 0.3, u0 = 1.0, T = 0.05;
  for (const std::string type : {"friction", "friction_LR"}) {
    const Slide s = slide(type, mu, u0, T);
    const double Q = mu * s.mass * kG * s.distance;  // friction force times slip distance
    std::printf("%s: heat %.6g J, mu M g d = %.6g J (d = %.6g m, exact %.6g), KE lost %.6g J, u = %.6g (exact %.6g)\n",
                type.c_str(), s.heat, Q, s.distance, u0 * T - 0.5 * mu * kG * T * T, s.ke_lost, s.u,
                u0 - mu * kG * T);
    // Energy balance: the heat is the kinetic energy lost but the terms the
    // heat leaves out (J_t^2/(2 m_eff) per exchange, O(dt); the inelastic
    // normal part of the block's elastic bounce; strain energy). Measured:
    // friction 0.04 % (0.13 % before session 18), friction_LR 2.5 %; bound 3 %.
    EXPECT_NEAR(s.ke_lost, s.heat, 0.03 * s.heat) << type;
    // heat = mu N d with N = M g: friction_LR 2.2 % (bound 3 %); friction
    // 0.07 % (bound 1 %). Before session 18 friction gave 1.40 mu M g d: its
    // normals at the symmetry-face nodes pointed 45 degrees out of plane
    // (mirrored now, ContactNormals.h), so each exchange took sqrt(2) times
    // the normal impulse; test_mpm_friction_coulomb.cpp has the deceleration.
    EXPECT_NEAR(s.heat, Q, (type == "friction_LR" ? 0.03 : 0.01) * Q) << type;
  }
}

// Two blocks in free space; A approaches B. A's right edge particles start
// inside the cell next to B's (they share nodes with B from t = 0) and no
// free-surface particle of A crosses a grid line into a node where only a
// sliver of its mass would land: linear-hat USL is fragile there (see
// test_mpm_disks.cpp), and a friction model that leaves a separating pair
// alone does not repair the resulting v*_g as single_velocity does. Returns (|P - P0| / sum m|v|_0,
// momentum received by B).
std::pair<double, double> impact(const std::string& contact, const Vec3& va) {
  const std::string mats = box_material(1e3, 1e7, 5e6, Vec3(0.125, 0.1, 0), Vec3(0.325, 0.275, 0.05), va) +
                           box_material(2e3, 2e7, 1e7, Vec3(0.35, 0.05, 0), Vec3(0.55, 0.35, 0.05), Vec3::Zero());
  const std::string bcs =
      "<Face side='z-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
      "<Face side='z+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>";
  auto c = scene(mats, contact, Vec3::Zero(), Vec3(0.8, 0.4, 0.05), IntVec3(16, 8, 1), bcs);
  const Sums a0 = sums(c->materials()[0]), b0 = sums(c->materials()[1]);
  run(*c, 0.06);
  const Sums a = sums(c->materials()[0]), b = sums(c->materials()[1]);
  const Vec3 dP = (a.momentum + b.momentum) - (a0.momentum + b0.momentum);
  return {dP.norm() / (a0.scale + b0.scale), b.momentum.norm()};
}

TEST(MpmContact, ClosedSystemsConserveMomentumToRoundOff) {
  // Oblique impact with friction: A moves towards B in x and slides in y.
  const Vec3 va(0.5, 0.3, 0.0);
  const auto [single_error, single_transfer] =
      impact("<contact><type>single_velocity</type></contact>", Vec3(0.5, 0.0, 0.0));
  EXPECT_LT(single_error, 1e-13);
  EXPECT_GT(single_transfer, 0.05 * 1e3 * 0.2 * 0.2 * 0.05 * 0.5) << "no momentum reached B";
  const auto [friction_error, friction_transfer] =
      impact("<contact><type>friction</type><mu>0.3</mu></contact>", va);
  std::printf("friction: |dP|/sum m|v| = %.3g, momentum to B %.3g; single_velocity: %.3g, %.3g\n", friction_error,
              friction_transfer, single_error, single_transfer);
  EXPECT_LT(friction_error, 1e-13);
  EXPECT_GT(friction_transfer, 0.05 * 1e3 * 0.2 * 0.2 * 0.05 * va.norm()) << "no momentum reached B";
  const auto [lr_error, lr_transfer] = impact("<contact><type>friction_LR</type><mu>0.3</mu></contact>", va);
  std::printf("friction_LR: |dP|/sum m|v| = %.3g, momentum to B %.3g\n", lr_error, lr_transfer);
  EXPECT_LT(lr_error, 1e-13);
  EXPECT_GT(lr_transfer, 0.05 * 1e3 * 0.2 * 0.2 * 0.05 * va.norm()) << "no momentum reached B";
}

}  // namespace
}  // namespace tephra
