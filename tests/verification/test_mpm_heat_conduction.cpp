// Explicit MPM heat conduction and thermal contact (mpm/thermal/HeatConduction.h)
// against closed forms:
//  * 1-D transient conduction in an insulated bar, the decaying cosine mode
//      T(x, t) = T0 + A cos(pi x / L) exp(-alpha pi^2 t / L^2),  alpha = k/(rho c_v),
//    which satisfies dT/dt = alpha d2T/dx2 and dT/dx = 0 at x = 0, L; observed
//    order of the particle L2 error over three resolutions (the lumped-mass
//    linear-element Laplacian has eigenvalue (4 alpha/h^2) sin^2(pi h/2L) =
//    alpha (pi/L)^2 (1 - (pi h/L)^2/12 + ...), and dt ~ h^2, so order 2);
//  * ThermalEnergy = sum m c_v T conserved to round-off with insulated ends;
//  * two materials in thermal contact reach the heat-capacity-weighted mean
//      T_eq = (m_A c_A T_A + m_B c_B T_B) / (m_A c_A + m_B c_B).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/base/PhaseTimers.h"
#include "core/deck/DeckLoader.h"
#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/ArtificialViscosity.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A bar [0, 1] x [0, h] x [0, h] of N x 1 x 1 cells, 2x2x2 particles per cell,
// soft enough that the mechanical step never limits (all motion is zero anyway:
// no load, stress-free). Material regions: [x0, x1) per entry of `parts`.
struct Part {
  double x0, x1, density, specific_heat, conductivity, temperature;
};

MpmSetup bar_setup(int N, const std::vector<Part>& parts, InterpolatorKind shape = InterpolatorKind::Linear) {
  MpmSetup s;
  s.flags.interpolator.kind = shape;
  // GIMP's support reaches the node layer outside the domain.
  if (shape != InterpolatorKind::Linear) s.grid.extra_cells = IntVec3::Ones();
  const double h = 1.0 / N;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3(1.0, h, h);
  s.grid.cells = IntVec3(N, 1, 1);
  s.grid.dx = Vec3::Constant(h);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  for (const Part& part : parts) {
    MpmMaterial m;
    m.index = int(s.materials.size());
    m.density = part.density;
    m.specific_heat = part.specific_heat;
    m.thermal_conductivity = part.conductivity;
    m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{1e-3, 1e-3});
    ParticleSource src;
    src.piece = std::make_shared<BoxPiece>(Vec3(part.x0, 0, 0), Vec3(part.x1, h, h));
    src.res = IntVec3::Constant(2);
    src.velocity = Vec3::Zero();
    src.temperature = part.temperature;
    m.sources.push_back(src);
    m.bcs.set_extra_nodes = shape != InterpolatorKind::Linear;
    s.materials.push_back(std::move(m));
  }
  return s;
}

// Runs to t_end with the component's stable step (x 0.9).
void run_to(MpmComponent& c, double t_end) {
  double t = 0.0;
  int step = 0;
  while (t < t_end) {
    const double dt = std::min(0.9 * c.stable_timestep(), t_end - t);
    c.advance(t, dt, ++step);
    t += dt;
  }
}

long long phase_calls(const std::string& name) {
  for (const auto& e : phase_timers().entries())
    if (e.name == name) return e.calls;
  return 0;
}

struct ModeResult {
  double error = 0;          // sqrt(sum V0 (T_p - T_exact)^2 / sum V0) / A
  double interior_error = 0; // the same over the particles in [0.25, 0.75]
  double energy_drift = 0;   // |E(t_end) - E(0)| / E(0)
};

ModeResult cosine_mode(int N, InterpolatorKind shape = InterpolatorKind::Linear) {
  const double rho = 1.0, cv = 1.0, alpha = 0.1, T0 = 300.0, A = 10.0, t_end = 1.0;
  MpmComponent c(bar_setup(N, {{0.0, 1.0, rho, cv, alpha * rho * cv, T0}}, shape));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = T0 + A * std::cos(kPi * p.x[i][0]);
  const double E0 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  run_to(c, t_end);
  const double E1 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  double e2 = 0, v = 0, e2_in = 0, v_in = 0;
  const double decay = std::exp(-alpha * kPi * kPi * t_end);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double exact = T0 + A * std::cos(kPi * p.x[i][0]) * decay;
    e2 += p.volume0[i] * std::pow(p.temperature[i] - exact, 2);
    v += p.volume0[i];
    if (p.x[i][0] > 0.25 && p.x[i][0] < 0.75) {
      e2_in += p.volume0[i] * std::pow(p.temperature[i] - exact, 2);
      v_in += p.volume0[i];
    }
  }
  return {std::sqrt(e2 / v) / A, std::sqrt(e2_in / v_in) / A, std::abs(E1 - E0) / E0};
}

