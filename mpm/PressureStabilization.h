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
#include <vector>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"

namespace tephra {

// Cells are those of the node grid g (cell (i,j,k) spans nodes i..i+1, ...).
// Uses p.x, p.volume0 and p.F; replaces p.F.
void stabilize_pressure(const NodeGrid& g, Particles& p);

}  // namespace tephra
