// trans_iso_hyper (models/solid/TransIsoHyper.h): VT §4.2.3 eqs. 4.13-4.19 with
// Weiss's fibre law. Closed forms:
//  - isochoric stretch lambda along the fibre a0 = e1, F = diag(l, l^{-1/2}, l^{-1/2}):
//    Bb = diag(l^2, 1/l, 1/l), f = e1, lb = l, and
//      sigma11 - sigma22 = 2[(C1 + C2 I1)(l^2 - 1/l) - C2 (l^4 - 1/l^2)] + lb W_f'(lb)
//    with lb W_f' = C3 (e^{C4(l-1)} - 1) below lambda*, C5 l + C6 above; 0 for l < 1;
//  - pure dilation F = s I: sigma = kappa ln J / J I (eq. 4.19, Bb = I, lb = 1);
//  - sigma = (1/J) dW/dF F^T by central differences with strong fibres (eq. 4.3);
//  - the fibre direction convects: F = R (rotation) rotates the fibre stress.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "models/solid/TransIsoHyper.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;
const double kRho0 = 1100.0;

TransIsoHyperParams ligament() {  // Weiss-like ligament constants (strong fibres)
  TransIsoHyperParams p;
  p.kappa = 1.0e8;
  p.C1 = 2.0e6;
  p.C2 = 0.5e6;
  p.C3 = 1.0e5;
  p.C4 = 40.0;
  p.C5 = 5.0e8;
  p.lambda_star = 1.06;
  p.a0 = Eigen::Vector3d::UnitX();
  return p;
}

TEST(ModelTransIsoHyper, FibreStretchClosedFormOnBothBranches) {
  const TransIsoHyperParams p = ligament();
  for (double l : {0.9, 1.0, 1.03, 1.06, 1.1}) {
    const M3 F = Eigen::Vector3d(l, 1 / std::sqrt(l), 1 / std::sqrt(l)).asDiagonal();
    const SolidPointResult r = trans_iso_hyper_point(F, kRho0, p);
    const double I1 = l * l + 2 / l;
    const double matrix = 2 * ((p.C1 + p.C2 * I1) * (l * l - 1 / l) - p.C2 * (l * l * l * l - 1 / (l * l)));
    const double fibre = l < 1 ? 0.0 : l < p.lambda_star ? p.C3 * (std::exp(p.C4 * (l - 1)) - 1) : p.C5 * l + p.C6();
    EXPECT_NEAR(r.stress(0, 0) - r.stress(1, 1), matrix + fibre, 1e-9 * (std::abs(matrix) + std::abs(fibre) + 1)) << l;
    EXPECT_NEAR(r.stress(1, 1), r.stress(2, 2), 1e-6);
    EXPECT_NEAR(r.stress.trace() / 3, 0.0, 1e-6);  // J = 1: p = 0 and sigma_d, sigma_f are trace-free
  }
  // lb W_f' is continuous at lambda* (C6 of eq. 4.16).
  EXPECT_NEAR(trans_iso_fibre_stress(p.lambda_star * (1 - 1e-12), p), trans_iso_fibre_stress(p.lambda_star, p),
              1e-6 * trans_iso_fibre_stress(p.lambda_star, p));
}

TEST(ModelTransIsoHyper, DilationGivesTheLogPressure) {
  const TransIsoHyperParams p = ligament();
  for (double s : {0.95, 1.0, 1.04}) {
    const SolidPointResult r = trans_iso_hyper_point(s * M3::Identity(), kRho0, p);
    const double J = s * s * s;
    EXPECT_LE((r.stress - p.kappa * std::log(J) / J * M3::Identity()).norm(), 1e-9 * p.kappa) << s;
    EXPECT_NEAR(r.energy_density, 0.5 * p.kappa * std::log(J) * std::log(J), 1e-9 * p.kappa);
  }
}

