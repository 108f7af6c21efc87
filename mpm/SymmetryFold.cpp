#include "mpm/SymmetryFold.h"

#include "mpm/FaceMirrorPairs.h"
#include "mpm/NodeRuns.h"

namespace tephra {

namespace {

bool active(const GridBoundaryConditions& bcs, const NodeGrid& g, int f, int dims = 3) {
  return f / 2 < dims && bcs.set_extra_nodes && bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry && g.extra[f / 2] > 0;
}

// fold(e, m, d) over the pairs of every active face, inside a parallel region
// (or serially outside one). Face after face, except that the low face of a
// direction needs no barrier before its high face when both are folded and
// the direction has more than 4 extra + 1 node planes: the low face reads
// planes [0, extra) and writes (extra, 2 extra], the high face reads
// (n - 1 - extra, n) and writes [n - 1 - 2 extra, n - 1 - extra): disjoint
// then. Between directions the barrier stays (the edges: a later direction
// reads extra nodes an earlier one wrote).
template <class Fold>
void fold_faces_here(const GridBoundaryConditions& bcs, const NodeGrid& g, int dims, Fold&& fold) {
  for (int f = 0; f < 6; ++f) {
    if (!active(bcs, g, f, dims)) continue;
    const int d = f / 2;
    const bool pair_follows = f % 2 == 0 && active(bcs, g, f + 1, dims) && mirror_faces_disjoint(g, d);
    for_face_mirror_pairs(g, f, fold, !pair_follows);
  }
}

// Pair nodes of the active faces (the threading threshold of fold_faces).
long pair_nodes(const GridBoundaryConditions& bcs, const NodeGrid& g, int dims);

// fold_faces_here in its own parallel region, threaded when there are enough pairs.
template <class Fold>
void fold_faces(const GridBoundaryConditions& bcs, const NodeGrid& g, int dims, Fold&& fold) {
  const long pairs = pair_nodes(bcs, g, dims);
  if (pairs == 0) return;
#pragma omp parallel if (pairs >= 4096)
  fold_faces_here(bcs, g, dims, fold);
}

// fn(gi) for every node of the active box, shared among the threads of an
// enclosing parallel region (mpm/NodeRuns.h).
template <class Fn>
void active_nodes_here(const NodeGrid& g, Fn&& fn) {
  for_each_run_node_here(node_runs(g), fn);
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

long pair_nodes(const GridBoundaryConditions& bcs, const NodeGrid& g, int dims) {
  const NodeBox box = g.active_box();
  if (box.empty()) return 0;
  long n = 0;
  for (int f = 0; f < 6; ++f)
    if (active(bcs, g, f, dims)) {
      const int d = f / 2;
      n += long(g.extra[d]) * (box.hi[(d + 1) % 3] - box.lo[(d + 1) % 3]) * (box.hi[(d + 2) % 3] - box.lo[(d + 2) % 3]);
    }
  return n;
}

// q_m += R q_e: the extra node keeps its own sums (the BCs set its velocity).
template <class T>
void fold_pair(std::vector<T>& q, std::size_t e, std::size_t m, int d) {
  q[m] += reflect(q[e], d);
}

template <class T>
void fold_field(const GridBoundaryConditions& bcs, const NodeGrid& g, int dims, std::vector<T>& q) {
  fold_faces(bcs, g, dims, [&](std::size_t e, std::size_t m, int d) { fold_pair(q, e, m, d); });
}

}  // namespace

void fold_symmetry_particle_sums(const GridBoundaryConditions& bcs, NodeGrid& g, int dims) {
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || active(bcs, g, f, dims);
  if (!any) return;
  const bool stress = !g.stress.empty();  // NodeGrid::node_stress
  // One parallel region: the node-wise products, the folds, the quotients
  // (each loop node-wise or pair-wise: the same bits for any thread count).
#pragma omp parallel if (long(g.count()) >= 4096)
  {
    active_nodes_here(g, [&](std::size_t n) {  // extensive sums
      g.velocity[n] *= g.mass[n];
      if (stress) g.stress[n] *= g.volume[n];
    });
    // The five fields of a pair in one visit (they are independent arrays).
    fold_faces_here(bcs, g, dims, [&](std::size_t e, std::size_t m, int d) {
      fold_pair(g.mass, e, m, d);
      fold_pair(g.volume, e, m, d);
      fold_pair(g.velocity, e, m, d);
      if (stress) fold_pair(g.stress, e, m, d);
      fold_pair(g.external_force, e, m, d);
    });
    active_nodes_here(g, [&](std::size_t n) {
      if (g.mass[n] > 0.0) g.velocity[n] /= g.mass[n];
      if (stress && g.volume[n] > 0.0) g.stress[n] /= g.volume[n];
    });
  }
}

void fold_symmetry_scalar(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& q) {
  fold_field(bcs, g, 3, q);
}

void fold_symmetry_vectors(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& v, int dims) {
  fold_field(bcs, g, dims, v);
}

void fold_symmetry_internal_force(const GridBoundaryConditions& bcs, NodeGrid& g, int dims) {
  fold_field(bcs, g, dims, g.internal_force);
}

void fold_symmetry_velocity(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& velocity,
                            int dims) {
  bool any = false;
  for (int f = 0; f < 6; ++f) any = any || active(bcs, g, f, dims);
  if (!any) return;
  // velocity = P / m_folded with P the unfolded momentum sum: P = velocity m_folded.
  // One parallel region; node-wise and pair-wise loops: the same bits for any thread count.
#pragma omp parallel if (long(g.count()) >= 4096)
  {
    active_nodes_here(g, [&](std::size_t n) { velocity[n] *= g.mass[n]; });
    fold_faces_here(bcs, g, dims, [&](std::size_t e, std::size_t m, int d) { fold_pair(velocity, e, m, d); });
    active_nodes_here(g, [&](std::size_t n) {
      velocity[n] = g.mass[n] > 0.0 ? Vec3(velocity[n] / g.mass[n]) : Vec3::Zero();
    });
  }
}

}  // namespace tephra
