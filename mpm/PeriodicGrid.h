#pragma once
// Periodic MPM (<Level><periodic>[1,1,0]</periodic>): in a periodic
// direction d of N cells the node planes i and i + N are one node (Uintah's
// periodic patches: node N is node 0). The node arrays keep both planes
// (no extra cells in a periodic direction, Grid.cpp), and after each scatter
// every set of aliases gets the sum over the set:
//   m, V, m v, V sigma, f_ext after P2G (v and sigma re-divided),  f_int after the internal force,
// so all later node-wise steps (integration, contact, l_p, G2P) see identical
// values on aliases and a particle near the face gathers from the whole
// periodic neighbourhood. After G2P a particle that left through a periodic
// face re-enters at the other: x_d <- lower_d + (x_d - lower_d) mod L_d
// (its displacement u keeps the unwrapped motion).
//
// Wide stencils (mpm/shape): a periodic direction gets `ghost` node layers
// beyond each periodic face (NodeGrid::ghost, counted in NodeGrid::extra;
// node 0 sits ghost cells below the lower face). Ghost node extra - k is the
// alias of node extra + N - k: the canonical map takes node index c to
// extra + ((c - extra) mod N), so the particle sums that a gimp, B-spline or
// CPDI-corner stencil leaves on ghost nodes land on their periodic images,
// and every alias reads the folded total (Uintah's periodic patches fill the
// same ghost nodes from the opposite side). Ghost layers per interpolator
// (periodic_ghost_layers): linear 0 (its support is the particle's cell);
// gimp (l <= h/2) and 3rdorderBS reach 1.5 cells from the particle: 1;
// cpgimp (l <= h) and cpdi/cpti (corners within one cell of the particle,
// each with a linear support of one cell): 2; a stencil that reaches further
// stops the run (the particle's stencil leaves the grid: exit 4). The
// boundary-modified cubic B-spline (4thorderBS) has no periodic form
// (MissingFeature). Contact: the mass gradients (the normals) are summed over
// each alias set (fold_vectors) and the mass-weighted positions averaged as
// offsets from their node (fold_positions), so a ghost and its image see the
// same normal, position and, by fold_particle_sums, the same m, v, V and
// stress: the node-wise exchange gives them the same velocities. friction_LR,
// which fits a plane through the particles that reach each node, has no
// periodic form (MissingFeature). Heat conduction:
// the grid temperature and the conduction rate are folded like the sums
// (fold_mass_weighted, mpm/thermal/ThermalPhase.cpp).
//
// A periodic face is not a domain boundary (Uintah; ICE here does the same,
// ice/IceDeck.cpp): its velocity and temperature BCs are not applied
// (MpmComponent's constructor clears them). After the grid BCs of the other
// faces, copy_from_canonical gives every ghost the value of its image.
#include <cstddef>
#include <vector>

#include "core/base/Types.h"
#include "core/grid/Grid.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

struct PeriodicNodes {
  // canonical[g]: the representative of node g's alias set (g itself when not periodic).
  std::vector<std::size_t> canonical;
  bool active() const { return !canonical.empty(); }
};

// Empty (inactive) when no direction is periodic.
PeriodicNodes periodic_nodes(const Grid& grid, const NodeGrid& g);

// Sums the P2G fields over each alias set (m, V, m v, V sigma, f_ext) and
// stores the sums (v = sum m v / sum m, sigma = sum V sigma / sum V) on every alias.
void fold_particle_sums(const PeriodicNodes& map, NodeGrid& g);

// The same for f_int.
void fold_internal_force(const PeriodicNodes& map, NodeGrid& g);

// A node field f = (particle sum) / m_g divided by the folded mass (the grid
// temperature and the conduction rate, mpm/thermal): f <- fold(f m) / m on
// every alias set, so each alias holds (sum over the set) / m_g.
void fold_mass_weighted(const PeriodicNodes& map, const std::vector<double>& mass, std::vector<double>& f);

// A particle sum v (the contact mass gradient) summed over each alias set, on every alias.
void fold_vectors(const PeriodicNodes& map, std::vector<Vec3>& v);

// The contact positions x_g = X_g + sum m_p (x_p - X_g) S / m_g from the
// offsets d_g = sum m_p (x_p - X_g) S / m_g (mass_weighted_offset,
// mpm/contact/ContactNormals.h; m_g folded): d_g is summed over each alias
// set as the particle sum m_g d_g, then x_g = X_g + d_g on every alias
// (aliases lie whole periods apart, so positions themselves do not add).
void fold_positions(const PeriodicNodes& map, const NodeGrid& g, std::vector<Vec3>& x);

// Ghost node layers a periodic direction needs for `kind`; -1: no periodic form (4thorderBS).
int periodic_ghost_layers(InterpolatorKind kind);

// v[g] <- v[canonical[g]] for every node (after the grid BCs, which set only
// the domain's nodes: the ghosts follow their images).
void copy_from_canonical(const PeriodicNodes& map, std::vector<Vec3>& v);

// The node indices of the grid without its ghost layers (the nodes the
// output frame stores: cells + 2 extra cells + 1 per direction), in index
// order; empty when the grid has no ghost layer.
std::vector<std::size_t> nodes_without_ghosts(const NodeGrid& g);

// x_d <- lower_d + (x_d - lower_d) mod L_d in every periodic direction.
void wrap_periodic_positions(const Grid& grid, Particles& p);

}  // namespace tephra
