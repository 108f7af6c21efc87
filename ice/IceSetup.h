#pragma once
// What the ICE component reads from a deck (make_ice_component): materials
// with their EOS and initial geometry, the <CFD> settings, physical constants,
// exchange coefficients and boundary conditions, all checked before step 1.
#include <memory>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "core/geometry/GeometryPiece.h"
#include "core/grid/BoundaryConditions.h"
#include "core/grid/Grid.h"
#include "models/eos/EquationOfState.h"
#include "models/thermo/IceSpecificHeat.h"
#include "ice/Lodi.h"

namespace tephra {

class IceModel;  // ice/models/IceModel.h

// One <geom_object> of an ICE material: the region and its initial state.
struct IceSource {
  GeometryPieceP piece;
  IntVec3 res = IntVec3::Constant(2);  // sample points per cell per direction (volume fraction of a cell)
  Vec3 velocity = Vec3::Zero();
  double density = 0;       // micro density rho (Uintah's rho_micro)
  double pressure = 0;      // read; ICE recomputes the pressure from rho and T through the EOS
  double temperature = 0;
  // <volumeFraction> (optional, in [0, 1]): the material's volume fraction in
  // the cells this piece covers, theta = volumeFraction x (covered share of
  // the cell), where Uintah's default (absent) is the covered share itself.
  // Uintah's ICEMaterial::initializeCells; IceComponent::initialize.
  double volume_fraction = 1.0;
};

struct IceMaterialSpec {
  int index = 0;             // material index (deck order)
  std::string name;
  std::string eos_type;
  EquationOfStateP eos;
  double gamma = 0, cv = 0;  // <gamma>, <specific_heat>
  IceSpecificHeatP cv_model; // <SpecificHeatModel>: c_v(T) per cell replaces cv in the energy equation
  double dynamic_viscosity = 0, thermal_conductivity = 0;  // mu [Pa s], k [W/(m K)] (ice/Diffusion.h)
  double tiny_rho = 1e-12;   // <tiny_rho>: rho_CC = tiny_rho * rho_micro where a material is absent
  std::vector<IceSource> sources;
  // An MPM material of an MPMICE run (mpmice/MpmIceComponent.h): its cell
  // state (rho_CC, vel_CC, temp_CC, sp_vol_CC) is set from the particles at
  // the start of every step; ICE takes it through equilibration, face
  // velocities, pressure and exchange but neither advects it nor adds gravity
  // (the MPM grid does). eos wraps the constitutive model's pressure hooks.
  bool lagrangian = false;
  // <isSurroundingMatl> (Uintah ICEMaterial): marks the background fluid. In
  // Uintah its only use is the hydrostatic adjustment of the pressure BC
  // (the surrounding material's micro density, and it must be given when
  // gravity is on). Tephra's adjustment (apply_hydrostatic_pressure_bc) uses
  // the cell's bulk mixture density sum rho_CC, which the face-velocity
  // balance (eq. 26.1) needs and which equals the surrounding material's
  // micro density where that material fills the boundary cell; so the flag
  // is recorded (IceSetup::surrounding_material) and changes nothing else.
  bool surrounding = false;
};

enum class AdvectionOrder { First, Second };

// Boundary condition of one label on one domain face for one material, as
// the ICE step applies it (core/grid/BoundaryConditions describes the deck).
struct IceFaceBc {
  BCKind kind = BCKind::Neumann;  // Dirichlet, Neumann, Symmetry, ComputeFromDensity, LODI
  double scalar = 0;
  Vec3 vector = Vec3::Zero();
};

// <CFD><ICE><TimestepControl> (Uintah's computeStableTimestep):
//   aggressive:   dt = cfl min_{cells,d} dx_d/(knob c + |u_d|)
//   conservative: dt = cfl V / sum of the outflow volumes swept per unit time
//                 through the six faces by a characteristic velocity
//                 (face velocity + knob c + velocity jump + sqrt(dx.|g|) + diffusion velocity).
// knob_for_speedSound defaults to 1 (explicit) and 0.5 with <ImplicitSolver> (Uintah).
enum class DeltScheme { Aggressive, Conservative };

// <ImplicitSolver> and its <Parameters variable="implicitPressure"> (the
// pressure solve, ice/ImplicitPressure.h), with the top-level <Solver type>.
struct HypreSettings {
  std::string solver = "cg";          // cg | gmres | pfmg | smg (lower case)
  std::string preconditioner = "pfmg";// none | pfmg | smg | jacobi
  double tolerance = 1e-10;           // relative residual ||r||_2/||b||_2
  int max_iterations = 100;
  int npre = 1, npost = 1, skip = 0;
  int relax_type = 1;                 // PFMG: 0 Jacobi, 1 weighted Jacobi, 2/3 red-black
};

struct ImplicitSettings {
  bool enabled = false;
  int max_outer_iterations = 20;
  double outer_iteration_tolerance = 1e-8;  // max |residual| of the volume balance (dimensionless)
  int iters_before_timestep_restart = 5;
  HypreSettings hypre;
};

enum IceBcLabel { kBcPressure = 0, kBcVelocity, kBcTemperature, kBcDensity, kBcSpecificVol, kBcLabels };

struct IceSetup {
  Grid grid;
  std::vector<IceMaterialSpec> materials;
  int surrounding_material = -1;  // the material with <isSurroundingMatl> true, or -1 (IceMaterialSpec::surrounding)
  AdvectionOrder advection = AdvectionOrder::First;
  double cfl = 0.5;
  DeltScheme delt_scheme = DeltScheme::Aggressive;
  double delt_knob = 1.0;  // knob_for_speedSound
  ImplicitSettings implicit;
  int max_iter_equilibration = 100;
  Vec3 gravity = Vec3::Zero();
  double reference_pressure = 101325.0;  // read and kept; the ideal gas does not use it
  // Exchange coefficients K_mn, H_mn (symmetric, zero diagonal), n x n row-major.
  std::vector<double> K, H;
  // <heatExchangeCoeff> variable: H per cell from the Lagrangian masses
  // (variable_heat_coefficients, ice/Exchange.h) instead of the deck's <heat>.
  bool variable_heat_exchange = false;
  // <ClampSpecificVolume>: M v_L >= tiny_rho rho_0 V v after the Lagrangian
  // specific volume (Uintah's clamp, used with the JWL++ decks).
  bool clamp_sp_vol = false;
  // <conserveTotalEnergy> (Tephra extension, default true): return the
  // kinetic energy lost by the momentum advection and the face-pressure work
  // to the internal energy (ice/IceEnergy.cpp, docs/algorithms/ice.md). false: Uintah's
  // energy equation.
  bool conserve_total_energy = true;
  // <Models><Model> and <CFD><ICE><ADD_HEAT> (ice/models/IceModel.h).
  std::vector<std::shared_ptr<IceModel>> models;
  LodiSettings lodi;  // <BoundaryConditions><LODI> (enabled when a face uses var="LODI")
  // bcs[m][face][label]; unused on periodic faces.
  std::vector<std::array<std::array<IceFaceBc, kBcLabels>, 6>> bcs;
  // <MPM><axisymmetric> true (read by ICE-only decks too; Uintah's ICE has no
  // such flag): x = r, y = z, one cell in z; finite volumes in (r, z) per
  // radian (ice/RadialWeights.h, docs/algorithms/ice.md "Axisymmetric ICE").
  bool axisymmetric = false;
};

}  // namespace tephra
