// <initialize_stress_using_body_force> (mpm/loads/BodyForceStress.h): a
// column starts in the stress that balances gravity.
//
// The column of test_mpm_gravity: height H = 1 m on the symmetry floor z = 0,
// laterally confined by symmetry planes, rho0 = 1000, g = 10 m/s^2 down,
// K = 1e6, G = 0.5e6 Pa (c = sqrt((K + 4G/3)/rho0) = 40.8 m/s), linear
// interpolation, 2 particles per cell, 20 cells, no damping. The surface
// reference point is the top, z_s = H, so eq. (1) gives
//     sigma_zz = -rho0 g (H - z),   sigma_xx = sigma_yy = 0,
// and d sigma_zz/dz = rho0 g balances the weight exactly.
//
// 1. Grid balance at t = 0. With linear shape functions and two particles
//    per cell at the quarter points, the internal force of a linear stress
//    at a free node is sigma(z_i + h/2) - sigma(z_i - h/2) = rho0 g h per
//    unit area and the nodal weight is rho0 h g (the top node: half of
//    each), so f_int + f_ext = 0 exactly but for the volume factor
//    V = J V0 of eq. (2): the internal force is that of J sigma, whose
//    derivative d(J sigma)/dz = rho0 g J + sigma dJ/dz differs from rho0 g
//    by at most 2 |eps_v|max rho0 g (J - 1 = eps_v, eps_v = (1 - 2 nu)
//    sigma_zz / E: 3.3e-3 at the floor). comp_neo_hook recomputes sigma
//    from F = I + eps, equal to eq. (1) up to its second-order term,
//    bounded by (K + 4G/3) eps_zz^2 (eps_zz = rho0 g H / E = 7.8e-3 at the
//    floor: 101 Pa), whose slope adds 2 (K + 4G/3) eps_zz,max / E to the
//    relative nodal imbalance.
// 2. Motion. Released from the unstressed state the column's top falls
//    freely until the unloading wave from the floor reaches it at t = H/c:
//    the top particle's speed reaches g H / c = 0.245 m/s (closed form of
//    the 1-D wave equation with a suddenly applied body force). Started in
//    the balanced state, the driving force is the residual of 1, at most
//    2 |eps_v|max rho0 g per unit volume for hypo_elastic: an equivalent
//    body force applied suddenly, whose top speed is bounded by the same
//    free-fall argument, 2 g |eps_v|max H / c = 1.6e-3 m/s. Both runs go
//    to t = 4 H / c (one period of the lowest mode).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "models/solid/HypoElastic.h"
#include "mpm/MpmComponent.h"
#include "mpm/loads/BodyForceStress.h"

namespace tephra {
namespace {

constexpr double kH = 1.0, kRho = 1000.0, kG = 10.0, kK = 1e6, kShear = 0.5e6;
constexpr int kCells = 20;

std::unique_ptr<MpmComponent> column(bool balanced, bool hypo) {
  const double h = kH / kCells;
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3(h, h, kH + 2 * h);
  s.grid.cells = IntVec3(1, 1, kCells + 2);
  s.grid.dx = Vec3::Constant(h);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  s.gravity = Vec3(0, 0, -kG);
  s.flags.initialize_stress_using_body_force = balanced;
  MpmMaterial m;
  m.density = kRho;
  m.specific_heat = 1.0;
  if (hypo)
    m.model = std::make_shared<HypoElastic>(HypoElasticParams{kShear, kK});
  else
    m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{kK, kShear});
  m.body_force_surface = Vec3(0, 0, kH);
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Zero(), Vec3(h, h, kH));
  src.res = IntVec3::Constant(2);
  src.velocity = Vec3::Zero();
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  for (int f = 0; f < 5; ++f) s.materials[0].bcs.face[f].kind = FaceVelocityBC::Kind::Symmetry;
  return std::make_unique<MpmComponent>(std::move(s));
}

