#pragma once
// Node quantities that contact models read, from one material's particles and
// stencils of the step (any interpolator: the flat Stencils of
// mpm/shape/Interpolator.h, W entries per particle).
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// g_g = sum_p m_p grad S_g(x_p)   (VT eq. 1.107): the mass gradient at the
// node, pointing out of the body (from its particles towards empty space).
void mass_gradient(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

// x_g = sum_p m_p x_p S_gp / m_g (Vaango's gPosition); 0 where m_g = 0.
void mass_weighted_position(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

// d_g = sum_p m_p (x_p - X_g) S_gp / m_g, X_g the node's position (periodic
// grids: the offsets fold over node aliases, mpm/PeriodicGrid.h fold_positions).
void mass_weighted_offset(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

}  // namespace tephra
