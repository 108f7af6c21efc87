// The deformation-gradient algorithms (mpm/DeformationGradient.h) and the
// artificial bulk viscosity (mpm/ArtificialViscosity.h) against closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpm/ArtificialViscosity.h"
#include "mpm/DeformationGradient.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/Transfers.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

// A = dt W for a rotation rate omega about z: exp(A) = R_z(omega dt) exactly.
Mat3 skew_z(double a) {
  Mat3 A = Mat3::Zero();
  A(0, 1) = -a;
  A(1, 0) = a;
  return A;
}
Mat3 rotation_z(double a) {
  Mat3 R = Mat3::Identity();
  R(0, 0) = R(1, 1) = std::cos(a);
  R(0, 1) = -std::sin(a);
  R(1, 0) = std::sin(a);
  return R;
}

TEST(DeformationGradient, FirstOrderIsIPlusA) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  Mat3 A;
  for (int k = 0; k < 9; ++k) A.data()[k] = u(rng);
  EXPECT_EQ(deformation_gradient_increment(DeformationGradientAlgorithm::FirstOrder, A, 7), Mat3::Identity() + A);
  // Subcycling uses one sub-step while |A| < 1 (Vaango: s = max(1, 2 floor|A|)).
  EXPECT_EQ(deformation_gradient_increment(DeformationGradientAlgorithm::Subcycling, A, 1), Mat3::Identity() + A);
}

// The truncated series sum_{k<=N} A^k/k! differs from exp(A) = R by the first
// omitted term, |A|^{N+1}/(N+1)! (leading order); for a = 0.05 and N = 1..6
// the ratio error / (a^{N+1}/(N+1)!) -> 1 (a norm factor sqrt 2 from the two
// rotated axes).
TEST(DeformationGradient, TaylorSeriesErrorIsTheFirstOmittedTerm) {
  const double a = 0.05;
  const Mat3 R = rotation_z(a);
  for (int N = 1; N <= 6; ++N) {
    const Mat3 inc = deformation_gradient_increment(DeformationGradientAlgorithm::TaylorSeries, skew_z(a), N);
    const double err = (inc - R).norm();
    const double term = std::sqrt(2.0) * std::pow(a, N + 1) / std::tgamma(N + 2);
    EXPECT_NEAR(err / term, 1.0, 0.05) << "N = " << N;
  }
  // N = 10: exp(A) to round-off, and orthogonal to round-off.
  const Mat3 inc = deformation_gradient_increment(DeformationGradientAlgorithm::TaylorSeries, skew_z(a), 10);
  EXPECT_LT((inc - R).norm(), 1e-15);
  EXPECT_LT((inc.transpose() * inc - Mat3::Identity()).norm(), 1e-15);
}

// First order: (I + A)^T (I + A) = I + a^2 (I - e_z e_z) for a rotation:
// the spurious stretch of one step is exactly a^2/2 per in-plane axis.
TEST(DeformationGradient, FirstOrderRotationStretchesByHalfASquared) {
  const double a = 0.01;
  const Mat3 inc = deformation_gradient_increment(DeformationGradientAlgorithm::FirstOrder, skew_z(a), 1);
  const Mat3 C = inc.transpose() * inc;
  EXPECT_NEAR(C(0, 0), 1.0 + a * a, 1e-16);
  EXPECT_NEAR(C(1, 1), 1.0 + a * a, 1e-16);
  EXPECT_EQ(C(2, 2), 1.0);
}

// Cayley-Hamilton evaluates the same truncated series as a0 I + a1 A + a2 A^2:
// equal to the Taylor sum to round-off for any A and N.
TEST(DeformationGradient, CayleyHamiltonEqualsTaylorSeries) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.3, 0.3);
  for (int trial = 0; trial < 20; ++trial) {
    Mat3 A;
    for (int k = 0; k < 9; ++k) A.data()[k] = u(rng);
    for (int N = 1; N <= 8; ++N) {
      const Mat3 t = deformation_gradient_increment(DeformationGradientAlgorithm::TaylorSeries, A, N);
      const Mat3 c = deformation_gradient_increment(DeformationGradientAlgorithm::CayleyHamilton, A, N);
      EXPECT_LT((t - c).norm(), 1e-14) << "N = " << N;
    }
  }
}

// Subcycling with |A| >= 1: s = 2 floor|A| sub-steps of (I + A/s).
TEST(DeformationGradient, SubcyclingSplitsLargeIncrements) {
  const Mat3 A = 1.7 * Mat3::Identity();  // |A| = 1.7 sqrt 3 = 2.94 -> s = 4
  const Mat3 inc = deformation_gradient_increment(DeformationGradientAlgorithm::Subcycling, A, 1);
  EXPECT_NEAR(inc(0, 0), std::pow(1.0 + 1.7 / 4.0, 4), 1e-14);
  EXPECT_EQ(inc(0, 1), 0.0);
}

