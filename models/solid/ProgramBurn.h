#pragma once
// Vaango's "program_burn" (VT ch. 2 list item 5; Vaango class ProgramBurn): an
// explosive whose burn is PROGRAMMED -- the burn front leaves <starting_location>
// at time <T0> and travels at the detonation speed <D>, so each point's burned
// fraction is a function of its position and the time (the point context,
// SolidUpdateInput::position, time, reference_volume). Pressure-only:
//
//   dist = |x_p - x_0|                           (point ignition, <direction_if_plane> = 0)
//        = |n . (x_p - x_0)| / |n|               (plane ignition, n = <direction_if_plane>)
//   t_b  = dist / D                              arrival time of the front
//   dL   = 1.5 (m_p / rho0)^{1/3} / D            time to burn through the particle
//   F    = 0 for t < t_b;  (t - t_b)/dL, and 1 once that exceeds 0.96    (t = time - T0)
//   p    = (1 - F) p_M(J) + F p_JWL(J)           (Souers' JWL++ mixture, VT eq. 3.15)
//   p_M  = (J^{-n} - 1)/(n K)                    (unreacted Murnaghan, K a COMPRESSIBILITY [1/Pa], eq. 3.16)
//   p_JWL = A e^{-R1 J} + B e^{-R2 J} + C J^{-(1+om)}                     (eq. 3.17)
//   sigma = -p I
// t is the time at the START of the step and x_p the position then (Vaango
// uses the old simulation time and position). m_p/rho0 = V0 rho_0,mat / rho0 with
// V0 the particle's reference volume and rho_0,mat the material density (Vaango
// divides the particle mass by the <rho0> parameter). F is recomputed each step
// (not a rate law); history "progressF" is its output (Vaango's p.progressF).
// Wave speed: dp/drho of the unreacted Murnaghan, (1/(K rho0)) (rho/rho0)^{n-1},
// while F = 0; of the JWL otherwise (Vaango). Stored energy 0, heating 0.
// No MPMICE hooks (Vaango's computeRhoMicroCM is "not yet implemented").
// Parameters: <K>, <n>, <A>, <B>, <C>, <R1>, <R2>, <om>, <rho0>, <starting_location>,
// <D> required; <direction_if_plane> (default [0,0,0]: point ignition), <T0> (default 0).
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/JwlppMPM.h"

namespace tephra {

struct ProgramBurnParams {
  JwlppParams eos;  // kappa = <K>, n, A, B, C, R1, R2, omega = <om>
  double rho0 = 0;  // <rho0> [kg/m^3]
  Eigen::Vector3d start = Eigen::Vector3d::Zero();      // <starting_location> [m]
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();  // <direction_if_plane> (0: point)
  double D = 0;   // <D> detonation velocity [m/s]
  double T0 = 0;  // <T0> ignition time [s]
};

// The burned fraction at position x, time t (absolute), for a particle of mass m.
double program_burn_fraction(const Eigen::Vector3d& x, double t, double mass, const ProgramBurnParams& p);

class ProgramBurn final : public ConstitutiveModel {
 public:
  explicit ProgramBurn(const ProgramBurnParams& p) : p_(p) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "program_burn"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return 1.0 / p_.eos.kappa; }
  double shear_modulus() const override { return 0.0; }
  bool needs_position() const override { return true; }

 private:
  ProgramBurnParams p_;
};

}  // namespace tephra
