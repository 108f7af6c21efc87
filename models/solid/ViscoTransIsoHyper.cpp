#include "models/solid/ViscoTransIsoHyper.h"

#include <cmath>
#include <string>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {
using RowMap = Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>;
const std::vector<double> kZero9(9, 0.0);
}  // namespace

double ViscoTransIsoHyper::shear_modulus() const {
  double sum = 1.0;
  for (const PronyTerm& t : terms_) sum += t.y;
  return sum * p_.shear_modulus();
}

std::vector<HistoryVariable> ViscoTransIsoHyper::history() const {
  std::vector<HistoryVariable> h = {
      {"SeDev", 9, kZero9, "elastic deviatoric stress pulled back, J F^-1 dev(sigma_e) F^-T, of the last step [Pa]"}};
  for (size_t k = 0; k < terms_.size(); ++k)
    h.push_back({"Hvisco" + std::to_string(k + 1), 9, kZero9,
                 "hereditary integral of Prony term " + std::to_string(k + 1) + " (PK2 frame) [Pa]"});
  return h;
}

long ViscoTransIsoHyper::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const Eigen::Matrix3d& F = in.F_new[i];
    const double J = F.determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const SolidPointResult e = trans_iso_hyper_point(F, in.density0, p_);
    const Eigen::Matrix3d Finv = F.inverse();
    const Eigen::Matrix3d dev = e.stress - e.stress.trace() / 3.0 * I;
    const Eigen::Matrix3d Se = J * Finv * dev * Finv.transpose();
    RowMap Se_old(&out.history[0][9 * i]);
    const Eigen::Matrix3d dSe = Se - Eigen::Matrix3d(Se_old);
    Eigen::Matrix3d Hsum = Eigen::Matrix3d::Zero();
    for (size_t k = 0; k < terms_.size(); ++k) {
      RowMap H(&out.history[k + 1][9 * i]);
      const double x = in.dt / terms_[k].tau;
      H = std::exp(-x) * Eigen::Matrix3d(H) + std::exp(-0.5 * x) * dSe;  // Simo (1987) recursion
      Hsum += terms_[k].y * Eigen::Matrix3d(H);
    }
    Se_old = Se;
    out.stress[i] = e.stress + (F * Hsum * F.transpose()) / J;
    // Instantaneous moduli bound the wave speed: the deviatoric part stiffens by (1 + sum y_i).
    const double Gi = shear_modulus(), G = p_.shear_modulus();
    out.wave_speed[i] = std::sqrt(e.wave_speed * e.wave_speed + 4.0 * (Gi - G) / 3.0 * J / in.density0);
    out.energy_density[i] = e.energy_density;
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return out.stress[i].allFinite();
  });
}

ConstitutiveModelP ViscoTransIsoHyper::create(const ModelParameters& params) {
  const TransIsoHyperParams p = read_trans_iso_hyper_params(params, "visco_trans_iso_hyper");
  std::vector<PronyTerm> terms;
  for (int k = 1; k <= 6; ++k) {
    const std::string yk = "y" + std::to_string(k), tk = "t" + std::to_string(k);
    const PronyTerm t{params.get_double(yk, 0.0), params.get_double(tk, 0.0)};
    if (!(t.y >= 0.0)) params.fail(yk, yk + " (Prony weight) must be >= 0");
    if (!(t.tau >= 0.0)) params.fail(tk, tk + " (relaxation time) must be >= 0");
    if (t.y == 0.0) continue;
    if (!(t.tau > 0.0)) params.fail(tk, tk + " (relaxation time of term " + yk + " > 0) must be > 0");
    terms.push_back(t);
  }
  return std::make_shared<ViscoTransIsoHyper>(p, std::move(terms));
}

}  // namespace tephra
