#include "models/geo/CamClay.h"

#include <cmath>
#include <memory>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"
#include "models/solid/PolarNewton.h"

namespace tephra {

namespace {

using M3 = Eigen::Matrix3d;

struct CamClayPointState {
  M3 eps_e;            // unrotated elastic strain
  double pc = 0;       // consolidation pressure
  double dgamma = 0;   // plastic multiplier of the step
  double dissipation = 0;  // sum of dgamma p p_c over the sub-increments (per current volume)
};

// One elastic predictor + return over the strain increment de. False when the return fails.
bool camclay_increment(const CamClayParams& c, CamClayPointState& s, const M3& de) {
  const M3 I = M3::Identity();
  const M3 eps_tr = s.eps_e + de;
  const double ev_tr = eps_tr.trace();
  const M3 e_tr = eps_tr - (ev_tr / 3.0) * I;
  const double es_tr = std::sqrt(2.0 / 3.0) * e_tr.norm();
  const BorjaInvariants v = borja_invariants(c.elastic, ev_tr, es_tr);
  const double f = camclay_yield(c.M, v.p, v.q, s.pc);
  if (!(f > 1e-13 * s.pc * s.pc)) {  // elastic (within round-off of the surface)
    s.eps_e = eps_tr;
    return std::isfinite(f);
  }
  const CamClayReturnResult r = camclay_return(c, ev_tr, es_tr, s.pc);
  if (!r.converged) return false;
  // eps^e = eps_v/3 I + sqrt(3/2) eps_s n_trial (VT §20.3.1, n unchanged by the return)
  s.eps_e = (r.eps_v / 3.0) * I;
  if (es_tr > 0.0) s.eps_e += (r.eps_s / es_tr) * e_tr;
  s.pc = r.pc;
  s.dgamma += r.dgamma;
  s.dissipation += r.dgamma * r.inv.p * r.pc;
  return true;
}

}  // namespace

long CamClay::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const double W0 = borja_energy(p_.elastic, 0.0, 0.0);
  return for_each_point(in.F_new.size(), [&](size_t i) {
    const double J0 = in.F_old[i].determinant(), J = in.F_new[i].determinant();
    if (!(J0 > 0.0) || !(J > 0.0) || !std::isfinite(J) || !std::isfinite(J0)) return false;
    double* eps_col = out.history[0].data() + 9 * i;
    double& pc_col = out.history[1][i];
    double& dgamma_col = out.history[2][i];
    const PolarDecomposition a = polar_decomposition_newton(in.F_old[i]);
    const PolarDecomposition b = polar_decomposition_newton(in.F_new[i]);
    const M3 G = (b.U - a.U) * (0.5 * (a.U + b.U)).inverse();
    const M3 de = 0.5 * (G + G.transpose());

    CamClayPointState s0;
    s0.eps_e = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(eps_col);
    s0.pc = pc_col;
    CamClayPointState s = s0;
    bool ok = false;
    for (int m = 1; m <= 1024 && !ok; m *= 2) {  // sub-increments when the return fails
      s = s0;
      ok = true;
      for (int k = 0; k < m && ok; ++k) ok = camclay_increment(p_, s, de / double(m));
    }
    if (!ok) return false;

    BorjaInvariants v;
    const M3 tau = borja_stress(p_.elastic, s.eps_e, &v);
    M3 sigma = b.R * tau * b.R.transpose();
    sigma = (0.5 * (sigma + sigma.transpose())).eval();  // eval: no aliasing
    if (!sigma.allFinite()) return false;
    Eigen::Map<Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> eps_out(eps_col);
    eps_out = s.eps_e;
    pc_col = s.pc;
    dgamma_col = s.dgamma;
    out.stress[i] = sigma;
    const double ev = s.eps_e.trace();
    const double es = std::sqrt(2.0 / 3.0) * (s.eps_e - (ev / 3.0) * M3::Identity()).norm();
    out.energy_density[i] = borja_energy(p_.elastic, ev, es) - W0;
    const double K = -v.p / p_.elastic.kappa;
    out.wave_speed[i] = std::sqrt((K + 4.0 * v.mu / 3.0) * J / in.density0);
    out.plastic_work[i] = J * s.dissipation;
    out.heating[i] = 0.0;
    return std::isfinite(out.wave_speed[i]);
  });
}

