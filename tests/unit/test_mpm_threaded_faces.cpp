// The face passes of the grid BCs and the symmetry folds, threaded in session 25
// (GridBoundaryConditions::apply, mpm/SymmetryFold.cpp): the rows of one face
// shared among the threads, the faces one after the other. Oracle: the
// definitions written here as plain serial loops in the documented order
// (GridBoundaryConditions.h / SymmetryFold.h):
//   apply: velocity faces (face nodes, then their extra nodes) face by face;
//          v_d = 0 on every symmetry face's nodes; then, face by face, each
//          extra node e of a symmetry face takes R v_m of its mirror node m;
//   fold:  face by face (x-, x+, y-, ...), q_m += R q_e for every pair.
// Compared bit for bit with 1, 2 and 3 threads on a grid whose faces hold
// more than 4096 nodes (the threaded path runs), with two extra layers in x
// (k = 1, 2), random node values, and edges/corners where the face order
// matters (the extra node beyond x- at y = 0 copies a node the y- face set).
#include <gtest/gtest.h>

#include <cstring>
#include <random>

#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"
#include "mpm/SymmetryFold.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

NodeGrid grid() {
  NodeGrid g;
  g.origin = Vec3(-0.2, -0.1, -0.1);
  g.h = Vec3(0.1, 0.1, 0.1);
  g.n = IntVec3(44, 38, 33);  // faces: 38 x 33 + 44 x 33 + 44 x 38 nodes, > 4096 in all
  g.extra = IntVec3(2, 1, 1);
  g.reset();
  return g;
}

std::vector<Vec3> random_vectors(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Vec3> v(n);
  for (auto& x : v) x = Vec3(u(rng), u(rng), u(rng));
  return v;
}

// Visits the nodes of face f's plane (without the extra rows in the other
// directions) or the extra-node pairs (e, m) of face f, as the definitions.
template <class Fn>
void face_nodes(const NodeGrid& g, int f, Fn&& fn) {
  const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
  IntVec3 c;
  c[d] = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
  for (c[b] = g.extra[b]; c[b] < g.n[b] - g.extra[b]; ++c[b])
    for (c[a] = g.extra[a]; c[a] < g.n[a] - g.extra[a]; ++c[a]) fn(g.index(c));
}
template <class Fn>
void face_pairs(const NodeGrid& g, int f, Fn&& fn) {
  const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
  const int plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d], out = (f % 2 == 0) ? -1 : 1;
  for (int k = 1; k <= g.extra[d]; ++k) {
    IntVec3 e, m;
    e[d] = plane + out * k;
    m[d] = plane - out * k;
    for (e[b] = 0; e[b] < g.n[b]; ++e[b])
      for (e[a] = 0; e[a] < g.n[a]; ++e[a]) {
        m[a] = e[a];
        m[b] = e[b];
        fn(g.index(e), g.index(m), d);
      }
  }
}

void reference_apply(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& v) {
  for (int f = 0; f < 6; ++f)
    if (bcs.face[f].kind == FaceVelocityBC::Kind::Velocity) {
      face_nodes(g, f, [&](std::size_t n) { v[n] = bcs.face[f].value; });
      face_pairs(g, f, [&](std::size_t e, std::size_t, int) { v[e] = bcs.face[f].value; });
    }
  for (int f = 0; f < 6; ++f)
    if (bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry) face_nodes(g, f, [&](std::size_t n) { v[n][f / 2] = 0.0; });
  for (int f = 0; f < 6; ++f)
    if (bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry)
      face_pairs(g, f, [&](std::size_t e, std::size_t m, int d) {
        v[e] = v[m];
        v[e][d] = -v[m][d];
      });
}

void reference_fold(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& v) {
  for (int f = 0; f < 6; ++f)
    if (bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry)
      face_pairs(g, f, [&](std::size_t e, std::size_t m, int d) {
        Vec3 r = v[e];
        r[d] = -r[d];
        v[m] += r;
      });
}

bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