TEST(MpmHeatConduction, DecayingCosineModeConvergesAtSecondOrder) {
  const int N[3] = {8, 16, 32};
  ModeResult r[3];
  for (int k = 0; k < 3; ++k) r[k] = cosine_mode(N[k]);
  for (int k = 0; k < 3; ++k) std::printf("conduction N = %d: L2 error / A = %.3e, energy drift %.1e\n", N[k], r[k].error, r[k].energy_drift);
  const double order1 = std::log2(r[0].error / r[1].error), order2 = std::log2(r[1].error / r[2].error);
  std::printf("conduction: observed order %.3f (8->16), %.3f (16->32)\n", order1, order2);
  RecordProperty("order_16_32", std::to_string(order2));
  EXPECT_GT(order1, 1.8);
  EXPECT_GT(order2, 1.8);
  // The amplitude at t_end is exp(-pi^2 0.1) = 0.37 of A: the coarsest error
  // must already be a small fraction of it.
  EXPECT_LT(r[0].error, 0.02);
  // Insulated ends: sum m c_v T is conserved to round-off (E ~ 300 m c_v).
  for (const ModeResult& x : r) EXPECT_LT(x.energy_drift, 1e-13);
}

// Periodic bar (x periodic, L = 1; mpm/PeriodicGrid.h fold_mass_weighted):
// the mode T = T0 + A sin(2 pi x) decays as exp(-alpha (2 pi / L)^2 t),
// alpha = k / (rho c_v). With insulated ends instead it is not a mode (its
// slope at x = 0, 1 is 2 pi A), so an unfolded (or insulated) run fails.
ModeResult periodic_sine_mode(int N, InterpolatorKind shape) {
  const double rho = 1.0, cv = 1.0, alpha = 0.025, T0 = 300.0, A = 10.0, t_end = 1.0;
  MpmSetup s = bar_setup(N, {{0.0, 1.0, rho, cv, alpha * rho * cv, T0}}, shape);
  s.grid.periodic = IntVec3(1, 0, 0);
  s.grid.extra_cells[0] = 0;  // a periodic direction has ghost node layers instead
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = T0 + A * std::sin(2 * kPi * p.x[i][0]);
  const double E0 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  run_to(c, t_end);
  const double E1 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  double e2 = 0, v = 0;
  const double decay = std::exp(-alpha * 4 * kPi * kPi * t_end);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double exact = T0 + A * std::sin(2 * kPi * p.x[i][0]) * decay;
    e2 += p.volume0[i] * std::pow(p.temperature[i] - exact, 2);
    v += p.volume0[i];
  }
  return {std::sqrt(e2 / v) / A, 0.0, std::abs(E1 - E0) / E0};
}

class MpmPeriodicConduction : public ::testing::TestWithParam<InterpolatorKind> {};

// Order >= 1.8 over 8 -> 16 -> 32 cells (measured 2.066, 2.018; errors /A
// 3.347e-2, 7.991e-3, 1.972e-3 against the decayed amplitude exp(-0.1 (2 pi)^2)
// = 0.37), ThermalEnergy conserved to round-off (no face, no flux). gimp gives
// the same digits as linear here: with 2 particles per cell at rest, every
// particle sits at d = l = h/4 from its nearest node, where the uGIMP weight
// and gradient equal the hat's (ShapeGimp.h); it checks the ghost-layer fold.
TEST_P(MpmPeriodicConduction, SineModeDecaysAtTheExactRate) {
  const int N[3] = {8, 16, 32};
  ModeResult r[3];
  for (int k = 0; k < 3; ++k) r[k] = periodic_sine_mode(N[k], GetParam());
  const double order1 = std::log2(r[0].error / r[1].error), order2 = std::log2(r[1].error / r[2].error);
  std::printf("periodic conduction %s: L2 error / A = %.3e, %.3e, %.3e (orders %.3f, %.3f), energy drift %.1e %.1e %.1e\n",
              interpolator_name(GetParam()).c_str(), r[0].error, r[1].error, r[2].error, order1, order2,
              r[0].energy_drift, r[1].energy_drift, r[2].energy_drift);
  EXPECT_GT(order1, 1.8);
  EXPECT_GT(order2, 1.8);
  EXPECT_LT(r[2].error, 5e-3);
  for (const ModeResult& x : r) EXPECT_LT(x.energy_drift, 1e-13);
}

