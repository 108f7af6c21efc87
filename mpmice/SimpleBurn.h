#pragma once
// The point functions of Vaango's Simple_Burn model (<Model type="Simple_Burn">;
// the Vaango/Uintah user guide "Simple Burn", rate m_dot = A p^0.778; the
// surface criterion and area of Vaango's HEChem/Common.cc), for the MPMICE
// mass conversion from an MPM reactant to an ICE product gas (used by
// SimpleBurnModel.cpp in step 4 of the coupled step; docs/mpmice.md).
//
// A cell's corner values wm[n] = w_n m_n are the 8 nodes' solid masses times
// their node -> cell weights (mpmice/CellProjection.h: 1/8, doubled per
// symmetry plane); node n sits at the cell corner (n & 1, (n >> 1) & 1,
// (n >> 2) & 1) (x, y, z bits).
#include "core/base/Types.h"

namespace tephra {

struct SimpleBurnParams {
  double threshold_temperature = 0;  // <ThresholdTemp> [K]
  double threshold_pressure = 0;     // <ThresholdPressure> [Pa]
  double enthalpy = 0;               // <Enthalpy> [J/kg], released into the product
  double burn_coeff = 0;             // <BurnCoeff> [kg/(m^2 s)] at p = refPressure
  double ref_pressure = 1;           // <refPressure> [Pa]
};

// Surface cell: 0.4 < (max - min)/max < 1 over the 8 corner values, max > tiny.
bool simple_burn_surface_cell(const double wm[8], double tiny);

// Unit normal n of the corner values: per axis 0.25 (sum of the 4 low-side
// minus the 4 high-side corners)/dx_d (pointing out of the solid), normalized.
Vec3 simple_burn_surface_normal(const double wm[8], const Vec3& dx);

// Burning surface area in the cell: A = dx dy dz / (sum_d dx_d |n_d|) x
// (1/max_d |n_d|)^(1/3). A plane face normal to an axis gives the cell face area.
double simple_burn_surface_area(const Vec3& n, const Vec3& dx);

// Mass burned in dt: dm = dt A BurnCoeff (p/refPressure)^0.778 when T >
// ThresholdTemp and p > ThresholdPressure, else 0; at most solid_mass.
double simple_burn_mass(const SimpleBurnParams& prm, double dt, double area, double p, double T, double solid_mass);

}  // namespace tephra
