// tabular_eos (VT §22.2) through the real MPM step: one cell of particles along uniaxial
// strain F*(t) = diag(lambda(t), 1, 1), lambda: 1 -> 0.8 over 1 ms (tests/support/PrescribedDriver.h),
// with a table sampled from Murnaghan p = (K/K')(eta^K' - 1), K = 2.56 GPa, K' = 7.4 (the
// murnaghanMPM constants of test_model_special_materials_driver), at eta = 0.9, 0.95, ..., 1.5.
// Expected: sigma = -p_table(eta) I at eta = 1/lambda, the table's linear interpolation
//   p_table = (1 - s) p_k + s p_{k+1} (VT eqs. 22.2-22.3), to round-off; and within the
//   interpolation bound h^2/8 max|p''| of the Murnaghan pressure itself.
// The deck names the table by a relative path: found beside the deck (the driver writes the
// deck in memory, so the test passes an absolute path and checks the relative lookup in the
// unit test test_model_tabular_eos).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <Eigen/LU>

#include "core/grid/Loop.h"
#include "tests/support/PrescribedDriver.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

const double kK = 2.56e9, kKp = 7.4;
double murnaghan(double eta) { return kK / kKp * (std::pow(eta, kKp) - 1.0); }

TEST(TabularEosDriver, UniaxialStrainPressureIsTheTable) {
  set_thread_count(1);
  const std::string path = test::scratch_dir("tabular_eos_driver") + "/murnaghan.json";
  std::vector<double> eta, p;
  for (int k = 0; k <= 12; ++k) {
    eta.push_back(0.9 + 0.05 * k);
    p.push_back(murnaghan(eta.back()));
  }
  {
    std::ofstream f(path);
    f.precision(17);
    f << "{\"Vaango_tabular_data\": {\"Meta\": {\"title\": \"Murnaghan K = 2.56 GPa, K' = 7.4\"},\n \"Data\": {\n"
         "  \"DensityRatio\": [";
    for (std::size_t k = 0; k < eta.size(); ++k) f << (k ? ", " : "") << eta[k];
    f << "],\n  \"Pressure\": [";
    for (std::size_t k = 0; k < p.size(); ++k) f << (k ? ", " : "") << p[k];
    f << "]}}}\n";
  }
  const double t1 = 1e-3, lambda = 0.8;
  const std::vector<PrescribedRow> rows = {PrescribedRow{0.0, Mat3::Identity(), 0.0, Vec3::UnitZ()},
                                           PrescribedRow{t1, Vec3(lambda, 1, 1).asDiagonal(), 0.0, Vec3::UnitZ()}};
  const test::PrescribedHistory h = test::drive_prescribed(
      "<constitutive_model type=\"tabular_eos\"><filename>" + path +
          "</filename><independent_variables>DensityRatio</independent_variables>"
          "<dependent_variables>Pressure</dependent_variables><interpolation type=\"linear\"/></constitutive_model>",
      rows, {.steps = 50, .density = 1160.0});
  double max_err = 0.0;
  for (std::size_t n = 0; n < h.stress.size(); ++n) {
    const double J = h.F[n].determinant();
    const double x = 1.0 / J;
    std::size_t k = 0;
    while (k + 2 < eta.size() && x > eta[k + 1]) ++k;
    const double s = (x - eta[k]) / (eta[k + 1] - eta[k]);
    const double p_table = (1 - s) * p[k] + s * p[k + 1];
    max_err = std::max(max_err, (h.stress[n] + p_table * Mat3::Identity()).norm());
    // Interpolation bound of the Murnaghan pressure: h^2/8 max|p''|, p'' = K (K'-1) eta^{K'-2} <= at 1.25.
    EXPECT_NEAR(-h.stress[n](0, 0), murnaghan(x), 0.05 * 0.05 / 8 * kK * (kKp - 1) * std::pow(1.25, kKp - 2) + 1e-6);
  }
  std::printf("tabular_eos through the MPM step: lambda = 0.8 -> sigma11 = %.8e Pa (Murnaghan %.8e), "
              "max |sigma + p_table I| = %.3e Pa\n",
              h.stress.back()(0, 0), -murnaghan(1 / lambda), max_err);
  EXPECT_LE(max_err, 1e-10 * kK);
}

}  // namespace
}  // namespace tephra
