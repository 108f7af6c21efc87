// Vaango's constitutive-model harness decks (decks README A2, A3): a one-cell
// specimen (material 1, one particle) squeezed between the z- symmetry plane
// and a heavy piston (material 0) moving at -0.01 m/s through `rigid`
// contact; its lateral faces are free, so the specimen is in uniaxial stress.
//
// const_test_hypo.ups (hypo_elastic, K = 32 MPa, G = 12 MPa): with the
// Green-Naghdi rate and the unrotated strain increment (mpm/../HypoElastic.cpp,
// VT eq. 4.2) a uniaxial-stress history integrates d(sigma_zz) = E d(ln h)
// exactly, so
//   sigma_zz = E ln(h / h0),  E = 9 K G / (3 K + G) = 32 MPa,  sigma_xx = sigma_yy = 0,
// up to the time discretisation of the strain increments (a midpoint rule on
// U: relative error O((dt eps_dot)^2) ~ (2e-5)^2 per step, observed 1e-10):
// tolerance 1e-8. There is no inertia error: the one particle's velocity
// gradient is set kinematically by the piston node (z = 0.01, v = -0.01 m/s)
// and the symmetry plane (z = 0), l_zz = -0.01/0.01 = -1 s^-1 exactly, so
// h = h0 exp(-t) (not h0 - 0.01 t: the piston drives the grid node, and the
// specimen's top, inside the cell, follows the interpolated velocity).
// h is the specimen height from the particle position: the particle sits at
// the specimen's centre and its bottom on the z- plane, so h = 2 z_p.
//
// const_test_cmr.ups (comp_mooney_rivlin, C1 = 1e5, C2 = 2e4, nu = 0.49, to
// 50 % strain): the closed form is the uniaxial-stress CMR response: for
// lambda = h/h0 find the lateral stretch a with sigma_xx(diag(a, a, lambda)) = 0
// (bisection on the model's point function, VT eq. 4.12), then sigma_zz of
// that F. The hyperelastic stress has no integration error of its own; the
// remaining error is the lateral stretch, set by the free lateral nodes
// (observed 7e-8): tolerance 1e-6.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "models/solid/CompMooneyRivlin.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

namespace fs = std::filesystem;

std::string deck_path(const std::string& name) { return test::shared_dir() + "/decks/inputs/MPM/" + name; }

// Runs the deck in-process with the deck's step rule and calls check(t, specimen)
// every `every` steps and at the end.
template <class Check>
void run_deck(const std::string& name, int every, Check&& check) {
  auto deck = load_deck(deck_path(name));
  const DeckNode& time = deck->root.require_child("Time");
  const double multiplier = time.get_double("timestep_multiplier");
  const double delt_max = time.get_double("delt_max");
  const double max_time = time.get_double("maxTime");
  auto c = make_mpm_component(*deck);
  c->initialize();
  double t = 0;
  int step = 0;
  while (t < max_time) {
    const double dt = std::min({multiplier * c->stable_timestep(), delt_max, max_time - t});
    c->advance(t, dt, ++step);
    t += dt;
    if (step % every == 0 || t >= max_time) check(t, c->materials()[1].particles);
  }
}

TEST(MpmConstTest, HypoElasticUniaxialStressIsELogStretch) {
  const double K = 32e6, G = 12e6, E = 9 * K * G / (3 * K + G), h0 = 0.01;
  double worst = 0, worst_lateral = 0, last_h = h0;
  int checks = 0;
  run_deck("const_test_hypo.ups", 100, [&](double t, const Particles& p) {
    ASSERT_EQ(p.size(), 1u);
    const double h = 2.0 * p.x[0][2];
    const double expected = E * std::log(h / h0);
    if (t < 0.005) return;  // |E ln(h/h0)| < 0.16 MPa: relative errors of tiny stresses
    const double err = std::abs(p.stress[0](2, 2) - expected) / std::abs(expected);
    worst = std::max(worst, err);
    worst_lateral = std::max(worst_lateral, std::max(std::abs(p.stress[0](0, 0)), std::abs(p.stress[0](1, 1))) /
                                                std::abs(expected));
    last_h = h;
    ++checks;
  });
  std::printf("const_test_hypo: %d checks, max |sigma_zz - E ln(h/h0)| / |E ln(h/h0)| = %.3e, "
              "max |sigma_lateral| / |sigma_zz| = %.3e, final h/h0 = %.5f\n",
              checks, worst, worst_lateral, last_h / h0);
  EXPECT_GT(checks, 20);
  // l_zz = -1 s^-1 for 0.1 s; forward Euler in x_p gives prod(1 - dt_n), below
  // exp(-t) by ~ t dt / 2 ~ 1e-6 (dt ~ 2e-5 s).
  EXPECT_NEAR(last_h / h0, std::exp(-0.1), 1e-5);
  EXPECT_LT(worst, 1e-8);
  EXPECT_LT(worst_lateral, 1e-8);
}

