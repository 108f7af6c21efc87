#pragma once
// Dirichlet temperature on the domain faces for the MPM heat conduction
// (<BCType var="Dirichlet" label="Temperature">; var="Neumann" with value 0 is
// the natural, insulated condition). The face nodes take the given
// temperature in T_g before the conduction rate is computed, and keep it
// through the step: their rate is zero (T*_g = T_bc).
//
// Vaango (HeatConduction::integrateTemperatureRate) instead hands the
// particles the rate (T*_g - T_g,noBC)/dt, T_g,noBC the node temperature
// before the condition: every step the particles next to the face are pulled
// by S_gp (T_bc - T_g,noBC), which keeps the mass-weighted mean of the
// first-cell particles at T_bc although the exact temperature there differs
// from T_bc by O(h). That is a first-order error in a layer one cell wide,
// L2 order 1.5 (measured 1.52, 1.51 on the quarter-wave mode of
// tests/verification/test_mpm_heat_conduction.cpp); holding the face nodes
// gives order 2.
#include <vector>

#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"

namespace tephra {

// True when any face has a Dirichlet temperature.
bool has_temperature_bcs(const GridBoundaryConditions& bcs);

// Sets the nodes of every face with a Dirichlet temperature (the face's node
// plane over the domain's nodes of the other two directions, and the
// extra-cell node layers beyond it when bcs.set_extra_nodes).
void apply_temperature_bcs(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& T);

// Zeroes the temperature rate on the same nodes.
void hold_temperature_faces(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& rate);

}  // namespace tephra
