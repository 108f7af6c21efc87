#pragma once
// Dirichlet temperature on the domain faces for the MPM heat conduction
// (<BCType var="Dirichlet" label="Temperature">; var="Neumann" with value 0 is
// the natural, insulated condition). The face nodes take the given
// temperature in T_g before the conduction rate is computed (as Vaango).
//
// The rate handed to the particles at a face node: Vaango
// (HeatConduction::integrateTemperatureRate) uses (T_bc - T_g,noBC)/dt, T_g,noBC
// the node's P2G temperature, which pulls the mass-weighted mean of the
// first-cell particles to T_bc every step. But that mean is the temperature at
// the particles' mass centroid xbar_g, not at the face: for a smooth field it
// differs from T_bc by dT/dn (xbar_g - x_face) = O(h), a first-order error in
// a layer one cell wide (L2 order 1.5, measured on the quarter-wave mode of
// tests/verification/test_mpm_heat_conduction.cpp). Holding the face nodes
// (rate 0) is second order for smooth data but never brings the first-cell
// particles to a suddenly raised face temperature (an O(1) error: L2 order
// 0.5 on the erfc step). Tephra pulls the P2G temperature to the value the
// face temperature and the normal gradient predict at the centroid:
//   rate_g = (T_bc + (T_in - T_bc)/h_n (xbar_g,n - x_face,n) - T_g,noBC) / dt,
// T_in the node one cell inside the face: O(h^2) for a smooth field (second
// order), and for a step it still moves the first-cell particles towards T_bc.
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

// The rate of the face nodes (formula above). T: node temperatures with the
// face values set; T_free: the P2G temperatures before; xbar: sum m x S / m_g.
void face_temperature_rates(const GridBoundaryConditions& bcs, const NodeGrid& g, const std::vector<double>& T,
                            const std::vector<double>& T_free, const std::vector<Vec3>& xbar, double dt,
                            std::vector<double>& rate);

}  // namespace tephra
