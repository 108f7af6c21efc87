// visco_scram through the real MPM step (the prescribed-deformation driver,
// tests/support/PrescribedDriver.h): a pure-shear strain eps = ln(1 + gamma)
// applied at a constant rate over t_r and then held. With cracks off, each
// Maxwell element obeys s_i_dot = 2 G_i eps_dot - s_i/tau_i, so
//
//   s_i(t) = 2 G_i eps_dot tau_i (1 - exp(-t/tau_i))                       t <= t_r
//   s_i(t) = 2 G_i eps_dot tau_i (1 - exp(-t_r/tau_i)) exp(-(t - t_r)/tau_i)  t >  t_r
//
// (eps_dot = eps/t_r; the step-strain relaxation sum_i 2 G_i eps exp(-t/tau_i)
// is the limit t_r -> 0), and sigma_xx = sum_i s_i,xx (J = 1 + O(gamma^2)).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/grid/Loop.h"
#include "tests/support/PrescribedDriver.h"

namespace tephra {
namespace {

const std::array<double, 5> kG = {1.0e8, 2.0e8, 1.5e8, 1.0e8, 0.5e8};  // [Pa]
const std::array<double, 5> kR = {0.0, 2e3, 5e3, 1e4, 2e4};           // RTau_i = 1/tau_i [1/s]

std::string scram_xml() {
  std::ostringstream x;
  x << "<constitutive_model type=\"visco_scram\"><PR>0.3</PR><CrackParameterA>1e-3</CrackParameterA>"
       "<CrackPowerValue>10</CrackPowerValue><CrackMaxGrowthRate>0</CrackMaxGrowthRate>"
       "<StressIntensityF>500</StressIntensityF><CrackFriction>0.35</CrackFriction>"
       "<InitialCrackRadius>1e-12</InitialCrackRadius><CrackGrowthRate>12</CrackGrowthRate>"
       "<Beta>1.5e-4</Beta><Gamma>1.0</Gamma><DCp_DTemperature>3.30773</DCp_DTemperature>";
  for (int i = 0; i < 5; ++i) x << "<G" << i + 1 << ">" << kG[i] << "</G" << i + 1 << "><RTau" << i + 1 << ">" << kR[i] << "</RTau" << i + 1 << ">";
  x << "</constitutive_model>";
  return x.str();
}

double element_stress(int i, double eps_dot, double t_r, double t) {
  if (kR[i] == 0.0) return 2 * kG[i] * eps_dot * std::min(t, t_r);
  const double tau = 1.0 / kR[i];
  if (t <= t_r) return 2 * kG[i] * eps_dot * tau * (1 - std::exp(-t / tau));
  return 2 * kG[i] * eps_dot * tau * (1 - std::exp(-t_r / tau)) * std::exp(-(t - t_r) / tau);
}

TEST(ViscoScramRelaxation, RampAndHoldThroughTheMpmStepMatchesMaxwellClosedForm) {
  set_thread_count(1);
  const double gamma = 1e-5, t_r = 1e-4, t_end = 1e-3;
  Mat3 F1 = Mat3::Identity();
  F1(0, 0) = 1 + gamma;
  F1(1, 1) = 1 / (1 + gamma);
  const std::vector<PrescribedRow> rows = {{0.0, Mat3::Identity(), 0.0, Vec3::UnitZ()},
                                           {t_r, F1, 0.0, Vec3::UnitZ()},
                                           {t_end, F1, 0.0, Vec3::UnitZ()}};
  // dt = 5 us: RTau_max dt = 0.1, t_r = 20 steps. The linear F interpolation of
  // the driver varies the rate by O(gamma) = 1e-5 relative over the ramp.
  const test::PrescribedHistory h = test::drive_prescribed(scram_xml(), rows, {.steps = 200, .density = 1830.0});
  const double eps_dot = std::log(1 + gamma) / t_r;
  const double peak = 2 * (kG[0] + kG[1] + kG[2] + kG[3] + kG[4]) * std::log(1 + gamma);
  double worst = 0, worst_element = 0;
  for (std::size_t k = 0; k < h.time.size(); ++k) {
    double exact = 0;
    for (int i = 0; i < 5; ++i) {
      const double s_i = element_stress(i, eps_dot, t_r, h.time[k]);
      exact += s_i;
      worst_element = std::max(worst_element, std::abs(h.history[k][9 * i] - s_i) / (2 * kG[i] * std::log(1 + gamma)));
    }
    worst = std::max(worst, std::abs(h.stress[k](0, 0) - exact) / peak);
  }
  const double end_exact = [&] {
    double e = 0;
    for (int i = 0; i < 5; ++i) e += element_stress(i, eps_dot, t_r, t_end);
    return e;
  }();
  std::printf("visco_scram ramp+hold via MPM: sigma_xx(t_end) %.6e (exact %.6e, peak scale %.3e); max error %.2e "
              "of peak, %.2e per element\n",
              h.stress.back()(0, 0), end_exact, peak, worst, worst_element);
  // sigma_xx also carries p = K ln J, J = 1 - f(1 - f) gamma^2 on the ramp: K gamma^2/4 ~ 3e-6 of
  // the peak; the elements see the O(gamma) rate variation and RK4's (RTau dt)^5/120 ~ 1e-7 per step.
  EXPECT_LT(worst, 1e-5);
  EXPECT_LT(worst_element, 2e-6);
  // The relaxed state: elements 2-5 have decayed by exp(-0.9 ms RTau_i) <= exp(-1.8).
  EXPECT_LT(h.stress.back()(0, 0), 0.5 * peak);
}

}  // namespace
}  // namespace tephra
