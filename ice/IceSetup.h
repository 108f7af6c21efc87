#pragma once
// What the ICE component reads from a deck (make_ice_component): materials
// with their EOS and initial geometry, the <CFD> settings, physical constants,
// exchange coefficients and boundary conditions, all checked before step 1.
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "core/geometry/GeometryPiece.h"
#include "core/grid/BoundaryConditions.h"
#include "core/grid/Grid.h"
#include "models/eos/EquationOfState.h"

namespace tephra {

// One <geom_object> of an ICE material: the region and its initial state.
struct IceSource {
  GeometryPieceP piece;
  IntVec3 res = IntVec3::Constant(2);  // sample points per cell per direction (volume fraction of a cell)
  Vec3 velocity = Vec3::Zero();
  double density = 0;       // micro density rho (Uintah's rho_micro)
  double pressure = 0;      // read; ICE recomputes the pressure from rho and T through the EOS
  double temperature = 0;
};

struct IceMaterialSpec {
  int index = 0;             // material index (deck order)
  std::string name;
  std::string eos_type;
  EquationOfStateP eos;
  double gamma = 0, cv = 0;  // <gamma>, <specific_heat>
  double dynamic_viscosity = 0, thermal_conductivity = 0;  // mu [Pa s], k [W/(m K)] (ice/Diffusion.h)
  double tiny_rho = 1e-12;   // <tiny_rho>: rho_CC = tiny_rho * rho_micro where a material is absent
  std::vector<IceSource> sources;
};

enum class AdvectionOrder { First, Second };

// Boundary condition of one label on one domain face for one material, as
// the ICE step applies it (core/grid/BoundaryConditions describes the deck).
struct IceFaceBc {
  BCKind kind = BCKind::Neumann;  // Dirichlet, Neumann, Symmetry, ComputeFromDensity
  double scalar = 0;
  Vec3 vector = Vec3::Zero();
};

enum IceBcLabel { kBcPressure = 0, kBcVelocity, kBcTemperature, kBcDensity, kBcSpecificVol, kBcLabels };

struct IceSetup {
  Grid grid;
  std::vector<IceMaterialSpec> materials;
  AdvectionOrder advection = AdvectionOrder::First;
  double cfl = 0.5;
  int max_iter_equilibration = 100;
  Vec3 gravity = Vec3::Zero();
  double reference_pressure = 101325.0;  // read and kept; the ideal gas does not use it
  // Exchange coefficients K_mn, H_mn (symmetric, zero diagonal), n x n row-major.
  std::vector<double> K, H;
  // bcs[m][face][label]; unused on periodic faces.
  std::vector<std::array<std::array<IceFaceBc, kBcLabels>, 6>> bcs;
};

}  // namespace tephra
