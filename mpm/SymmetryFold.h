#pragma once
// Symmetry planes as mirrors for the particle sums on the grid.
//
// A symmetry face (<BCType var="symmetry">) stands for the mirror image of the
// body across the face. Shape functions wider than a cell (gimp, cpdi,
// 3rdorderBS, ...) give an interior node g = face + k a support that crosses
// the face, so the mirrored particles would contribute to its mass, momentum
// and forces. Those contributions are, by the reflection R (normal component
// negated, R v and R sigma R), exactly what the real particles give the
// extra-cell node e = face - k (S_g(R x) = S_e(x) on a uniform grid). Without
// them the node misses the part of its weak form that lies beyond the face:
// for the internal force, -int_{beyond} sigma grad S_g = -sigma(face) S_g(face)
// + O(h) per unit area, i.e. the wall's reaction on node g, an O(1) relative
// error that does not fall with h (docs/mpm-convergence.md, the gimp and
// 3rdorderBS stall on AxisAligned). Folding adds the extra node's sums,
// reflected, to its mirror node:
//   m_g += m_e,  (m v)_g += R (m v)_e,  f_g += R f_e,  V_g += V_e,
//   (V sigma)_g += R (V sigma)_e R.
// The extra node keeps its own sums (its velocities are then set from the
// mirror node by GridBoundaryConditions::apply, as before). Applied face by
// face (x-, x+, y-, ...): a later face reads the sums an earlier one folded
// into its extra nodes, which composes the images of edges and corners
// (R_x R_y, ...). The face node is its own mirror (its sums double,
// their ratios do not change) and is left alone. Nothing happens without
// extra cells or when the BCs do not set the extra nodes.
//
// The fold is the Galerkin form of the mirrored velocity space, whatever the
// weights: the BCs set v_e = R v_m, so G2P reads v(x) = S_m(x) v_m + S_e(x) R v_m
// and the basis function of the unknown v_m is S_m + S_e R; P2G and the
// internal force must use its transpose, which is the fold above. That holds
// for the r-weighted axisymmetric weights too (the image of a ring across the
// axis r = 0 is the same ring in the meridian plane, across r = a a mirror
// wall): axisymmetric runs fold the in-plane faces (dims = 2: x = r, y = z)
// and not the hoop (z) faces, whose two node planes carry the hoop weights.
#include <vector>

#include "core/base/Types.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"

namespace tephra {

// mass, volume, momentum (velocity x mass), V sigma and the external force.
// dims: fold the faces of the first dims directions (3; 2 for axisymmetric runs).
void fold_symmetry_particle_sums(const GridBoundaryConditions& bcs, NodeGrid& g, int dims = 3);
// The internal force.
void fold_symmetry_internal_force(const GridBoundaryConditions& bcs, NodeGrid& g, int dims = 3);
// A P2G velocity field v = (sum m_p v_p S)/m_g whose m_g is already folded:
// folds the momentum v m_g (unfolded sum) and divides again.
void fold_symmetry_velocity(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& velocity,
                            int dims = 3);
// A vector node sum v (of g's node layout) that reflects as a vector, e.g. the
// mass gradient sum m_p grad S_gp (the mirrored particle at R x gives node m
// the term R (m grad S_e(x)), since S_m(R x) = S_e(x)): v_m += R v_e, the same
// faces in the same order as fold_symmetry_particle_sums.
void fold_symmetry_vectors(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& v, int dims = 3);
// One extensive node sum q (of g's node layout), folded as
// fold_symmetry_particle_sums folds g.mass: the same faces, in the same order.
void fold_symmetry_scalar(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& q);

}  // namespace tephra
