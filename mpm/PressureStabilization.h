#pragma once
// Pressure stabilisation, <MPM><do_pressure_stabilization> (theory manual
// §1.5, eqs. 1.82-1.84; for nearly incompressible materials): per cell c,
// over the particles whose centres lie in c,
//   V_c0 = sum m_p / rho_0 = sum V0_p,   V_c = sum J_p V0_p,   J_c = V_c / V_c0,
// and each particle's deformation gradient takes the cell's dilatation:
//   F_p <- (J_c / det F_p)^{1/3} F_p,   so det F_p = J_c   (the oracle of §1.5).
// The isochoric part of F_p is kept; a cell's volume is unchanged.
// A particle-to-particle oscillation of J inside a cell (the checkerboard
// pressure mode of locking elements) is replaced by its cell average; a
// uniform dilatation is left as it is.
//
// On MPI ranks (issue 7) the particles of one cell may sit on two ranks (a
// particle lives on the rank owning its interior cell; near a patch cut the
// cell of the node grid and the owning cell can disagree by round-off of the
// floor, and extra cells are clamped): the per-cell sums are therefore kept
// in a node-indexed array (cell (i,j,k) at its lower-corner node (i,j,k),
// which lies in the rank's node box whenever one of its particles is in the
// cell) and summed over the ranks in rank order (MpmComponent::sum_node_doubles)
// between the two halves below.
#include <vector>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"

namespace tephra {

// Cells are those of the node grid g (cell (i,j,k) spans nodes i..i+1, ...).
// Uses p.x, p.volume0 and p.F; replaces p.F. One process: both halves in turn.
void stabilize_pressure(const NodeGrid& g, Particles& p);

// First half: {V_c0, V_c} of every cell over the particles of p, two doubles
// per node of g (cell (i,j,k) at node g.index(i,j,k); the last node layer 0).
std::vector<double> cell_volume_sums(const NodeGrid& g, const Particles& p);

// Second half: F_p <- (J_c / det F_p)^{1/3} F_p with J_c = V_c / V_c0 from `sums`
// (cell_volume_sums of every particle of the cell, possibly over several ranks).
void apply_cell_dilatation(const NodeGrid& g, const std::vector<double>& sums, Particles& p);

}  // namespace tephra
