#include "mpm/SymmetryFold.h"

#include "mpm/NodeRuns.h"

namespace tephra {

namespace {

bool active(const GridBoundaryConditions& bcs, const NodeGrid& g, int f, int dims = 3) {
  return f / 2 < dims && bcs.set_extra_nodes && bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry && g.extra[f / 2] > 0;
}

// Visits the pairs (extra node e, mirror node m) of face f, k = 1..extra layers,
// over all nodes of the other two directions: fn(e, m, d).
template <class Fn>
void for_pairs(const NodeGrid& g, int f, Fn&& fn) {
  const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
  const int face_plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
  const int out = (f % 2 == 0) ? -1 : 1;
  for (int k = 1; k <= g.extra[d]; ++k) {
    IntVec3 e, m;
    e[d] = face_plane + out * k;
    m[d] = face_plane - out * k;
    if (m[d] < 0 || m[d] >= g.n[d]) continue;  // a domain thinner than the extra layers
    // The active box's nodes of the other two directions (the whole grid in one
    // process); the box is closed under the mirror pairs (MpmComponent::set_node_boxes).
    const NodeBox box = g.active_box();
    if (box.empty() || e[d] < box.lo[d] || e[d] >= box.hi[d]) continue;
    for (int jb = box.lo[b]; jb < box.hi[b]; ++jb)
      for (int ja = box.lo[a]; ja < box.hi[a]; ++ja) {
        e[a] = m[a] = ja;
        e[b] = m[b] = jb;
        fn(g.index(e), g.index(m), d);
      }
  }
}

Vec3 reflect(const Vec3& v, int d) {
  Vec3 r = v;
  r[d] = -r[d];
  return r;
}
Mat3 reflect(const Mat3& s, int d) {  // R s R, R = I - 2 e_d e_d^T
  Mat3 r = s;
  for (int j = 0; j < 3; ++j)
    if (j != d) {
      r(d, j) = -r(d, j);
      r(j, d) = -r(j, d);
    }
  return r;
}
double reflect(double s, int) { return s; }

template <class T>
void fold_field(const NodeGrid& g, int f, std::vector<T>& q) {
  for_pairs(g, f, [&](std::size_t e, std::size_t m, int d) {
    q[m] += reflect(q[e], d);  // the extra node keeps its own sums (the BCs set its velocity)
  });
}

}  // namespace

void fold_symmetry_particle_sums(const GridBoundaryConditions& bcs, NodeGrid& g, int dims) {
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || active(bcs, g, f, dims);
  if (!any) return;
  const bool stress = !g.stress.empty();  // NodeGrid::node_stress
  // Node-wise loops over the active box, threaded: the same bits for any thread count.
  for_each_active_node(g, [&](std::size_t n) {  // extensive sums
    g.velocity[n] *= g.mass[n];
    if (stress) g.stress[n] *= g.volume[n];
  });
  for (int f = 0; f < 6; ++f) {
    if (!active(bcs, g, f, dims)) continue;
    fold_field(g, f, g.mass);
    fold_field(g, f, g.volume);
    fold_field(g, f, g.velocity);
    if (stress) fold_field(g, f, g.stress);
    fold_field(g, f, g.external_force);
  }
  for_each_active_node(g, [&](std::size_t n) {
    if (g.mass[n] > 0.0) g.velocity[n] /= g.mass[n];
    if (stress && g.volume[n] > 0.0) g.stress[n] /= g.volume[n];
  });
}

void fold_symmetry_scalar(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& q) {
  for (int f = 0; f < 6; ++f)
    if (active(bcs, g, f)) fold_field(g, f, q);
}

void fold_symmetry_vectors(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& v, int dims) {
  for (int f = 0; f < 6; ++f)
    if (active(bcs, g, f, dims)) fold_field(g, f, v);
}

void fold_symmetry_internal_force(const GridBoundaryConditions& bcs, NodeGrid& g, int dims) {
  for (int f = 0; f < 6; ++f)
    if (active(bcs, g, f, dims)) fold_field(g, f, g.internal_force);
}

void fold_symmetry_velocity(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& velocity,
                            int dims) {
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || active(bcs, g, f, dims);
  if (!any) return;
  // velocity = P / m_folded with P the unfolded momentum sum: P = velocity m_folded.
  // Node-wise loops over the active box, threaded: the same bits for any thread count.
  for_each_active_node(g, [&](std::size_t n) { velocity[n] *= g.mass[n]; });
  for (int f = 0; f < 6; ++f)
    if (active(bcs, g, f, dims)) fold_field(g, f, velocity);
  for_each_active_node(g, [&](std::size_t n) {
    velocity[n] = g.mass[n] > 0.0 ? Vec3(velocity[n] / g.mass[n]) : Vec3::Zero();
  });
}

}  // namespace tephra