TEST(MpmThreadedFaces, GridBcsApplyIsTheFaceByFaceDefinition) {
  const NodeGrid g = grid();
  GridBoundaryConditions all_symmetric, mixed;
  for (int f = 0; f < 6; ++f) all_symmetric.face[f].kind = FaceVelocityBC::Kind::Symmetry;
  all_symmetric.set_extra_nodes = true;
  mixed = all_symmetric;
  mixed.face[1].kind = FaceVelocityBC::Kind::Velocity;  // x+ moves, y+ moves: their edge takes y+'s value (later face)
  mixed.face[1].value = Vec3(0.5, -0.25, 0.125);
  mixed.face[3].kind = FaceVelocityBC::Kind::Velocity;
  mixed.face[3].value = Vec3(-2.0, 3.0, 1.0);
  for (const GridBoundaryConditions* bcs : {&all_symmetric, &mixed}) {
    const std::vector<Vec3> start = random_vectors(g.count(), 7);
    std::vector<Vec3> expect = start;
    reference_apply(*bcs, g, expect);
    for (int threads : {1, 2, 3}) {
      ThreadCountScope scope(threads);
      std::vector<Vec3> v = start;
      bcs->apply(g, v);
      EXPECT_TRUE(same_bits(v, expect)) << threads << " threads";
    }
  }
}

TEST(MpmThreadedFaces, SymmetryFoldsAreTheFaceByFaceDefinition) {
  NodeGrid g = grid();
  GridBoundaryConditions bcs;
  for (int f = 0; f < 6; ++f) bcs.face[f].kind = FaceVelocityBC::Kind::Symmetry;
  bcs.face[3].kind = FaceVelocityBC::Kind::None;  // y+ not folded
  bcs.set_extra_nodes = true;
  const std::vector<Vec3> start = random_vectors(g.count(), 11);
  std::vector<Vec3> expect = start;
  reference_fold(bcs, g, expect);
  // The masses for fold_symmetry_velocity: positive, then folded as scalars.
  std::vector<double> mass0(g.count());
  std::mt19937 rng(5);
  for (double& m : mass0) m = 0.5 + std::uniform_real_distribution<double>(0.0, 1.0)(rng);
  std::vector<double> mass_folded = mass0;
  for (int f = 0; f < 6; ++f)
    if (bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry)
      face_pairs(g, f, [&](std::size_t e, std::size_t m, int) { mass_folded[m] += mass_folded[e]; });
  for (int threads : {1, 2, 3}) {
    ThreadCountScope scope(threads);
    std::vector<Vec3> v = start;
    fold_symmetry_vectors(bcs, g, v);
    EXPECT_TRUE(same_bits(v, expect)) << "vectors, " << threads << " threads";
    g.internal_force = start;
    fold_symmetry_internal_force(bcs, g);
    EXPECT_TRUE(same_bits(g.internal_force, expect)) << "internal force, " << threads << " threads";
    std::vector<double> m = mass0;
    fold_symmetry_scalar(bcs, g, m);
    EXPECT_EQ(std::memcmp(m.data(), mass_folded.data(), m.size() * sizeof(double)), 0) << threads << " threads";
    // The particle sums: momentum = v m unfolded, folded, divided by the folded mass.
    g.mass = mass0;
    g.volume = mass0;
    g.velocity = start;
    g.external_force = start;
    fold_symmetry_particle_sums(bcs, g);
    std::vector<Vec3> momentum(g.count());
    for (std::size_t n = 0; n < g.count(); ++n) momentum[n] = start[n] * mass0[n];
    reference_fold(bcs, g, momentum);
    std::vector<Vec3> velocity(g.count());
    for (std::size_t n = 0; n < g.count(); ++n) velocity[n] = momentum[n] / mass_folded[n];
    EXPECT_TRUE(same_bits(g.velocity, velocity)) << "particle sums velocity, " << threads << " threads";
    EXPECT_TRUE(same_bits(g.external_force, expect)) << "particle sums f_ext, " << threads << " threads";
    EXPECT_EQ(std::memcmp(g.mass.data(), mass_folded.data(), g.count() * sizeof(double)), 0);
  }
}

}  // namespace
}  // namespace tephra
