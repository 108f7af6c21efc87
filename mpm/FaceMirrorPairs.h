#pragma once
// The (extra node, mirror node) pairs of a grid face: the symmetry folds of
// the particle sums (mpm/SymmetryFold.cpp) and the extra-node velocities of
// the grid boundary conditions (mpm/GridBoundaryConditions.cpp) both visit them.
#include <cstddef>

#include "mpm/NodeGrid.h"

namespace tephra {

// Visits the pairs (extra node e, mirror node m) of face f, k = 1..extra layers,
// over all nodes of the other two directions: fn(e, m, d). The rows (k, jb)
// are shared among the threads of an enclosing parallel region (an orphaned
// `omp for`, with its barrier at the end; outside a parallel region: serial).
// Within one face the pairs are disjoint and no extra node is a mirror node
// (e lies beyond the face plane, m inside), so fn(e, m) of one face may run
// in any order or at once: the same bits for any thread count. Faces stay
// one after the other (the barrier): a later face reads what an earlier one
// folded into its extra nodes (SymmetryFold.h). wait = false leaves out the
// barrier at the end (the two faces of one direction when their node planes are disjoint).
// True when the low and the high face of direction d touch disjoint node
// planes, so the high face needs no barrier after the low one: with e extra
// layers the low face's pairs lie in [0, 2e], the high face's in
// [n - 1 - 2e, n), disjoint when n > 4e + 1.
inline bool mirror_faces_disjoint(const NodeGrid& g, int d) { return g.n[d] > 4 * g.extra[d] + 1; }

template <class Fn>
void for_face_mirror_pairs(const NodeGrid& g, int f, Fn&& fn, bool wait = true) {
  const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
  const int face_plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
  const int out = (f % 2 == 0) ? -1 : 1;
  // The active box's nodes of the other two directions (the whole grid in one
  // process); the box is closed under the mirror pairs (MpmComponent::set_node_boxes).
  const NodeBox box = g.active_box();
  const long span_b = box.empty() ? 0 : long(box.hi[b] - box.lo[b]);
  const long rows = long(g.extra[d]) * span_b;
  auto row = [&](long r) {
    const int k = 1 + int(r / span_b), jb = box.lo[b] + int(r % span_b);
    IntVec3 e, m;
    e[d] = face_plane + out * k;
    m[d] = face_plane - out * k;
    if (m[d] < 0 || m[d] >= g.n[d]) return;  // a domain thinner than the extra layers
    if (e[d] < box.lo[d] || e[d] >= box.hi[d]) return;
    e[b] = m[b] = jb;
    for (int ja = box.lo[a]; ja < box.hi[a]; ++ja) {
      e[a] = m[a] = ja;
      fn(std::size_t(g.index(e)), std::size_t(g.index(m)), d);
    }
  };
  if (wait) {
#pragma omp for schedule(static)
    for (long r = 0; r < rows; ++r) row(r);
  } else {
#pragma omp for schedule(static) nowait
    for (long r = 0; r < rows; ++r) row(r);
  }
}

}  // namespace tephra
