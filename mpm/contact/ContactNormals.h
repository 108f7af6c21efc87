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

// <MPM><collinear_bimaterial_contact_normals>true: the body-averaged normals
// (VT §1.7.5 after eq. 1.117, "for multiple objects an average gradient";
// Vaango's SerialMPM computeNormals with d_computeCollinearNormals): at each
// node, every material alpha with mass takes
//   g_alpha <- (g_alpha - sum_{b != alpha} m_b g_b / sum_{b != alpha} m_b) / 2,
// 0 where m_alpha = 0. With two materials g_1 = -g_2 = (g_1 - g_2)/2: both
// bodies see the same plane, the normal of VT eq. 1.129, (g_a - g_b)/|g_a - g_b|.
// `grids[m]->mass` are the node masses; `gradient[m]` the mass gradients.
void collinear_normals(const std::vector<const NodeGrid*>& grids, std::vector<std::vector<Vec3>>& gradient);

// x_g = sum_p m_p x_p S_gp / m_g (Vaango's gPosition); 0 where m_g = 0.
void mass_weighted_position(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

// d_g = sum_p m_p (x_p - X_g) S_gp / m_g, X_g the node's position (periodic
// grids: the offsets fold over node aliases, mpm/PeriodicGrid.h fold_positions).
void mass_weighted_offset(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

}  // namespace tephra
