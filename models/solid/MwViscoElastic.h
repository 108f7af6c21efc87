#pragma once
// Vaango's simplified Maxwell-Wiechert viscoelastic solid, type "mw_visco_elastic"
// (VT §2.2 item 23 / §7.4, "partly" described; the law is Vaango's MWViscoElastic:
// a standard linear solid, an elastic spring (K_e, G_e) in parallel with a
// Maxwell element (spring K_ve, G_ve in series with dashpots eta_v, eta_d)).
// Rate form, tension positive, d = sym(l), d' = dev(d):
//   sigma   = sigma_e + s_ve - p_ve I
//   sigma_e_dot = K_e tr(d) I + 2 G_e d'                       (elastic branch)
//   s_ve_dot / (2 G_ve) + s_ve / eta_d = d'                    (deviatoric Maxwell, tau_d = eta_d / (2 G_ve))
//   p_ve_dot / K_ve + 3 p_ve / eta_v  = -tr(d)                 (volumetric Maxwell, tau_v = eta_v / (3 K_ve))
// Each Maxwell element is integrated by backward Euler (as Vaango):
//   s_ve_{n+1} = beta_d (s_ve_n + 2 G_ve dev(de)),  beta_d = eta_d / (eta_d + 2 G_ve dt)
//   p_ve_{n+1} = beta_v (p_ve_n - K_ve tr(de)),     beta_v = eta_v / (eta_v + 3 K_ve dt)
// Deviation (objectivity): Vaango adds the increments in the spatial frame with
// no rotation; Tephra integrates in the unrotated frame of the polar
// decomposition F = R U (as hypo_elastic: de = the midpoint increment of U), so
// a superposed rotation rotates the stress. History (unrotated frame):
// p.stress_e (9), p.stress_ve_d (9), p.stress_ve_v (1) (Vaango's labels pStress_e, pStress_ve_d, pStress_ve_v).
// Stored energy J [|s_e|^2/(4 G_e) + p_e^2/(2 K_e) + |s_ve|^2/(4 G_ve) + p_ve^2/(2 K_ve)]
// (Vaango lumps the two pressures into p^2/(2(K_e + K_ve))); dissipation of the step
// J (|s_ve|^2 / eta_d + 3 p_ve^2 / eta_v) dt >= 0 reported as plastic_work.
// Wave speed c^2 = (K + 4G/3) J / rho0 with the instantaneous K = K_e + K_ve, G = G_e + G_ve.
// MPMICE hooks (Vaango MWViscoElastic::computePressEOSCM): p = K (1 - rho0/rho),
// dp/drho = K rho0 / rho^2, c^2 = (K + 4G/3)/rho (Vaango returns its square root:
// erratum), rho(p) = rho0 / (1 - p/K) (+inf for p >= K).
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct MwViscoElasticParams {
  double G_e = 0, K_e = 0;      // <e_shear_modulus>, <e_bulk_modulus> [Pa] (> 0)
  double G_ve = 0, K_ve = 0;    // <ve_shear_modulus>, <ve_bulk_modulus> [Pa] (>= 0)
  double eta_v = 0, eta_d = 0;  // <ve_volumetric_viscosity>, <ve_deviatoric_viscosity> [Pa s] (>= 0)
};

class MwViscoElastic final : public ConstitutiveModel {
 public:
  explicit MwViscoElastic(const MwViscoElasticParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "mw_visco_elastic"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.K_e + p_.K_ve; }
  double shear_modulus() const override { return p_.G_e + p_.G_ve; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  MwViscoElasticParams p_;
};

}  // namespace tephra
