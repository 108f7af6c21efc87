#pragma once
// The grid velocity of the updated particle velocities (MUSL: Sulsky, Zhou &
// Schreyer 1995, "modified update stress last"; Nairn's USL+):
//   v_p^{n+1} = v_p + dt sum_g a_g S_gp            (the FLIP update, eq. 1.76)
//   v_g^{n+1} = sum_p m_p S_gp v_p^{n+1} / m_g      (P2G of it on the same stencils)
// Tephra takes l_p = sum_g v_g^{n+1} (grad S_gp)^T from it (docs/mpm-stability.md).
//
// Why: with l_p from v*_g (Vaango's USL) a node reached only by particles far
// out in its support, S_gp = S << 1 (a free surface, or a particle that has
// just crossed a grid line), has m_g ~ m S but |f_g| ~ V sigma / h, so
// v*_g - v_g ~ dt sigma / (rho h S) and the particle's l_p jumps by
// ~ dt sigma / (rho h^2 S): a single linear-hat cell crossing under GPa stress
// inverts F. v_g^{n+1} is a mass-weighted mean of particle velocities, so it
// stays bounded however small m_g is. The same node limits the USL step:
// von Neumann for that node (omega^2 = c^2 / (h^2 S), consistent/lumped mass
// ratio r = S) gives dt c / h <= sqrt(4 S / (2 - S)) = 0.603 at S = 1/6 (the
// outer particle of 3 per cell) with USL; with v_g^{n+1} the amplification
// matrix has det 1 and trace 2 - (dt c / h)^2, stable for dt c / h <= 2.
#include <cstddef>
#include <vector>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

class PatchBand;

// out[g] = v_g^{n+1} above (0 where m_g = 0), from g.acceleration (after contact
// and BCs) and the particles at t_n. `canonical` (may be null) maps each node
// to the representative of its periodic alias set (mpm/PeriodicGrid.h): the
// momentum is summed over each set, as P2G does.
// band (may be null): the momentum sums per patch, added in ascending patch id
// at the band nodes (mpm/PatchBand.h), before the division by m_g.
void updated_particle_grid_velocity(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                    const std::vector<std::size_t>* canonical, std::vector<Vec3>& out,
                                    PatchBand* band = nullptr);

}  // namespace tephra

namespace tephra {

// The node fill phi = V_g / V_cell (V_g = sum V_p S_gp: 1 at a node inside the
// body, ~S at a node reached only by particles far out in its support) below
// which USL is unstable at Courant number C = dt (c + |v|) / h: from the
// node's amplification matrix (omega^2 = c^2 / (h^2 phi), r = phi),
// C^2 <= 4 phi / (2 - phi), i.e. phi >= 2 C^2 / (4 + C^2).
// The nodes where keep_stable_usl_nodes (below) keeps v_g^{n+1}: needed[g] = 1
// where phi_g < limit, and on the node planes within 2 extra of each face
// (the grid BCs set an extra-cell node from its mirror across the face, which
// then must hold v_g^{n+1} too). Returns the number of nodes with phi_g < limit.
// full_x (may be null): the volume V_full of a node surrounded by material,
// per node index i along x (g.n[0] entries), used instead of cell_volume:
// axisymmetric runs, whose V_g is per radian and grows with r_g
// (axisymmetric_full_node_volumes, mpm/Axisymmetric.h), phi_g = V_g / V_full(i).
std::size_t usl_needed_nodes(const NodeGrid& g, double limit, double cell_volume, std::vector<unsigned char>& needed,
                             const std::vector<double>* full_x = nullptr);

// v_g^{n+1} as updated_particle_grid_velocity (no periodic aliases), exact at
// the nodes with needed[g] != 0; the other nodes hold partial sums. Only the
// particles whose stencil reaches a needed node are summed, in the scatter order
// of P2G (mpm/shape/ScatterOrder.h; particle order if the stencils have none),
// so a needed node's sum has the same terms in the same order: the same bits.
// With no needed node there is nothing to sum (USL everywhere).
void updated_particle_grid_velocity_at(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                       const std::vector<unsigned char>& needed, std::vector<Vec3>& out,
                                       PatchBand* band = nullptr);

inline double usl_fill_limit(double courant) { return 2.0 * courant * courant / (4.0 + courant * courant); }

// Where phi_g >= limit, v_g = v*_g (Vaango's USL: a well-filled node is stable
// and keeps USL's accuracy, e.g. one particle per cell); elsewhere v_g stays
// the updated-particle velocity. `v_star` holds v*_g, `v` the result.
// full_x: as usl_needed_nodes (null: phi_g = V_g / cell_volume).
void keep_stable_usl_nodes(const NodeGrid& g, double limit, double cell_volume, const std::vector<Vec3>& v_star,
                           std::vector<Vec3>& v, const std::vector<double>* full_x = nullptr);

}  // namespace tephra
