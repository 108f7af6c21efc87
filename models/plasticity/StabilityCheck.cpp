// Stability checks, VT ch. 16 (see StabilityCheck.h for the equations and the Becker erratum).
#include "models/plasticity/StabilityCheck.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

namespace tephra {

Eigen::Matrix3d Tangent4::contract(const Eigen::Matrix3d& d) const {
  Eigen::Matrix3d s = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) s(i, j) += (*this)(i, j, k, l) * d(k, l);
  return s;
}

Tangent4 Tangent4::rotated(const Eigen::Matrix3d& Q) const {
  // Four successive single-index transformations (3^5 operations each).
  Tangent4 a = *this, b;
  for (int slot = 0; slot < 4; ++slot) {
    b.c.fill(0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l) {
            const int idx[4] = {i, j, k, l};
            for (int m = 0; m < 3; ++m) {
              int src[4] = {i, j, k, l};
              src[slot] = m;
              b(i, j, k, l) += Q(m, idx[slot]) * a(src[0], src[1], src[2], src[3]);
            }
          }
    a = b;
  }
  return a;
}

Tangent4 isotropic_tangent(double lambda, double mu) {
  Tangent4 C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l)
          C(i, j, k, l) = lambda * (i == j) * (k == l) + mu * ((i == k) * (j == l) + (i == l) * (j == k));
  return C;
}

Tangent4 j2_elastoplastic_tangent(double K, double mu, double H, const Eigen::Matrix3d& n_hat) {
  Tangent4 C = isotropic_tangent(K - 2.0 * mu / 3.0, mu);  // K I⊗I + 2μ I_dev
  const double c = 2.0 * mu * 3.0 * mu / (3.0 * mu + H);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) C(i, j, k, l) -= c * n_hat(i, j) * n_hat(k, l);
  return C;
}

Eigen::Matrix3d acoustic_tensor(const Tangent4& C, const Eigen::Vector3d& n) {
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) A(j, k) += n(i) * C(i, j, k, l) * n(l);
  return A;
}

namespace {
Eigen::Vector3d unit(double theta, double phi) {
  return {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
}
}  // namespace

double min_acoustic_determinant(const Tangent4& C, Eigen::Vector3d* n_min) {
  // det A(n) = det A(-n): the hemisphere θ ∈ [0, π/2], φ ∈ [0, 2π) suffices.
  // Grid of 5° (19 x 72 directions), then a compass search halving the step to 1e-6 rad.
  const double step0 = M_PI / 36.0;
  double best = 1e300, bt = 0, bp = 0;
  for (int a = 0; a <= 18; ++a)
    for (int b = 0; b < 72; ++b) {
      const double t = a * step0, p = b * step0;
      const double d = acoustic_tensor(C, unit(t, p)).determinant();
      if (d < best) best = d, bt = t, bp = p;
    }
  for (double h = step0 / 2; h > 1e-6; h /= 2) {
    bool moved = true;
    while (moved) {
      moved = false;
      const double cand[4][2] = {{bt + h, bp}, {bt - h, bp}, {bt, bp + h}, {bt, bp - h}};
      for (const auto& c : cand) {
        const double d = acoustic_tensor(C, unit(c[0], c[1])).determinant();
        if (d < best) best = d, bt = c[0], bp = c[1], moved = true;
      }
    }
  }
  if (n_min) *n_min = unit(bt, bp);
  return best;
}

BeckerQuadratic becker_quadratic(const Tangent4& c) {
  // Indices 0, 1, 2 = principal directions 1, 2, 3 (σ1 >= σ2 >= σ3).
  BeckerQuadratic q;
  q.a1 = c(2, 0, 0, 2) * c(2, 2, 2, 2);
  q.a2 = c(0, 0, 0, 0) * c(2, 2, 2, 2) + c(2, 0, 0, 2) * c(0, 2, 2, 0) -
         (c(0, 0, 2, 2) + c(2, 0, 2, 0)) * (c(2, 2, 0, 0) + c(0, 2, 0, 2));
  q.a3 = c(0, 0, 0, 0) * c(0, 2, 2, 0);
  return q;
}

bool becker_unstable(const BeckerQuadratic& q) {
  if (q.a1 == 0.0) return false;  // q linear: at most two real n3/n1, stable (16.41)
  const double disc = q.a2 * q.a2 - 4.0 * q.a1 * q.a3;
  if (disc < 0.0) return false;
  // Both roots β >= 0: product a3/a1 >= 0 and sum -a2/a1 >= 0.
  return q.a3 / q.a1 >= 0.0 && -q.a2 / q.a1 >= 0.0;
}

double drucker_product(const Tangent4& C, const Eigen::Matrix3d& D) { return C.contract(D).cwiseProduct(D).sum(); }

namespace {

// (C : D) : D <= 0 (StabilityCheck.h; Vaango's DruckerCheck: stable only when > 0).
bool drucker_unstable(const StabilityInput& in) { return drucker_product(in.tangent, in.deformation_rate) <= 0.0; }

bool becker_check(const StabilityInput& in) {
  // Principal frame, columns ordered σ1 >= σ2 >= σ3 (Eigen sorts ascending).
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(0.5 * (in.stress + in.stress.transpose()));
  Eigen::Matrix3d Q;
  for (int k = 0; k < 3; ++k) Q.col(k) = eig.eigenvectors().col(2 - k);
  return becker_unstable(becker_quadratic(in.tangent.rotated(Q)));
}

class NoCheck final : public StabilityCheck {
 public:
  std::string type() const override { return "none"; }
  bool unstable(const StabilityInput&) const override { return false; }
};
class Drucker final : public StabilityCheck {
 public:
  std::string type() const override { return "drucker"; }
  bool unstable(const StabilityInput& in) const override { return drucker_unstable(in); }
};
class Acoustic final : public StabilityCheck {
 public:
  std::string type() const override { return "acoustic"; }
  bool unstable(const StabilityInput& in) const override { return min_acoustic_determinant(in.tangent) <= 0.0; }
};
class Becker final : public StabilityCheck {
 public:
  std::string type() const override { return "becker"; }
  bool unstable(const StabilityInput& in) const override { return becker_check(in); }
};
class DruckerBecker final : public StabilityCheck {
 public:
  std::string type() const override { return "drucker_becker"; }
  bool unstable(const StabilityInput& in) const override { return drucker_unstable(in) || becker_check(in); }
};

template <class T>
std::unique_ptr<StabilityCheck> make(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<T>();
}
}  // namespace

const std::vector<SubModelEntry<StabilityCheck>>& stability_checks() {
  static const std::vector<SubModelEntry<StabilityCheck>> table = {
      {"none", {}, &make<NoCheck>},
      {"drucker", {}, &make<Drucker>},
      {"acoustic", {}, &make<Acoustic>},
      {"becker", {}, &make<Becker>},
      {"drucker_becker", {}, &make<DruckerBecker>},
  };
  return table;
}

std::unique_ptr<StabilityCheck> create_stability_check(const std::string& key, const ModelParameters& p,
                                                       const SubModelContext& ctx) {
  const auto* e = find_sub_model(stability_checks(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
