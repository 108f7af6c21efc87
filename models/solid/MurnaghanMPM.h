#pragma once
// Vaango's Murnaghan material, type "murnaghanMPM" (VT §3.4, eqs. 3.9-3.11;
// Vaango class MurnaghanMPM). Explicit MPM only.
//
//   sigma = -p I + 2 mu eta,  eta = dev(d), d = sym(l)     (3.9-3.10)
//   p(J) = (K/K') (J^{-K'} - 1)                            (3.11)
//
// K the initial bulk modulus [Pa], K' = dK/dp. Stored energy of the pressure
// part W(J) = (K/K') [(J^{1-K'} - 1)/(K' - 1) + J - 1] (Vaango reports none);
// viscous dissipation J 2 mu eta:eta dt per reference volume as plastic_work.
// Wave speed (Vaango): c^2 = K J^{-(K'+1)} / rho, rho = rho0/J. Small-strain
// moduli K and G = 0.
//
// MPMICE hooks: eq. 3.11 in density form, x = rho/rho0 (the MPM stress's pressure),
//   p = (K/K') (x^{K'} - 1),  dp/drho = (K/rho0) x^{K'-1} = c^2,  rho(p) = rho0 (1 + K' p/K)^{1/K'}
// (NaN for p < -K/K'). Gauge to the caller's reference pressure.
// Deviation: Vaango's MurnaghanMPM::computePressEOSCM returns P0 + that for rho >= rho0 but
// P0 x^{K/P0} for rho < rho0 (its ICE Murnaghan's tension branch). With K/P0 ~ 1e4-1e5 that
// branch drops to p = -P0 within 0.1 % of rho0 and its dp/drho underflows to 0 (no sound
// speed), and ERRATUM: its computeRhoMicroCM raises p/P0 to K/P0 instead of P0/K, so it does
// not invert its own pressure. Tephra keeps one EOS for MPM and MPMICE.
// The reference density is the material's <density> (as Vaango's hooks); the
// deck's <rho0> must equal it (checked when both are known).
#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct MurnaghanParams {
  double K = 0.0;          // <K> initial bulk modulus [Pa] (> 0)
  double Kprime = 0.0;     // <Kprime> dK/dp [-] (> 0)
  double P0 = 0.0;         // <pressure> Vaango's absolute reference pressure [Pa] (> 0; required, no role in the gauge hooks)
  double rho0 = 0.0;       // <rho0> [kg/m^3] (> 0; = the material density)
  double viscosity = 0.0;  // <viscosity> mu [Pa s] (>= 0)
};

double murnaghan_pressure(double J, const MurnaghanParams& p);  // eq. 3.11

class MurnaghanMPM final : public ConstitutiveModel {
 public:
  explicit MurnaghanMPM(const MurnaghanParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);

  std::string type() const override { return "murnaghanMPM"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  double bulk_modulus() const override { return p_.K; }
  double shear_modulus() const override { return 0.0; }
  bool hyperelastic() const override { return p_.viscosity == 0.0; }
  std::optional<SolidEosPoint> pressure_at_density(double rho, double density0, double T) const override;
  std::optional<double> density_at_pressure(double p_gauge, double density0, double T) const override;

 private:
  MurnaghanParams p_;
};

}  // namespace tephra
