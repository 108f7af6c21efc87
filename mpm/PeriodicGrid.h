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
// Only the linear interpolator: GIMP, CPDI and B-spline supports reach the
// node plane outside the domain, which a periodic direction does not store
// (a MissingFeature, make_mpm_component). Contact normals across a periodic
// face are not folded either (contact with periodic directions is a
// MissingFeature).
#include <cstddef>
#include <vector>

#include "core/base/Types.h"
#include "core/grid/Grid.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"

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

// x_d <- lower_d + (x_d - lower_d) mod L_d in every periodic direction.
void wrap_periodic_positions(const Grid& grid, Particles& p);

}  // namespace tephra
