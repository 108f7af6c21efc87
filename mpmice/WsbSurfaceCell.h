#pragma once
// The burning-surface rule shared by the WSB burn models (Steady_Burn,
// Unsteady_Burn and the deflagration branch of DDT1; Uintah's HEChem
// Steady_Burn.cc / Unsteady_Burn.cc / DDT1.cc, read for the rule):
//   * on the surface: the corner values w_n m_n of the cell satisfy
//     min/max < 0.7 and the cell holds reactant particles;
//   * ignited: some cell of the 3x3x3 neighbourhood with at most
//     <BoundaryParticles> reactant particles has a material with volume
//     fraction > 0.2 hotter than <IgnitionTemp>;
//   * T0 = the reactant temperature of the neighbour with the largest
//     reactant volume fraction (the bulk temperature of the WSB rate);
//   * p = the equilibration pressure of the neighbour with the largest
//     product volume fraction (the gas pressure above the surface).
#include "mpmice/SolidBurn.h"

namespace tephra {

struct WsbIgnition {
  double ignition_temp = 0;       // <IgnitionTemp> [K]
  double boundary_particles = 0;  // <BoundaryParticles>
};

struct WsbSurface {
  bool on_surface = false;     // min/max < 0.7 and particles in the cell
  bool ignited = false;        // a hot neighbour with few particles (and on_surface)
  bool hot_neighbour = false;  // some material of some neighbour hotter than IgnitionTemp (any volume fraction)
  double T0 = 0;               // [K]
  double pressure = 0;         // [Pa]
};

// The rule for cell `cell` of model m (its reactant and product), corner
// values wm (SolidBurnSupport::corner_masses).
WsbSurface wsb_surface_cell(const SolidBurnModel& m, const WsbIgnition& ig, const double wm[8], const BurnCell& cell);

// The most a WSB model burns in the cell: its solid mass less V x 1e-12 (V = cell.volume)
// kg/m^3 (Uintah's MIN_MASS_IN_A_CELL = V d_TINY_RHO; the value 1e-12 is
// assumed, as in Simple_Burn), never negative.
double wsb_burnable_mass(const BurnCell& cell);

}  // namespace tephra
