#include "models/solid/ProgramBurn.h"

#include <cmath>
#include <sstream>

#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/VectorParameter.h"
#include "models/solid/PointLoop.h"

namespace tephra {

double program_burn_fraction(const Eigen::Vector3d& x, double t, double mass, const ProgramBurnParams& p) {
  const double n = p.direction.norm();
  const double dist = n > 0.0 ? std::abs(p.direction.dot(x - p.start)) / n : (x - p.start).norm();
  const double t_b = dist / p.D;
  const double dL = 1.5 * std::cbrt(mass / p.rho0) / p.D;
  const double tau = t - p.T0;
  if (!(tau >= t_b)) return 0.0;
  const double F = (tau - t_b) / dL;
  return F > 0.96 ? 1.0 : F;
}

std::vector<HistoryVariable> ProgramBurn::history() const {
  return {{"progressF", 1, {0.0}, "programmed burned fraction F [-]"}};
}

long ProgramBurn::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const size_t n = in.F_new.size();
  if (in.position.size() != n || in.reference_volume.size() != n) return n > 0 ? 0 : -1;  // no point context
  const double t_n = in.time - in.dt;  // the start of the step (Vaango: the old simulation time)
  const JwlppParams& e = p_.eos;
  return for_each_point(n, [&](size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const double mass = in.density0 * in.reference_volume[i];
    const double F = program_burn_fraction(in.position[i], t_n, mass, p_);
    out.history[0][i] = F;
    const double pM = jwlpp_murnaghan_pressure(J, e), pJ = jwlpp_jwl_pressure(J, e);
    const double p = (1.0 - F) * pM + F * pJ;
    const double rho = p_.rho0 / J;  // Vaango's current density uses <rho0>
    double dp_drho;
    if (F > 0.0) {
      const double P1 = e.A * std::exp(-e.R1 * J), P2 = e.B * std::exp(-e.R2 * J),
                   P3 = e.C * std::pow(1.0 / J, 1.0 + e.omega);
      dp_drho = (e.R1 * P1 + e.R2 * P2) * p_.rho0 / (rho * rho) + (1.0 + e.omega) / rho * P3;
    } else {
      dp_drho = std::pow(rho / p_.rho0, e.n - 1.0) / (e.kappa * p_.rho0);
    }
    out.stress[i] = -p * Eigen::Matrix3d::Identity();
    out.wave_speed[i] = std::sqrt(dp_drho);
    out.energy_density[i] = 0.0;
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return std::isfinite(p) && std::isfinite(out.wave_speed[i]);
  });
}

ConstitutiveModelP ProgramBurn::create(const ModelParameters& params) {
  ProgramBurnParams p;
  auto pos = [&](const char* n, double& v) {
    v = params.get_double(n);
    if (!(v > 0.0) || !std::isfinite(v)) params.fail(n, std::string(n) + " must be > 0");
  };
  pos("K", p.eos.kappa);
  pos("n", p.eos.n);
  p.eos.A = params.get_double("A");
  p.eos.B = params.get_double("B");
  p.eos.C = params.get_double("C");
  p.eos.R1 = params.get_double("R1");
  p.eos.R2 = params.get_double("R2");
  p.eos.omega = params.get_double("om");
  pos("rho0", p.rho0);
  pos("D", p.D);
  p.start = vector_parameter(params, "starting_location");
  if (const auto dir = optional_vector_parameter(params, "direction_if_plane")) p.direction = *dir;
  p.T0 = params.get_double("T0", 0.0);
  if (!std::isfinite(p.T0)) params.fail("T0", "T0 must be finite");
  return std::make_shared<ProgramBurn>(p);
}

}  // namespace tephra