// Largest top-particle speed over t in [0, 4 H / c].
double max_top_speed(MpmComponent& c) {
  const double c_wave = std::sqrt((kK + 4 * kShear / 3) / kRho), t_end = 4 * kH / c_wave;
  double t = 0, vmax = 0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.5 * c.stable_timestep(), t_end - t);
    c.advance(t, dt, ++step);
    t += dt;
    const Particles& p = c.materials()[0].particles;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.x[i][2] - p.displacement[i][2] > kH - 0.5 * kH / kCells) vmax = std::max(vmax, p.v[i].norm());
  }
  return vmax;
}

TEST(MpmBodyForceStress, StressAndDeformationGradientAreEqs1And2) {
  // sigma_ii = -rho b_i (x_i - x_s,i): gravity (0, -2, -10) at x = (1, 2, 3), surface (0, 5, 7).
  const Mat3 s = body_force_stress(1000, Vec3(0, -2, -10), Vec3(1, 2, 3), Vec3(0, 5, 7));
  EXPECT_EQ(s(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(s(1, 1), -1000 * 2 * 3.0);  // -rho |b_y| (y_s - y)
  EXPECT_DOUBLE_EQ(s(2, 2), -1000 * 10 * 4.0);
  EXPECT_EQ(s(0, 1), 0.0);
  // F - I = linear elastic strain: uniaxial stress sigma gives eps_zz = sigma/E, eps_xx = -nu sigma/E.
  const double K = 1e6, G = 0.5e6, E = 9 * K * G / (3 * K + G), nu = (3 * K - 2 * G) / (2 * (3 * K + G));
  Mat3 sig = Mat3::Zero();
  sig(2, 2) = -1e4;
  const Mat3 F = small_strain_deformation_gradient(sig, K, G);
  EXPECT_NEAR(F(2, 2) - 1, -1e4 / E, 1e-15);
  EXPECT_NEAR(F(0, 0) - 1, nu * 1e4 / E, 1e-15);
  EXPECT_EQ(F(0, 2), 0.0);
}

TEST(MpmBodyForceStress, ColumnStartsInEquilibrium) {
  const double E = 9 * kK * kShear / (3 * kK + kShear), nu = (3 * kK - 2 * kShear) / (2 * (3 * kK + kShear));
  const double eps_v_max = (1 - 2 * nu) * kRho * kG * kH / E;  // at the floor
  const double c_wave = std::sqrt((kK + 4 * kShear / 3) / kRho);
  for (bool hypo : {true, false}) {
    auto cp = column(true, hypo);
    MpmComponent& c = *cp;
    c.initialize();
    const Particles& p = c.materials()[0].particles;
    double stress_error = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
      stress_error = std::max(stress_error, std::abs(p.stress[i](2, 2) + kRho * kG * (kH - p.x[i][2])));
    // hypo_elastic keeps eq. (1); comp_neo_hook recomputes it from F = I + eps, equal up to (K + 4G/3) eps_zz^2.
    const double eps_zz_max = kRho * kG * kH / E, M = kK + 4 * kShear / 3;
    if (hypo) EXPECT_LT(stress_error, 1e-10 * kRho * kG * kH);
    else EXPECT_LT(stress_error, M * eps_zz_max * eps_zz_max);
    // 1. Grid balance at the free nodes (z > 0) in z.
    const NodeGrid& g = c.materials()[0].grid;
    double worst = 0;
    const double h = kH / kCells;
    for (int k = 0; k < g.n[2]; ++k)
      for (int j = 0; j < g.n[1]; ++j)
        for (int i = 0; i < g.n[0]; ++i) {
          const std::size_t n = g.index(i, j, k);
          if (g.mass[n] <= 0 || g.position(i, j, k)[2] < 0.5 * h) continue;  // the floor nodes carry the reaction
          worst = std::max(worst, std::abs(g.internal_force[n][2] + g.external_force[n][2]) / (g.mass[n] * kG));
        }
    const double balance_bound = 2 * eps_v_max + (hypo ? 0.0 : 2 * M * eps_zz_max / E);
    std::printf("%s: max |sigma_zz - eq.1| = %.2e Pa, max |f_int + f_ext|_z / (m_g g) = %.3e (bound %.3e)\n",
                hypo ? "hypo_elastic" : "comp_neo_hook", stress_error, worst, balance_bound);
    EXPECT_LE(worst, balance_bound);
    // 2. Motion, against the unstressed start.
    const double v_balanced = max_top_speed(c);
    auto free = column(false, hypo);
    free->initialize();
    const double v_free = max_top_speed(*free);
    const double bound = 2 * kG * eps_v_max * kH / c_wave;
    std::printf("  top speed over one period: balanced %.3e m/s (bound %.3e), unstressed %.4f m/s (g H / c = %.4f)\n",
                v_balanced, bound, v_free, kG * kH / c_wave);
    EXPECT_LT(v_balanced, bound);
    EXPECT_GT(v_free, 0.9 * kG * kH / c_wave);
  }
}

std::string deck_text(const std::string& mpm_flags, const std::string& model_extra, const std::string& type) {
  return "<Uintah_specification><Meta><title>t</title></Meta><SimulationComponent type=\"mpm\"/>"
         "<Time><maxTime>1</maxTime><initTime>0</initTime><delt_min>0</delt_min><delt_max>1</delt_max>"
         "<timestep_multiplier>0.5</timestep_multiplier></Time>"
         "<MPM><interpolator>linear</interpolator>" + mpm_flags + "</MPM>"
         "<PhysicalConstants><gravity>[0,0,-10]</gravity></PhysicalConstants>"
         "<MaterialProperties><MPM><material><density>1000</density><thermal_conductivity>0</thermal_conductivity>"
         "<specific_heat>1</specific_heat><constitutive_model type=\"" + type + "\">" +
         (type == "hypo_elastic" ? "<G>5e5</G><K>1e6</K>" : "<bulk_modulus>1e6</bulk_modulus><shear_modulus>5e5</shear_modulus>") +
         model_extra + "</constitutive_model>"
         "<geom_object><box label=\"b\"><min>[0,0,0]</min><max>[0.1,0.1,1]</max></box><res>[2,2,2]</res>"
         "<velocity>[0,0,0]</velocity><temperature>300</temperature></geom_object></material>"
         "<contact><type>null</type></contact></MPM></MaterialProperties>"
         "<Grid><Level><Box label=\"1\"><lower>[0,0,0]</lower><upper>[0.1,0.1,1.1]</upper>"
         "<resolution>[1,1,11]</resolution><patches>[1,1,1]</patches></Box></Level></Grid>"
         "</Uintah_specification>";
}

TEST(MpmBodyForceStress, DeckOptionsAndErrors) {
  const std::string flag = "<initialize_stress_using_body_force>true</initialize_stress_using_body_force>";
  const std::string opt =
      "<initialize_with_body_force>true</initialize_with_body_force><surface_reference_point>[0,0,1]</surface_reference_point>";
  {
    auto d = load_deck_from_string(deck_text(flag, opt, "hypo_elastic"), "t.ups", ".");
    auto c = make_mpm_component(*d);
    c->initialize();
    const Particles& p = c->materials()[0].particles;
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p.stress[i](2, 2), -1e4 * (1 - p.x[i][2]), 1e-9);
  }
  // The material opts in but the MPM flag is off: unstressed (Vaango), with a warning.
  {
    auto d = load_deck_from_string(deck_text("", opt, "comp_neo_hook"), "t.ups", ".");
    auto c = make_mpm_component(*d);
    c->initialize();
    EXPECT_EQ(c->materials()[0].particles.stress[0], Mat3::Zero());
  }
  // Missing surface point; a model eq. (2) does not describe.
  EXPECT_THROW(make_mpm_component(*load_deck_from_string(
                   deck_text(flag, "<initialize_with_body_force>true</initialize_with_body_force>", "hypo_elastic"),
                   "t.ups", ".")),
               DeckError);
  EXPECT_THROW(make_mpm_component(*load_deck_from_string(
                   deck_text(flag, "<surface_reference_point>[0,0,1]</surface_reference_point>", "hypo_elastic"),
                   "t.ups", ".")),
               DeckError);
}

}  // namespace
}  // namespace tephra