INSTANTIATE_TEST_SUITE_P(LinearGimp, MpmPeriodicConduction,
                         ::testing::Values(InterpolatorKind::Linear, InterpolatorKind::Gimp));

// Dirichlet face: T(0, t) = T1 held by <BCType var="Dirichlet" label="Temperature">
// on x-, x = 1 insulated. Exact: the quarter-wave mode
//   T = T1 + A sin(pi x / 2L) exp(-alpha (pi / 2L)^2 t).
double quarter_wave_error(int N) {
  const double alpha = 0.1, T1 = 300.0, A = 10.0, t_end = 2.0, k = kPi / 2.0;
  MpmSetup s = bar_setup(N, {{0.0, 1.0, 1.0, 1.0, alpha, T1}});
  s.materials[0].bcs.temperature[0] = T1;
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.temperature[i] = T1 + A * std::sin(k * p.x[i][0]);
  run_to(c, t_end);
  double e2 = 0, v = 0;
  const double decay = std::exp(-alpha * k * k * t_end);
  for (std::size_t i = 0; i < p.size(); ++i) {
    e2 += p.volume0[i] * std::pow(p.temperature[i] - (T1 + A * std::sin(k * p.x[i][0]) * decay), 2);
    v += p.volume0[i];
  }
  return std::sqrt(e2 / v) / A;
}

TEST(MpmHeatConduction, DirichletFaceQuarterWaveConverges) {
  const double e[3] = {quarter_wave_error(8), quarter_wave_error(16), quarter_wave_error(32)};
  const double o1 = std::log2(e[0] / e[1]), o2 = std::log2(e[1] / e[2]);
  std::printf("conduction, Dirichlet face: L2 error / A = %.3e %.3e %.3e, observed order %.3f %.3f\n", e[0], e[1],
              e[2], o1, o2);
  EXPECT_GT(o1, 1.8);
  EXPECT_GT(o2, 1.8);
}

// A body at T0 whose x- face is raised to Tb at t = 0 (a step in temperature):
// T = T0 + (Tb - T0) erfc(x / (2 sqrt(alpha t))), the semi-infinite solution
// (at t = 0.1, alpha = 0.1 the far face at x = 1 sits 5 diffusion lengths
// away: erfc(5) = 1.5e-12, so the insulated far face does not matter).
double erfc_error(int N) {
  const double alpha = 0.1, T0 = 300.0, Tb = 400.0, t_end = 0.1;
  MpmSetup s = bar_setup(N, {{0.0, 1.0, 1.0, 1.0, alpha, T0}});
  s.materials[0].bcs.temperature[0] = Tb;
  MpmComponent c(std::move(s));
  c.initialize();
  run_to(c, t_end);
  const Particles& p = c.materials()[0].particles;
  double e2 = 0, v = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double exact = T0 + (Tb - T0) * std::erfc(p.x[i][0] / (2.0 * std::sqrt(alpha * t_end)));
    e2 += p.volume0[i] * std::pow(p.temperature[i] - exact, 2);
    v += p.volume0[i];
  }
  return std::sqrt(e2 / v) / (Tb - T0);
}

TEST(MpmHeatConduction, TemperatureStepAtAFaceFollowsTheErfcSolution) {
  const double e[3] = {erfc_error(16), erfc_error(32), erfc_error(64)};
  const double o1 = std::log2(e[0] / e[1]), o2 = std::log2(e[1] / e[2]);
  std::printf("conduction, erfc step: L2 error / (Tb - T0) = %.3e %.3e %.3e, observed order %.3f %.3f\n", e[0], e[1],
              e[2], o1, o2);
  // Measured 2.15, 2.03 with the centroid-corrected face rate
  // (mpm/thermal/TemperatureBoundary.h); holding the face nodes gave 0.50.
  EXPECT_GT(o1, 1.8);
  EXPECT_GT(o2, 1.8);
  EXPECT_LT(e[0], 0.01);
}

