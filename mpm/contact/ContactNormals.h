#pragma once
// Node quantities that contact models read, from one material's particles and
// stencils of the step (any interpolator: the flat Stencils of
// mpm/shape/Interpolator.h, W entries per particle).
#include <vector>

#include "core/base/Types.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// g_g = sum_p m_p grad S_g(x_p)   (VT eq. 1.107): the mass gradient at the
// node, pointing out of the body (from its particles towards empty space).
void mass_gradient(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out);

// Symmetry faces (<BCType var="symmetry">) are mirrors: the body continues
// as its mirror image R x across the face (mpm/SymmetryFold.h). The mirrored
// particles add to the mass gradient of node m the term R (m_p grad S_e(x_p)),
// e the extra-cell node mirror of m, so
//   g_m += R g_e            (extra-cell layers, when the BCs set them), and
//   g . e_d = 0             on the face plane (the node is its own mirror:
//                            g + R g has no normal part),
// for the faces of the first `dims` directions (3; 2 for axisymmetric runs).
// Without it the normal at a face node points out through the symmetry plane:
// a body one cell thick between two symmetry faces (plane strain) gets normals
// tilted 45 degrees out of plane, and a Coulomb exchange that removes the
// in-plane approach then takes sqrt(2) times the normal impulse, so friction
// is sqrt(2) mu (docs/mpm-contact.md, "Coulomb friction against closed forms").
// Vaango applies its Symmetric BC to the normals (FrictionContact).
void mirror_gradient_at_symmetry_faces(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& gradient,
                                       int dims = 3);

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
