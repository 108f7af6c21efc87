#pragma once
// The interface of a solid constitutive model (DESIGN.md §2.1): a point function
// over an explicit state,
//   (F_n, F_{n+1}, l, dt, T, sigma_n, history_n)
//       -> (sigma_{n+1}, history_{n+1}, wave speed, stored energy, plastic work, heating),
// applied by the model to a span of points: virtual dispatch once per material
// per step (§2.3), the concrete loop inside the model. No particle, grid, MPI or
// I/O type appears here; the driver owns storage, the loop over materials, the
// stable time step and the energy sums.
//
// History: a model declares its internal variables (name, component count,
// initial value); the driver stores each as one flat SoA column of doubles
// (components values per point, row-major for tensors), saves it in
// checkpoints and can write it as the output label "p.<name>".
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tephra {

class ModelParameters;

// One point's result of a point function (what unit tests call).
struct SolidPointResult {
  Eigen::Matrix3d stress;     // Cauchy stress, tension positive [Pa]
  double wave_speed = 0.0;    // dilatational wave speed in the current state [m/s]
  double energy_density = 0;  // stored energy per unit REFERENCE volume [J/m^3]
};

// One internal variable a model carries from step to step.
struct HistoryVariable {
  std::string name;             // output label "p.<name>" (Vaango's label where it has one)
  int components = 1;           // 1 (scalar), 3 (vector) or 9 (tensor, row-major), as OutputFrame
  std::vector<double> initial;  // value at the reference state, `components` entries
  std::string description;      // meaning and unit, for documentation and --list
};

// The driver's storage of the declared history: columns[k] belongs to
// history()[k] and holds components * n values for the n points of the span.
// The update reads the state at t_n and overwrites it with the state at t_{n+1}.
using HistoryColumns = std::span<const std::span<double>>;

// The inputs of a span of n points. Every span has length n, except where noted.
struct SolidUpdateInput {
  double dt = 0.0;                           // step size [s]; 0 at initialization
  double density0 = 0.0;                     // reference mass density rho_0 [kg/m^3]
  std::span<const Eigen::Matrix3d> F_old;    // deformation gradient at t_n
  std::span<const Eigen::Matrix3d> F_new;    // deformation gradient at t_{n+1}
  std::span<const Eigen::Matrix3d> L;        // velocity gradient of the step, F_{n+1} = (I + dt L) F_n;
                                             // may be empty when the model's reads_velocity_gradient() is false
  std::span<const double> temperature;       // T at t_{n+1} [K]
  std::span<const Eigen::Matrix3d> stress_old;  // Cauchy stress at t_n (may alias out.stress)
  // Read-only point context for models whose law depends on where and when
  // (polar_orthotropic_hypoelastic: the material cylindrical frame from the
  // initial position; program_burn: the burn front). The MPM driver fills both;
  // a driver without positions leaves `position` empty, and models that need it
  // report the span (their update fails) -- see needs_position().
  std::span<const Eigen::Vector3d> position;  // particle position x_p at t_n [m]
  double time = 0.0;                          // t_{n+1}, the end of the step [s] (0 at initialization)
  std::span<const double> reference_volume;   // particle reference volume V0 = m_p/rho_0 [m^3]
};

struct SolidUpdateOutput {
  std::span<Eigen::Matrix3d> stress;  // Cauchy stress at t_{n+1}, tension positive [Pa]
  std::span<double> wave_speed;       // dilatational wave speed at t_{n+1} [m/s] (0: no limit)
  std::span<double> energy_density;   // stored elastic energy per REFERENCE volume at t_{n+1} [J/m^3]
  std::span<double> plastic_work;     // dissipated work per reference volume during the step [J/m^3]
  std::span<double> heating;          // internal heating rate dT/dt of the step [K/s] (Vaango pdTdt)
  HistoryColumns history;             // in/out, one column per history() entry
};

// Pressure response for MPMICE (Vaango computePressEOSCM): gauge pressure,
// positive in compression, at mass density rho.
struct SolidEosPoint {
  double pressure = 0.0;  // p - p_ref [Pa]
  double dp_drho = 0.0;   // [Pa m^3/kg]
  double c2 = 0.0;        // sound speed squared [m^2/s^2]
};

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;
  virtual std::string type() const = 0;  // Vaango's type attribute, e.g. "comp_neo_hook"

  // Updates every point of the span. Returns the index of the first point whose
  // state is inadmissible (J <= 0 or a non-finite result), or -1 when all are
  // fine; the driver turns that into a NumericalFailure naming the particle.
  virtual long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const = 0;

  // The internal variables this model carries (none by default).
  virtual std::vector<HistoryVariable> history() const { return {}; }

  // Small-strain moduli (time-step estimates, contact, tests).
  virtual double bulk_modulus() const = 0;
  virtual double shear_modulus() const = 0;

  // True when sigma depends on F_{n+1} only and energy_density is W(F) with
  // sigma = (1/J) dW/dF F^T (VT eq. 4.3); contract tests check dW/dF then.
  virtual bool hyperelastic() const { return false; }

  // True for a rigid body (VT eq. 3.1): the driver keeps F = I (and so the
  // reference volume); the particles only move with the grid velocity.
  virtual bool rigid() const { return false; }

  // True when update() reads SolidUpdateInput::position (drivers must supply it).
  virtual bool needs_position() const { return false; }

  // False when update() never reads SolidUpdateInput::L (the law uses F_n and
  // F_{n+1} only): the MPM driver may then pass an empty L and not keep the
  // per-particle velocity-gradient column (72 B per particle; MpmComponent::keeps_L).
  virtual bool reads_velocity_gradient() const { return true; }

  // ---- hooks MPMICE needs (Vaango computePressEOSCM / computeRhoMicroCM).
  // std::nullopt: not provided by this model; the caller reports MissingFeature.
  virtual std::optional<SolidEosPoint> pressure_at_density(double /*rho*/, double /*density0*/,
                                                           double /*T*/) const {
    return std::nullopt;
  }
  // The inverse: rho such that pressure_at_density(rho) = p_gauge.
  virtual std::optional<double> density_at_pressure(double /*p_gauge*/, double /*density0*/,
                                                    double /*T*/) const {
    return std::nullopt;
  }
  // <useModifiedEOS> (Vaango computePressEOSCM/computeRhoMicroCM of UCNH, ElasticPlastic(HP),
  // ViscoScram): in expansion (rho < rho0) MPMICE takes p = p_ref (rho/rho0)^n instead of the
  // hooks above, which then give the compression branch (models/solid/ModifiedEos.h).
  virtual bool modified_eos() const { return false; }
};

using ConstitutiveModelP = std::shared_ptr<const ConstitutiveModel>;

// ---- registry keyed by Vaango's type names
// Implemented types, sorted (what `tephra --list constitutive_model` prints).
std::vector<std::string> constitutive_model_types();
// Every type name Vaango's schema accepts (implemented or not).
const std::vector<std::string>& vaango_constitutive_model_types();
// Creates the model `type` from its parameters. Returns nullptr when the type
// is not implemented; the caller decides between MissingFeature (a Vaango
// type) and DeckError (an unknown name).
ConstitutiveModelP create_constitutive_model(const std::string& type, const ModelParameters& params);

}  // namespace tephra