TEST(MpmHeatConduction, DecayingCosineModeWithQuadraticBsplines) {
  // The same mode with <interpolator>3rdorderBS (the conduction uses the
  // run's stencils; GIMP and CPDI give exactly the linear weights at the
  // seeded quarter-cell positions of resting particles, B-splines do not).
  // The support reaches the extra-cell node layer, which carries mass and
  // takes part in the conduction, so the faces stay flux-free and the energy
  // is conserved to round-off. Away from the faces (particles in [0.25, 0.75])
  // the error converges at second order (measured 1.90, 2.00, 2.00 up to 64
  // cells); next to the faces the truncated B-spline basis (no boundary-
  // modified splines, the same limitation that keeps the B-spline MMS test
  // disabled) converges more slowly, so the whole-bar L2 order falls
  // (1.99, 1.70, 1.33 up to 64 cells): only the interior order is asserted.
  const int N[3] = {8, 16, 32};
  ModeResult r[3];
  for (int k = 0; k < 3; ++k) r[k] = cosine_mode(N[k], InterpolatorKind::QuadraticBspline);
  const double order1 = std::log2(r[0].interior_error / r[1].interior_error);
  const double order2 = std::log2(r[1].interior_error / r[2].interior_error);
  std::printf("conduction (3rdorderBS): interior L2 error / A = %.3e %.3e %.3e, observed order %.3f %.3f; "
              "whole bar %.3e %.3e %.3e\n",
              r[0].interior_error, r[1].interior_error, r[2].interior_error, order1, order2, r[0].error, r[1].error,
              r[2].error);
  EXPECT_GT(order1, 1.8);
  EXPECT_GT(order2, 1.8);
  for (const ModeResult& x : r) EXPECT_LT(x.energy_drift, 1e-13);
}

TEST(MpmHeatConduction, TwoMaterialsInThermalContactReachTheCapacityWeightedMean) {
  // A on [0, 0.5) (rho c = 2), B on [0.5, 1] (rho c = 1): equal volumes, so
  // T_eq = (2 * 400 + 1 * 250) / 3 = 350 K. Conductivities give alpha = 0.1
  // in both; decay of the slowest mode ~ exp(-alpha pi^2 t), t = 15 gives
  // ~1e-6 of the initial 150 K spread.
  MpmSetup s = bar_setup(16, {{0.0, 0.5, 2.0, 1.0, 0.2, 400.0}, {0.5, 1.0, 1.0, 1.0, 0.1, 250.0}});
  s.thermal_contact = true;
  MpmComponent c(std::move(s));
  c.initialize();
  const double E0 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  run_to(c, 15.0);
  const double T_eq = (2.0 * 400.0 + 1.0 * 250.0) / 3.0;
  double worst = 0;
  for (const MpmMaterial& m : c.materials())
    for (double T : m.particles.temperature) worst = std::max(worst, std::abs(T - T_eq));
  std::printf("thermal contact: max |T - T_eq| = %.3e K after t = 15\n", worst);
  EXPECT_LT(worst, 5e-4);  // observed 1.5e-4 K
  const double E1 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  EXPECT_NEAR(E1 / E0, 1.0, 1e-13);
}

TEST(MpmHeatConduction, ThermalContactWithoutConductionEquilibratesOverlappingMaterialsInOneStep) {
  // Both materials fill the whole bar, k = 0: each node's T_c is
  // (rho_A c_A T_A + rho_B c_B T_B)/(rho_A c_A + rho_B c_B) (the node masses
  // are rho V_g of each), and G2P adds S-weighted (T_c - T_m) with sum S = 1,
  // so after one step every particle sits at T_c = (3*300 + 1*500)/4 = 350 K.
  MpmSetup s = bar_setup(4, {{0.0, 1.0, 3.0, 1.0, 0.0, 300.0}, {0.0, 1.0, 1.0, 1.0, 0.0, 500.0}});
  s.thermal_contact = true;
  MpmComponent c(std::move(s));
  c.initialize();
  c.advance(0.0, 1e-3, 1);
  for (const MpmMaterial& m : c.materials())
    for (double T : m.particles.temperature) EXPECT_NEAR(T, 350.0, 1e-12);
}

