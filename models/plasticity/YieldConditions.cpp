// Yield conditions, VT ch. 8.
#include <cmath>

#include "models/plasticity/YieldCondition.h"

namespace tephra {

double von_mises_stress(const Eigen::Matrix3d& xi) {
  const Eigen::Matrix3d s = xi - xi.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * s.cwiseProduct(s).sum());
}

namespace {
Eigen::Matrix3d deviator(const Eigen::Matrix3d& a) { return a - a.trace() / 3.0 * Eigen::Matrix3d::Identity(); }

// von Mises, eq. 8.1-8.8: f = σ_eff - σ_y; ∂f/∂σ = (3/2) s/σ_eff (= N of eq. 8.3 scaled).
class VonMises final : public YieldCondition {
 public:
  std::string type() const override { return "von_mises"; }
  double value(const Eigen::Matrix3d& xi, double sy, double) const override { return von_mises_stress(xi) - sy; }
  Eigen::Matrix3d gradient(const Eigen::Matrix3d& xi, double, double) const override {
    const double se = von_mises_stress(xi);
    return se > 0 ? Eigen::Matrix3d(1.5 * deviator(xi) / se) : Eigen::Matrix3d::Zero();
  }
};

// Gurson-Tvergaard-Needleman, eq. 8.9-8.10:
//   f = (σ_eff/σ_y)² + 2 q_1 φ* cosh(q_2 tr ξ/(2σ_y)) - (1 + q_3 φ*²),
//   φ* = φ (φ <= φ_c), φ_c + k(φ - φ_c) otherwise.
// Erratum (inventory ch. 8): ch. 17.4/18.8.2 use another φ*; eq. 8.10 (the
// form with the deck tags k, f_c) is used.
class Gurson final : public YieldCondition {
 public:
  double q1, q2, q3, k, fc;
  std::string type() const override { return "gurson"; }
  double phi_star(double phi) const { return phi <= fc ? phi : fc + k * (phi - fc); }
  double value(const Eigen::Matrix3d& xi, double sy, double phi) const override {
    const double se = von_mises_stress(xi), ps = phi_star(phi);
    return se * se / (sy * sy) + 2.0 * q1 * ps * std::cosh(q2 * xi.trace() / (2.0 * sy)) - (1.0 + q3 * ps * ps);
  }
  Eigen::Matrix3d gradient(const Eigen::Matrix3d& xi, double sy, double phi) const override {
    const double ps = phi_star(phi);
    return 3.0 * deviator(xi) / (sy * sy) +
           q1 * q2 * ps / sy * std::sinh(q2 * xi.trace() / (2.0 * sy)) * Eigen::Matrix3d::Identity();
  }
};

// Rousselier, eq. 8.19-8.23: f = σ_eff/(1-φ) + D σ_1 φ exp(tr ξ/(3(1-φ)σ_1)) - σ_y.
// Erratum (8.23 drops the I): the hydrostatic part of ∂f/∂σ is
// D φ/(3(1-φ)) exp(...) I. Deck spelling <sig_1> (RousselierYieldSteel.xml) and
// the schema's <sigma_1> are both accepted.
class Rousselier final : public YieldCondition {
 public:
  double D, s1;
  std::string type() const override { return "rousselier"; }
  double value(const Eigen::Matrix3d& xi, double sy, double phi) const override {
    return von_mises_stress(xi) / (1.0 - phi) + D * s1 * phi * std::exp(xi.trace() / (3.0 * (1.0 - phi) * s1)) - sy;
  }
  Eigen::Matrix3d gradient(const Eigen::Matrix3d& xi, double, double phi) const override {
    const double se = von_mises_stress(xi);
    Eigen::Matrix3d g = se > 0 ? Eigen::Matrix3d(1.5 * deviator(xi) / (se * (1.0 - phi))) : Eigen::Matrix3d::Zero();
    g += D * phi / (3.0 * (1.0 - phi)) * std::exp(xi.trace() / (3.0 * (1.0 - phi) * s1)) * Eigen::Matrix3d::Identity();
    return g;
  }
};

std::unique_ptr<YieldCondition> make_vm(const ModelParameters&, const SubModelContext&) {
  return std::make_unique<VonMises>();
}
std::unique_ptr<YieldCondition> make_gurson(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<Gurson>();
  m->q1 = positive_parameter(p, "q1");
  m->q2 = positive_parameter(p, "q2");
  m->q3 = positive_parameter(p, "q3");
  m->k = positive_parameter(p, "k");
  m->fc = positive_parameter(p, "f_c");
  return m;
}
std::unique_ptr<YieldCondition> make_rousselier(const ModelParameters& p, const SubModelContext&) {
  auto m = std::make_unique<Rousselier>();
  m->D = positive_parameter(p, "D");
  if (p.has("sig_1") && p.has("sigma_1")) p.fail("sig_1", "given twice (as <sig_1> and <sigma_1>)");
  m->s1 = positive_parameter(p, p.has("sig_1") ? "sig_1" : "sigma_1");
  return m;
}
}  // namespace

const std::vector<SubModelEntry<YieldCondition>>& yield_conditions() {
  static const std::vector<SubModelEntry<YieldCondition>> table = {
      {"von_mises", {"vonMises"}, &make_vm},
      {"gurson", {}, &make_gurson},
      {"rousselier", {}, &make_rousselier},
  };
  return table;
}

std::unique_ptr<YieldCondition> create_yield_condition(const std::string& key, const ModelParameters& p,
                                                       const SubModelContext& ctx) {
  const auto* e = find_sub_model(yield_conditions(), key);
  return e ? e->create(p, ctx) : nullptr;
}

}  // namespace tephra
