// friction_LR (mpm/contact/FrictionLRContact.cpp): the logistic-regression
// normal of a separable point cloud, and the contact decision and exchange
// on two blocks of particles that touch or are separated by a gap.
//
// Oracles:
//  * Points placed in mirror pairs y -+ d n0 about a plane through the node
//    (labels -1, +1): the regression plane is that plane, n = n0.
//  * Touching blocks (material 0 below z = 0.5, heavier, so alpha; material
//    1 above), 1 approaching: at every node where both have mass the normal
//    relative velocity is removed, (v_1 - v_0) . e_z = 0 (to the accuracy of
//    the regression normal), momentum is
//    unchanged to round-off, and with mu = 0 the tangential velocities are
//    left alone.
//  * The same blocks with a gap of 0.3 cells between their particle domains:
//    the nodes in between carry mass of both, but the prominences differ by
//    0.3 h > 0.01 h: no exchange.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>

#include <Eigen/Geometry>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/Transfers.h"
#include "mpm/contact/ContactTypes.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

TEST(MpmContactLR, RegressionNormalOfMirroredClouds) {
  const Vec3 n0 = Vec3(1, 2, 3).normalized();
  const Vec3 t1 = n0.cross(Vec3::UnitX()).normalized(), t2 = n0.cross(t1);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-0.1, 0.1), d(0.005, 0.05);
  std::vector<Vec3> x;
  std::vector<double> label;
  for (int i = 0; i < 40; ++i) {
    const Vec3 y = u(rng) * t1 + u(rng) * t2;
    const double dist = d(rng);
    for (double s : {-1.0, 1.0}) {  // y and -y: the cloud is centred on the node
      x.push_back(s * y - dist * n0);
      label.push_back(-1.0);
      x.push_back(s * y + dist * n0);
      label.push_back(1.0);
    }
  }
  const Vec3 n = logistic_regression_normal(x, label, 1e-7 * 0.01);
  // Newton stops when 1 - n_k+1 . n_k < 1e-5 (Vaango's rule); the normal is
  // then within ~2e-5 rad of n0 here (observed 1 - n . n0 = 1.3e-10).
  EXPECT_GT(n.dot(n0), 1.0 - 1e-9) << n.transpose();
  // Labels swapped: the normal reverses.
  for (double& l : label) l = -l;
  EXPECT_GT(-logistic_regression_normal(x, label, 1e-7 * 0.01).dot(n0), 1.0 - 1e-9);
}

struct Blocks {
  std::vector<NodeGrid> grids = std::vector<NodeGrid>(2);
  std::vector<Particles> parts = std::vector<Particles>(2);
  std::vector<Stencils> stencils = std::vector<Stencils>(2);
  ContactNodes nodes;

  // h = 0.1, 10 cells per side; 2 particles per cell direction; block 0 fills
  // z in [0.2, 0.5], block 1 z in [0.5 + gap, 0.8], both x, y in [0.2, 0.8].
  explicit Blocks(double gap) {
    const double h = 0.1, rho[2] = {2000.0, 1000.0};
    const Vec3 v[2] = {Vec3(0.0, 0.0, 0.0), Vec3(0.3, 0.1, -1.0)};
    for (int m = 0; m < 2; ++m) {
      NodeGrid& g = grids[m];
      g.n = IntVec3(11, 11, 11);
      g.h = Vec3::Constant(h);
      g.reset();
      const double z0 = m == 0 ? 0.2 : 0.5 + gap, z1 = m == 0 ? 0.5 : 0.8;
      const int nz = int(std::lround((z1 - z0) / (0.5 * h)));
      const double dz = (z1 - z0) / nz;
      for (int k = 0; k < nz; ++k)
        for (int j = 0; j < 12; ++j)
          for (int i = 0; i < 12; ++i) {
            const double V = 0.05 * 0.05 * dz;
            const Mat3 size = Vec3(0.5, 0.5, dz / h).asDiagonal();
            parts[m].add(Vec3(0.2 + (i + 0.5) * 0.05, 0.2 + (j + 0.5) * 0.05, z0 + (k + 0.5) * dz), v[m], rho[m] * V,
                         V, 300.0, 0.0, i, size);
          }
      EXPECT_EQ(compute_stencils(parts[m], g, {InterpolatorKind::Linear, 1e10}, stencils[m]), -1);
      particles_to_grid(parts[m], stencils[m], Vec3::Zero(), g);
      nodes.grid.push_back(&g);
      nodes.velocity.push_back(&g.velocity);
      nodes.particles.push_back(&parts[m]);
      nodes.stencils.push_back(&stencils[m]);
    }
    nodes.h = Vec3::Constant(h);
    nodes.dt = 1e-4;
  }
};