TEST(ModelTransIsoHyper, StressIsTheDerivativeOfTheEnergyWithStrongFibres) {
  // P = dW/dF (central differences, h = 1e-6), sigma = P F^T / J; the fibre
  // energy uses the exponential integral (header).
  TransIsoHyperParams p = ligament();
  p.a0 = Eigen::Vector3d(1, 2, 2).normalized();
  const M3 Fs[3] = {(M3() << 1.04, 0.02, 0.0, 0.01, 0.99, 0.03, 0.0, 0.01, 1.0).finished(),
                    (M3() << 1.01, 0.05, 0.02, 0.0, 1.05, 0.0, 0.03, 0.0, 1.04).finished(),
                    (M3() << 1.1, 0.0, 0.0, 0.0, 1.08, 0.02, 0.0, 0.0, 1.07).finished()};
  for (const M3& F : Fs) {
    const double lb = (F * p.a0).norm() / std::cbrt(F.determinant());
    M3 P;
    const double h = 1e-6;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        M3 Fp = F, Fm = F;
        Fp(i, j) += h;
        Fm(i, j) -= h;
        P(i, j) = (trans_iso_hyper_point(Fp, kRho0, p).energy_density - trans_iso_hyper_point(Fm, kRho0, p).energy_density) /
                  (2 * h);
      }
    const M3 sigma = trans_iso_hyper_point(F, kRho0, p).stress;
    std::printf("trans_iso_hyper lb = %.5f: |sigma - P F^T/J| / |sigma| = %.3e\n", lb,
                (sigma - P * F.transpose() / F.determinant()).norm() / sigma.norm());
    EXPECT_LE((sigma - P * F.transpose() / F.determinant()).norm(), 1e-6 * sigma.norm());
  }
}

TEST(ModelTransIsoHyper, FibreConvectsWithARotation) {
  // F = R U: sigma(R U) = R sigma(U) R^T (the fibre f = J^{-1/3} F a0 / lb turns with R).
  const TransIsoHyperParams p = ligament();
  const M3 U = Eigen::Vector3d(1.05, 0.98, 0.975).asDiagonal();
  const M3 R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 1, 0).normalized()).toRotationMatrix();
  const SolidPointResult a = trans_iso_hyper_point(U, kRho0, p), b = trans_iso_hyper_point(R * U, kRho0, p);
  EXPECT_LE((b.stress - R * a.stress * R.transpose()).norm(), 1e-9 * a.stress.norm());
  EXPECT_GT(a.stress(0, 0) - a.stress(1, 1), 0.0);  // the stretched fibre carries tension
}

TEST(ModelTransIsoHyper, DeckParameters) {
  test::MapModelParameters p({{"bulk_modulus", 1e8}, {"c1", 2e6}, {"c2", 0.5e6}, {"c3", 1e5}, {"c4", 40},
                              {"c5", 5e8}, {"fiber_stretch", 1.06}, {"max_fiber_strain", 2},
                              {"max_matrix_strain", 2}, {"failure_option", 0}});
  EXPECT_THROW(create_constitutive_model("trans_iso_hyper", p), std::invalid_argument);  // no direction
  p.strings["direction_of_symm"] = "[0, 0, 2]";
  const auto m = create_constitutive_model("trans_iso_hyper", p);
  ASSERT_TRUE(m);
  // The fibre is e3 after normalization: stretch along z stiffens.
  test::PointState s(*m);
  ASSERT_EQ(test::step_point(*m, kRho0, s, Eigen::Vector3d(1 / std::sqrt(1.05), 1 / std::sqrt(1.05), 1.05).asDiagonal().toDenseMatrix(), 0.0), -1);
  TransIsoHyperParams q = ligament();
  q.a0 = Eigen::Vector3d::UnitZ();
  EXPECT_NEAR(s.stress(2, 2) - s.stress(0, 0),
              trans_iso_hyper_point(Eigen::Vector3d(1 / std::sqrt(1.05), 1 / std::sqrt(1.05), 1.05).asDiagonal(), kRho0, q).stress(2, 2) -
                  trans_iso_hyper_point(Eigen::Vector3d(1 / std::sqrt(1.05), 1 / std::sqrt(1.05), 1.05).asDiagonal(), kRho0, q).stress(0, 0),
              1e-6);
  p.strings["direction_of_symm"] = "[0, 0]";
  EXPECT_THROW(create_constitutive_model("trans_iso_hyper", p), std::invalid_argument);
  p.strings["direction_of_symm"] = "[0, 0, 1]";
  p.values["failure_option"] = 1;
  EXPECT_THROW(create_constitutive_model("trans_iso_hyper", p), std::logic_error);  // MissingFeature
}

}  // namespace
}  // namespace tephra