// sigma_zz of CMR in uniaxial stress at axial stretch lambda (see the top).
double cmr_uniaxial_stress(double lambda, const CompMooneyRivlinParams& prm) {
  auto sxx = [&](double a) {
    Eigen::Matrix3d F = Eigen::Vector3d(a, a, lambda).asDiagonal();
    return comp_mooney_rivlin_point(F, 1000.0, prm).stress(0, 0);
  };
  // sigma_xx increases with a; bracket around the incompressible guess 1/sqrt(lambda).
  double lo = 0.5 / std::sqrt(lambda), hi = 2.0 / std::sqrt(lambda);
  EXPECT_LT(sxx(lo), 0.0);
  EXPECT_GT(sxx(hi), 0.0);
  for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
    const double mid = 0.5 * (lo + hi);
    (sxx(mid) < 0 ? lo : hi) = mid;
  }
  const double a = 0.5 * (lo + hi);
  Eigen::Matrix3d F = Eigen::Vector3d(a, a, lambda).asDiagonal();
  return comp_mooney_rivlin_point(F, 1000.0, prm).stress(2, 2);
}

TEST(MpmConstTest, CompMooneyRivlinUniaxialStressMatchesClosedForm) {
  CompMooneyRivlinParams prm;
  prm.C1 = 1e5;
  prm.C2 = 2e4;
  prm.nu = 0.49;
  const double h0 = 0.01;
  double worst = 0, last_h = h0;
  int checks = 0;
  run_deck("const_test_cmr.ups", 500, [&](double t, const Particles& p) {
    ASSERT_EQ(p.size(), 1u);
    const double h = 2.0 * p.x[0][2];
    if (t < 0.025) return;  // tiny stresses at the start (as above)
    const double expected = cmr_uniaxial_stress(h / h0, prm);
    worst = std::max(worst, std::abs(p.stress[0](2, 2) - expected) / std::abs(expected));
    last_h = h;
    ++checks;
  });
  std::printf("const_test_cmr: %d checks, max relative error of sigma_zz = %.3e, final h/h0 = %.4f\n", checks,
              worst, last_h / h0);
  EXPECT_GT(checks, 20);
  EXPECT_NEAR(last_h / h0, std::exp(-0.5), 3e-5);  // as above: t dt / 2 ~ 1e-5 (dt ~ 4e-5 s)
  EXPECT_LT(worst, 1e-6);
}

// The decks run to their end through the executable: exit 0, finite reductions.
TEST(MpmConstTest, DecksRunToTheEndThroughTheExecutable) {
  for (const char* name : {"const_test_hypo.ups", "const_test_cmr.ups"}) {
    const fs::path dir = fs::path(test::scratch_dir(std::string("const_test_") + name)) / "out";
    std::string out;
    ASSERT_EQ(test::run_tephra(deck_path(name) + " --quiet --output " + dir.string(), &out), 0) << name << "\n" << out;
    if (std::string(name) == "const_test_hypo.ups") {
      std::ifstream in(dir / "BndyForce_zminus.dat");
      ASSERT_TRUE(in) << "no BndyForce_zminus.dat";
      std::string line;
      int rows = 0;
      while (std::getline(in, line)) {
        ++rows;
        EXPECT_EQ(line.find("nan"), std::string::npos) << line;
      }
      EXPECT_GE(rows, 10);  // outputInterval 0.01 over 0.1 s
    }
  }
}

}  // namespace
}  // namespace tephra