TEST(MpmContactLR, TouchingBlocksExchangeEqualAndOppositeMomentum) {
  Blocks b(0.0);
  std::vector<Vec3> v0[2] = {b.grids[0].velocity, b.grids[1].velocity};
  FrictionParameters p;
  p.materials = {0, 1};
  p.mu = 0.0;
  FrictionLRContact(p, 2).exchange(ContactStage::Interpolated, b.nodes);
  int contact = 0;
  for (std::size_t g = 0; g < b.grids[0].count(); ++g) {
    const double m0 = b.grids[0].mass[g], m1 = b.grids[1].mass[g];
    const Vec3 &va = b.grids[0].velocity[g], &vb = b.grids[1].velocity[g];
    const Vec3 before = m0 * v0[0][g] + m1 * v0[1][g], after = m0 * va + m1 * vb;
    EXPECT_LE((after - before).norm(), 1e-13 * (m0 * v0[0][g].norm() + m1 * v0[1][g].norm()) + 1e-300) << g;
    if (!(m0 > 0 && m1 > 0)) continue;
    ++contact;
    // The normal relative velocity is removed and (mu = 0) the tangential one
    // kept, up to the tilt of the regression normal left by its stopping rule
    // (observed at most 3.0e-6 and 9.3e-6 of |v_1 - v_0| = 1.05).
    const double vrel = (v0[1][g] - v0[0][g]).norm();
    EXPECT_NEAR(vb[2] - va[2], 0.0, 1e-5 * vrel) << "node " << g;
    EXPECT_NEAR((vb - va).head<2>().norm(), (v0[1][g] - v0[0][g]).head<2>().norm(), 3e-5 * vrel) << "node " << g;
  }
  EXPECT_GE(contact, 49);  // the 7 x 7 interface nodes of z = 0.5 at least
}

TEST(MpmContactLR, SeparatedBlocksAreLeftAlone) {
  Blocks b(0.03);  // 0.3 cells between the domains
  std::vector<Vec3> v0[2] = {b.grids[0].velocity, b.grids[1].velocity};
  int shared = 0;
  for (std::size_t g = 0; g < b.grids[0].count(); ++g) shared += b.grids[0].mass[g] > 0 && b.grids[1].mass[g] > 0;
  ASSERT_GE(shared, 49);  // the grid alone cannot tell that they do not touch
  FrictionParameters p;
  p.materials = {0, 1};
  p.mu = 0.5;
  FrictionLRContact(p, 2).exchange(ContactStage::Integrated, b.nodes);
  EXPECT_EQ(b.grids[0].velocity, v0[0]);
  EXPECT_EQ(b.grids[1].velocity, v0[1]);
}


