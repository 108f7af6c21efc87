#pragma once
// The interface of a solid constitutive model: a point function
//   (F_{n+1}, reference density, state) -> (Cauchy stress, wave speed, energy)
// applied by the model to a span of points (virtual dispatch once per material
// per step, DESIGN.md §2.3). No particle, grid or I/O type appears here.
#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace tephra {

class ModelParameters;

// One point's result.
struct SolidPointResult {
  Eigen::Matrix3d stress;    // Cauchy stress, tension positive [Pa]
  double wave_speed = 0.0;   // dilatational wave speed in the current state [m/s]
  double energy_density = 0; // stored energy per unit REFERENCE volume W(F) [J/m^3]
};

// The inputs of a span of points (all spans have the same length).
struct SolidUpdateInput {
  std::span<const Eigen::Matrix3d> F;  // deformation gradient at t_{n+1}
  double density0 = 0.0;               // reference (initial) mass density [kg/m^3]
};

struct SolidUpdateOutput {
  std::span<Eigen::Matrix3d> stress;
  std::span<double> wave_speed;
  std::span<double> energy_density;
};

class ConstitutiveModel {
 public:
  virtual ~ConstitutiveModel() = default;
  virtual std::string type() const = 0;  // Vaango's type attribute, e.g. "comp_neo_hook"
  // Updates every point of the span. Returns the index of the first point whose
  // state is inadmissible (J <= 0 or a non-finite result), or -1 when all are fine;
  // the driver turns that into a NumericalFailure naming the particle.
  virtual long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const = 0;
  // Small-strain moduli (for time-step estimates and tests).
  virtual double bulk_modulus() const = 0;
  virtual double shear_modulus() const = 0;
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
