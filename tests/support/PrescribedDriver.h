#pragma once
// The material-point driver for constitutive-model tests: runs one cell of
// particles of a model through a prescribed deformation history F*(t) by the
// real MPM step (<use_prescribed_deformation>, mpm/PrescribedDeformation.h),
// and returns the state of one particle after every step.
//
//   std::vector<PrescribedRow> rows = {{0.0, Mat3::Identity()}, {1e-3, F1}};
//   PrescribedHistory h = drive_prescribed(
//       "<constitutive_model type=\"comp_neo_hook\"><bulk_modulus>1e9</bulk_modulus>"
//       "<shear_modulus>5e8</shear_modulus></constitutive_model>", rows);
//   h.stress.back()   // Cauchy stress at the last row's time
//
// The deck is built in memory: one MPM material (density, extra material
// properties as given), a 1-cell block of 2x2x2 particles ([0, h]^3, h = 1 mm),
// linear interpolation, a grid around it large enough for the deformed block,
// no gravity, no boundary conditions. The step is fixed, (t_last - t_0) /
// steps, so the history is sampled uniformly; each step's
// F_{n+1} = F*(t_{n+1}) F*(t_n)^{-1} F_n, so F follows the rows exactly.
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "mpm/PrescribedDeformation.h"

namespace tephra::test {

struct PrescribedHistory {
  std::vector<double> time;  // t_0 and the end of every step
  std::vector<Mat3> F;       // particle 0's deformation gradient
  std::vector<Mat3> stress;  // its Cauchy stress (tension positive)
  std::vector<std::vector<double>> history;  // its model history columns, flattened, per sample
  std::vector<double> plastic_work;          // its model's dissipation of the step per reference volume [J/m^3]
  std::vector<double> strain_energy;      // reductions over the cell: StrainEnergy = sum W(F) V0 [J]
  std::vector<double> acc_strain_energy;  //   and AccStrainEnergy, the accumulated stress work [J]
  std::vector<double> plastic_work_total; //   and PlasticWork, the accumulated plastic work [J]
};

struct PrescribedDriverOptions {
  int steps = 200;            // equal steps over [t_0, t_last]
  double density = 1000.0;    // <density> [kg/m^3]
  // Extra <material> children (e.g. "<melt_temp>1356</melt_temp>"), placed before the model.
  std::string material_xml = "<thermal_conductivity>1</thermal_conductivity><specific_heat>1000</specific_heat>";
  double temperature = 294.0;  // initial particle temperature [K]
};

// Throws whatever the deck reader or the run throws (DeckError, MissingFeature, NumericalFailure).
PrescribedHistory drive_prescribed(const std::string& model_xml, const std::vector<PrescribedRow>& rows,
                                   const PrescribedDriverOptions& options = {});

}  // namespace tephra::test