// The cloud of the interface node at the front end of the block on the incline
// (tests/support/FrictionScenes.h, h = 0.025, linear weights, 2x2x2 particles
// per cell, plane strain one cell thick): slab (alpha, -1) particles at
// x in {-3,-1,1,3} h/4, z in {-3,-1} h/4; block (beta, +1) only on the node's
// rear side, x in {-3,-1} h/4, z in {1,3} h/4; y in {1,3} h/4.
//  * Identity: with the full interface (block particles on both sides in x)
//    the cloud is mirror-symmetric in x, so the fit's n_x = 0 and n = +z; the
//    Newton iteration starts from +x (Vaango's) and stops on the 1e-5 rule,
//    which leaves n_x = -9.7e-8 (observed): bound 1e-6.
//  * Identity: the offset N4 is not penalised (lambda_4 = 0), so the plane
//    does not depend on where the coordinates start: Vaango regresses
//    absolute positions (SerialMPM::computeLogisticRegression), Tephra and
//    Nairn (MachineLearning.cpp) positions relative to the node; the normals
//    agree to the Newton stopping tolerance (1 - n_k+1 . n_k < 1e-5, i.e.
//    ~4e-3 rad; observed 6e-5).
//  * The corner cloud's plane is tilted: n = (-0.01853, 0, 0.99983) (this
//    code; Nairn's start from twice the linear-regression plane converges to
//    the same -0.01853, session 21 harness). It is a property of the
//    regularised logistic fit (lambda = 1e-7 h^2, Vaango's and Nairn's),
//    not of Tephra's implementation: this tilt at the block's two end nodes
//    is the whole frictionless incline deficit (docs/mpm-contact.md).
//    Pinned to 5 % so a change of the fit shows.
TEST(MpmContactLR, CornerCloudNormalTiltsAsTheRegularisedFitDoes) {
  const double h = 0.025, lambda = 1e-7 * h * h;
  auto cloud = [&](bool corner, const Vec3& origin, std::vector<Vec3>& x, std::vector<double>& label) {
    x.clear(), label.clear();
    for (double xq : {-0.75, -0.25, 0.25, 0.75})
      for (double yq : {0.25, 0.75}) {
        for (double zq : {-0.75, -0.25}) x.push_back(origin + h * Vec3(xq, yq, zq)), label.push_back(-1.0);
        if (corner && xq > 0.0) continue;
        for (double zq : {0.25, 0.75}) x.push_back(origin + h * Vec3(xq, yq, zq)), label.push_back(1.0);
      }
  };
  std::vector<Vec3> x;
  std::vector<double> label;
  cloud(false, Vec3::Zero(), x, label);
  const Vec3 flat = logistic_regression_normal(x, label, lambda);
  EXPECT_LT(std::abs(flat[0]), 1e-6) << flat.transpose();
  EXPECT_GT(flat[2], 1.0 - 1e-12);
  cloud(true, Vec3::Zero(), x, label);
  const Vec3 n = logistic_regression_normal(x, label, lambda);
  cloud(true, Vec3(0.2, 0.0, 0.025), x, label);  // Vaango's absolute coordinates of that node
  const Vec3 n_abs = logistic_regression_normal(x, label, lambda);
  std::printf("corner cloud: n = (%.6f, %.6f, %.6f), absolute coordinates (%.6f, %.6f, %.6f)\n", n[0], n[1], n[2],
              n_abs[0], n_abs[1], n_abs[2]);
  EXPECT_GT(n.dot(n_abs), 1.0 - 1e-5);
  EXPECT_NEAR(n[0], -0.01853, 0.05 * 0.01853);
  EXPECT_LT(std::abs(n[1]), 1e-12);
}

// Vaango's Symmetric BC on the regression normal (SerialMPM::
// computeLogisticRegression: MPMBoundCond "Symmetric" on gNormAlphaToBeta,
// then renormalised): on a symmetry face's node plane the component along
// the face's axis is zeroed. Closed forms on a 5 x 4 x 3 node grid with one
// extra layer (planes at index 1 and n - 2), symmetry on y- and x+:
//   node (2, 1, 1) on y-: (0, 0.6, 0.8) -> (0, 0, 1);
//   node (2, 2, 1) off every plane: unchanged;
//   node (3, 1, 1) on y- and x+: (0.6, 0.8, 0) -> 0 (nothing left);
//   node (3, 2, 1) on x+ (x- is not symmetric): (0.6, 0, 0.8) -> (0, 0, 1).
TEST(MpmContactLR, SymmetricBoundaryConditionOnTheNormal) {
  NodeGrid g;
  g.n = IntVec3(5, 4, 3);
  g.extra = IntVec3(1, 1, 1);
  std::array<bool, 6> sym{};
  sym[2] = true, sym[1] = true;
  auto at = [&](int i, int j, int k, Vec3 n) {
    symmetric_normal(g, g.index(IntVec3(i, j, k)), sym, n);
    return n;
  };
  EXPECT_LT((at(2, 1, 1, Vec3(0, 0.6, 0.8)) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_EQ(at(2, 2, 1, Vec3(0, 0.6, 0.8)), Vec3(0, 0.6, 0.8));
  EXPECT_LT(at(3, 1, 1, Vec3(0.6, 0.8, 0)).norm(), 1e-15);
  EXPECT_LT((at(3, 2, 1, Vec3(0.6, 0, 0.8)) - Vec3(0, 0, 1)).norm(), 1e-15);
  EXPECT_EQ(at(1, 2, 1, Vec3(0.6, 0, 0.8)), Vec3(0.6, 0, 0.8));  // x- plane: not a symmetry face
}

}  // namespace
}  // namespace tephra