std::vector<HistoryVariable> CamClay::history() const {
  return {{"elasticStrain", 9, std::vector<double>(9, 0.0), "elastic strain eps^e in the unrotated frame [-]"},
          {"p_c", 1, {p_.pc0}, "consolidation pressure p_c (tension positive, < 0) [Pa]"},
          {"deltaGamma", 1, {0.0}, "plastic multiplier of the last step [1/Pa]"}};
}

double CamClay::bulk_modulus() const { return -borja_invariants(p_.elastic, 0.0, 0.0).p / p_.elastic.kappa; }
double CamClay::shear_modulus() const { return borja_invariants(p_.elastic, 0.0, 0.0).mu; }

std::optional<SolidEosPoint> CamClay::pressure_at_density(double rho, double density0, double) const {
  const double p = borja_mean_stress_at_density(p_.elastic, rho, density0);
  const double p_ref = borja_invariants(p_.elastic, 0.0, 0.0).p;
  SolidEosPoint e;
  e.pressure = -(p - p_ref);
  // dP/drho = -(dp/d eps_v)(d eps_v/drho) = -(-p/kt)(-rho0/rho^2)
  e.dp_drho = -p * density0 / (p_.elastic.kappa * rho * rho);
  e.c2 = (-p / p_.elastic.kappa) / rho;
  return e;
}

std::optional<double> CamClay::density_at_pressure(double p_gauge, double density0, double) const {
  const double p_ref = borja_invariants(p_.elastic, 0.0, 0.0).p;
  return borja_density_at_mean_stress(p_.elastic, p_ref - p_gauge, density0);
}

namespace {
const ModelParameters& required_block(const ModelParameters& params, const std::string& name, const std::string& key) {
  const ModelParameters* b = params.block(name);
  if (!b) params.fail(name, "camclay needs <" + name + " type=\"" + key + "\">");
  if (b->type_attribute() != key)
    b->fail("type", "camclay needs <" + name + " type=\"" + key + "\">, not '" + b->type_attribute() +
                        "' (VT ch. 20: the Borja/Cam-Clay sub-models work only together)");
  return *b;
}
}  // namespace

ConstitutiveModelP CamClay::create(const ModelParameters& params) {
  CamClayParams c;
  const ModelParameters& eos = required_block(params, "equation_of_state", "borja_pressure");
  c.elastic.p0 = eos.get_double("p0");
  c.elastic.alpha = eos.get_double("alpha");
  c.elastic.kappa = eos.get_double("kappatilde");
  c.elastic.eps_v0 = eos.get_double("epse_v0");
  if (!(c.elastic.p0 < 0.0)) eos.fail("p0", "must be < 0 (tension-positive mean stress)");
  if (!(c.elastic.alpha >= 0.0)) eos.fail("alpha", "must be >= 0");
  if (!(c.elastic.kappa > 0.0)) eos.fail("kappatilde", "must be > 0");
  const ModelParameters& shear = required_block(params, "shear_modulus_model", "borja_shear");
  c.elastic.mu0 = shear.get_double("mu0");
  if (!(c.elastic.mu0 > 0.0)) shear.fail("mu0", "must be > 0");
  const ModelParameters& yield = required_block(params, "yield_condition", "camclay");
  c.M = yield.get_double("M");
  if (!(c.M > 0.0)) yield.fail("M", "must be > 0");
  const ModelParameters& iv = required_block(params, "internal_variable_model", "borja_consolidation_pressure");
  c.pc0 = iv.get_double("pc0");
  c.lambda = iv.get_double("lambdatilde");
  if (!(c.pc0 < 0.0)) iv.fail("pc0", "must be < 0 (tension positive)");
  if (!(c.lambda > c.elastic.kappa)) iv.fail("lambdatilde", "must be > kappatilde of the equation_of_state");
  if (iv.has("kappatilde") && iv.get_double("kappatilde") != c.elastic.kappa)
    iv.fail("kappatilde", "must equal the equation_of_state's kappatilde");
  // The reference state must be admissible: f(p(0,0), 0, pc0) <= 0, i.e. pc0 <= p(0,0).
  const double p_ref = borja_invariants(c.elastic, 0.0, 0.0).p;
  if (camclay_yield(c.M, p_ref, 0.0, c.pc0) > 1e-12 * c.pc0 * c.pc0)
    iv.fail("pc0", "the reference state p = p0 exp(epse_v0/kappatilde) = " + std::to_string(p_ref) +
                       " Pa lies outside the yield surface: pc0 must be <= it");
  return std::make_shared<CamClay>(c);
}

}  // namespace tephra