TEST(MpmHeatConduction, ArtificialViscosityHeatingRaisesTheParticleTemperature) {
  // Uniform compression v = -rate (x - c) of a block with k = 0 (no
  // conduction): each particle's temperature rises by the model heating of the
  // step, here Vaango's artificial-viscosity heating
  //   dT = dt (-q tr D) / (rho c_v),  q = rho (A1 c_b |tr D| h + A2 (tr D h)^2),
  // with tr D = tr l_p of the step and rho = m_p / V_p after it. Checked
  // against that closed form at every particle, and the total rise against
  // the work of q: sum m c_v dT = dt sum V_p q_p (-tr D_p).
  const double rate = 50.0, dt = 1e-4, cv = 2.0;
  MpmSetup s = bar_setup(4, {{0.0, 1.0, 1000.0, cv, 0.0, 300.0}});
  s.flags.artificial_viscosity = true;
  s.flags.artificial_viscosity_heating = true;
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = -rate * (p.x[i] - Vec3(0.5, 0.125, 0.125));
  const double E0 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  c.advance(0.0, dt, 1);
  const MpmMaterial& m = c.materials()[0];
  const double h = 0.25, K = 1e-3;
  double work = 0;
  int heated = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double trD = m.L[i].trace(), rho = p.mass[i] / p.volume[i];
    const double q = artificial_bulk_viscosity(trD, std::sqrt(K / rho), rho, h, {0.2, 2.0});
    EXPECT_NEAR(p.temperature[i] - 300.0, dt * (-q * trD) / (rho * cv), 1e-12);
    work += dt * p.volume[i] * q * -trD;
    heated += p.temperature[i] > 300.0;
  }
  EXPECT_GT(heated, 0);
  const double E1 = c.reductions({"ThermalEnergy"}).at("ThermalEnergy")[0];
  EXPECT_NEAR(E1 - E0, work, 1e-9 * work);
}

// The same through the deck reader: <thermal_contact/> in <MaterialProperties><MPM>.
TEST(MpmHeatConduction, ThermalContactFromTheDeck) {
  auto material = [](double rho, double T) {
    return "<material><density>" + std::to_string(rho) +
           "</density><constitutive_model type='comp_neo_hook'><bulk_modulus>1</bulk_modulus>"
           "<shear_modulus>1</shear_modulus></constitutive_model><thermal_conductivity>0</thermal_conductivity>"
           "<specific_heat>1</specific_heat><geom_object><box><min>[0,0,0]</min><max>[1,0.25,0.25]</max></box>"
           "<res>[2,2,2]</res><velocity>[0,0,0]</velocity><temperature>" +
           std::to_string(T) + "</temperature></geom_object></material>";
  };
  for (bool contact : {false, true}) {
    const std::string text =
        "<Uintah_specification><MaterialProperties><MPM>" + material(3.0, 300.0) + material(1.0, 500.0) +
        (contact ? "<thermal_contact/>" : "") +
        "</MPM></MaterialProperties><Grid><Level><Box><lower>[0,0,0]</lower><upper>[1,0.25,0.25]</upper>"
        "<resolution>[4,1,1]</resolution><extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level>"
        "</Grid></Uintah_specification>";
    auto deck = load_deck_from_string(text, "contact.ups", ".");
    auto c = make_mpm_component(*deck);
    c->initialize();
    c->advance(0.0, 1e-3, 1);
    // With contact: (3*300 + 1*500)/4 = 350 K; without: each keeps its own.
    for (const MpmMaterial& m : c->materials())
      for (double T : m.particles.temperature) EXPECT_NEAR(T, contact ? 350.0 : (m.index == 0 ? 300.0 : 500.0), 1e-12);
  }
}

TEST(MpmHeatConduction, NoConductionPhaseWithoutConductivityOrWithUniformTemperature) {
  const std::string phase = "MPM: heat conduction";
  // k = 0 and no thermal contact: the phase never runs, T stays.
  {
    MpmComponent c(bar_setup(4, {{0.0, 1.0, 1.0, 1.0, 0.0, 300.0}}));
    c.initialize();
    c.materials()[0].particles.temperature[0] = 400.0;
    const long long before = phase_calls(phase);
    c.advance(0.0, 1e-3, 1);
    EXPECT_EQ(phase_calls(phase), before);
    EXPECT_EQ(c.materials()[0].particles.temperature[0], 400.0);
  }
  // k > 0, uniform T: nothing to conduct; the phase is skipped.
  {
    MpmComponent c(bar_setup(4, {{0.0, 1.0, 1.0, 1.0, 1.0, 300.0}}));
    c.initialize();
    const long long before = phase_calls(phase);
    c.advance(0.0, 1e-3, 1);
    EXPECT_EQ(phase_calls(phase), before);
    for (double T : c.materials()[0].particles.temperature) EXPECT_EQ(T, 300.0);
  }
  // <do_explicit_heat_conduction>false: k > 0 and a gradient, still no phase.
  {
    MpmSetup s = bar_setup(4, {{0.0, 1.0, 1.0, 1.0, 1.0, 300.0}});
    s.flags.explicit_heat_conduction = false;
    MpmComponent c(std::move(s));
    c.initialize();
    c.materials()[0].particles.temperature[0] = 400.0;
    const long long before = phase_calls(phase);
    c.advance(0.0, 1e-3, 1);
    EXPECT_EQ(phase_calls(phase), before);
  }
}

}  // namespace
}  // namespace tephra
