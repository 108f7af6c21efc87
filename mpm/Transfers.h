#pragma once
// The particle <-> grid kernels of explicit MPM (Vaango theory manual §1.5,
// Algorithms 5-9 and 14), as free functions over one material's particles and
// node arrays, generic over the interpolator: each particle's stencil is a
// list of (node, S_gp, grad S_gp) entries (mpm/shape/Interpolator.h).
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

class PatchBand;

// The scatters below take an optional PatchBand (mpm/PatchBand.h): with an
// active one every node sum is formed per patch and the partials of the
// band nodes are added in ascending patch id (the same bits in one process
// and on MPI ranks); without one (nullptr) the sums run in the scatter order
// straight into the node arrays.

// P2G (Alg. 5, eqs. 1.62, 1.64, 1.69), on a reset grid:
//   m_g = sum m_p S,  V_g = sum V_p S,  v_g = (sum m_p v_p S) / m_g,
//   f_ext,g = sum (f_ext,p + m_p b) S,  sigma_g = (sum V_p sigma_p S) / V_g.
// Nodes with m_g = 0 keep v_g = 0. sigma_g only when g.stress is sized (NodeGrid::node_stress).
void particles_to_grid(const Particles& p, const Stencils& s, const Vec3& body_force,
                       NodeGrid& g, PatchBand* band = nullptr);

// f_int,g = - sum V_p (sigma_p - q_p I) grad S_gp   (Alg. 6, eq. 1.70; sigma, V at t_n;
// q_p the artificial bulk viscosity, 0 unless <artificial_viscosity>).
void compute_internal_force(const Particles& p, const Stencils& s, NodeGrid& g, PatchBand* band = nullptr);

// particles_to_grid and compute_internal_force in one pass over the particles
// and their stencils, on a reset grid: every node sum takes the same terms in
// the same particle order (the scatter order), so the same bits as the two
// calls. For the step when nothing between P2G and the internal force changes
// sigma_p, V_p or q_p (no contact, no MPMICE; MpmComponent::advance).
void particles_to_grid_and_internal_force(const Particles& p, const Stencils& s, const Vec3& body_force,
                                          NodeGrid& g, PatchBand* band = nullptr);

// a_g = (f_int,g + f_ext,g) / m_g,  v*_g = v_g + a_g dt   (Alg. 7, eqs. 1.71-1.72).
void integrate_grid_velocity(NodeGrid& g, double dt);

// a_g = (v*_g - v_g) / dt, after the boundary conditions changed v*_g (Alg. 8).
void acceleration_from_velocities(NodeGrid& g, double dt);

// l_p = sum_g v*_g (grad S_gp)^T   (Alg. 9, eq. 1.73).
void velocity_gradients(const Stencils& s, const NodeGrid& g, std::vector<Mat3>& L);

// velocity_gradients and the first-order update F_{n+1} = (I + dt l_p) F_n
// (eq. 1.75, update_deformation_gradients with FirstOrder) in one pass over
// the particles: the same expressions, so the same bits as the two calls.
void velocity_gradients_and_first_order_F(const Stencils& s, const NodeGrid& g, double dt, std::vector<Mat3>& L,
                                          const std::vector<Mat3>& F_old, std::vector<Mat3>& F);
// The same F without keeping l_p (for a model that does not read L:
// MpmComponent::keeps_L): the same expressions, so the same bits.
void first_order_F(const Stencils& s, const NodeGrid& g, double dt, const std::vector<Mat3>& F_old,
                   std::vector<Mat3>& F);

// G2P, FLIP update (Alg. 14, eq. 1.76):
//   v_p += dt sum a_g S,  x_p += dt sum v*_g S,  u_p += dt sum v*_g S.
void grid_to_particles(const Stencils& s, const NodeGrid& g, double dt, Particles& p);

}  // namespace tephra