TEST(DeformationGradient, NamesAreVaangos) {
  EXPECT_EQ(deformation_gradient_algorithm("taylor_series"), DeformationGradientAlgorithm::TaylorSeries);
  EXPECT_EQ(deformation_gradient_algorithm("cayley_hamilton"), DeformationGradientAlgorithm::CayleyHamilton);
  EXPECT_THROW(deformation_gradient_algorithm("exact"), std::invalid_argument);
}

// q = rho (A1 c |tr D| h + A2 (tr D h)^2) in compression, 0 in expansion.
TEST(ArtificialViscosity, ClosedFormInCompressionZeroInExpansion) {
  const ArtificialViscosityCoefficients a;  // Vaango's defaults 0.2, 2.0
  EXPECT_EQ(a.A1, 0.2);
  EXPECT_EQ(a.A2, 2.0);
  const double rho = 1700, c = 187.9, h = 0.002, trD = -50.0;
  EXPECT_DOUBLE_EQ(artificial_bulk_viscosity(trD, c, rho, h, a),
                   rho * (0.2 * c * 50.0 * h + 2.0 * (50.0 * h) * (50.0 * h)));
  EXPECT_EQ(artificial_bulk_viscosity(0.0, c, rho, h, a), 0.0);
  EXPECT_EQ(artificial_bulk_viscosity(+50.0, c, rho, h, a), 0.0);
}

// q enters the internal force as -q I added to the stress (Vaango's
// computeInternalForce): particles with (sigma, q) give the same f_int as
// particles with (sigma - q I, 0), bit for bit up to the one subtraction.
TEST(ArtificialViscosity, EntersTheInternalForceAsMinusQIdentity) {
  NodeGrid g;
  g.origin = Vec3(0.0, 0.0, 0.0);
  g.h = Vec3(0.1, 0.1, 0.1);
  g.n = IntVec3(5, 5, 5);
  g.reset();
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.05, 0.35);
  Particles a, b;
  for (int i = 0; i < 20; ++i) {
    const Vec3 x(u(rng), u(rng), u(rng));
    a.add(x, Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, i);
    b.add(x, Vec3::Zero(), 1.0, 1e-3, 300.0, 0.0, i);
    Mat3 sig;
    for (int k = 0; k < 9; ++k) sig.data()[k] = u(rng) - 0.2;
    a.stress.back() = sig;
    a.q.back() = 0.5 * u(rng);
    b.stress.back() = sig - a.q.back() * Mat3::Identity();
  }
  Stencils s;
  ASSERT_EQ(compute_stencils(a, g, InterpolatorSpec{}, s), -1);
  compute_internal_force(a, s, g);
  const std::vector<Vec3> fa = g.internal_force;
  g.reset();
  compute_internal_force(b, s, g);
  for (std::size_t n = 0; n < fa.size(); ++n) EXPECT_LT((fa[n] - g.internal_force[n]).norm(), 1e-15) << n;
}

}  // namespace
}  // namespace tephra

namespace tephra {
namespace {

// The out-of-place update F = inc(dt L) F_old (MpmComponent keeps F_n that
// way, without a copy) is the same bits as the in-place one, every algorithm.
TEST(MpmDeformationGradient, OutOfPlaceUpdateIsTheInPlaceBits) {
  std::vector<Mat3> L(300), F_old(300);
  for (std::size_t i = 0; i < L.size(); ++i) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        L[i](r, c) = std::sin(1.0 + i + 3 * r + c);
        F_old[i](r, c) = (r == c ? 1.0 : 0.0) + 0.1 * std::cos(2.0 + i + 5 * r + c);
      }
  }
  for (auto alg : {DeformationGradientAlgorithm::FirstOrder, DeformationGradientAlgorithm::Subcycling,
                   DeformationGradientAlgorithm::TaylorSeries, DeformationGradientAlgorithm::CayleyHamilton}) {
    std::vector<Mat3> in_place = F_old, out(7, Mat3::Zero());  // wrong size on purpose: resized
    update_deformation_gradients(alg, 4, 0.3, L, in_place);
    update_deformation_gradients(alg, 4, 0.3, L, F_old, out);
    EXPECT_EQ(out, in_place);
    EXPECT_NE(out, F_old);
  }
}

}  // namespace
}  // namespace tephra
