// Symmetry faces as mirrors (mpm/SymmetryFold.h). Oracle: a block filling
// the domain [0,1]^3 with symmetry on all six faces and a uniform stress
// sigma0 is in equilibrium (Div sigma = 0), and its mirror images continue
// the particle lattice across every face. So, after folding, the internal
// force f_g = -sum V_p sigma0 grad S_gp vanishes at every node inside the
// faces (the lattice x = (k + 1/2) h/ppc is symmetric about every node, and
// grad S_g is odd about it), and the lumped mass is m_g = rho h^3 there
// (partition of unity over the full lattice). Without the fold, the node one
// cell inside a face misses the mirrored particles: its force is the wall's
// reaction sigma0 n S_g(face) h^2 (about sigma0_nn h^2 / 8 for the quadratic
// B-spline), checked below so that the test can fail.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/SymmetryFold.h"
#include "mpm/Transfers.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {
namespace {

struct Block {
  NodeGrid g;
  Particles p;
  Stencils s;
  GridBoundaryConditions bcs;
  double h = 0.25, rho = 2.0;
  Mat3 sigma0;
};

Block make_block(InterpolatorKind kind, int ppc, bool x_faces_only = false) {
  Block b;
  const int cells = 4;
  b.g.origin = Vec3::Constant(-b.h);  // one extra cell per side
  b.g.h = Vec3::Constant(b.h);
  b.g.n = IntVec3::Constant(cells + 3);
  b.g.extra = IntVec3::Ones();
  b.g.reset();
  // Diagonal: a stress the three mirrors leave unchanged (R sigma R = sigma;
  // a shear stress would flip sign across the plane, no symmetric state).
  b.sigma0 = Vec3(3.0, -1.0, 2.0).asDiagonal();
  const double dx = b.h / ppc, v0 = dx * dx * dx;
  long long id = 0;
  for (int k = 0; k < cells * ppc; ++k)
    for (int j = 0; j < cells * ppc; ++j)
      for (int i = 0; i < cells * ppc; ++i) {
        b.p.add(Vec3((i + 0.5) * dx, (j + 0.5) * dx, (k + 0.5) * dx), Vec3::Zero(), b.rho * v0, v0, 300.0, 0.0, id++,
                Mat3::Identity() / ppc);
        b.p.stress.back() = b.sigma0;
      }
  for (int f = 0; f < 6; ++f)
    b.bcs.face[f].kind = (f < 2 || !x_faces_only) ? FaceVelocityBC::Kind::Symmetry : FaceVelocityBC::Kind::None;
  b.bcs.set_extra_nodes = true;
  EXPECT_EQ(compute_stencils(b.p, b.g, {kind, 1e10}, b.s), -1);
  particles_to_grid(b.p, b.s, Vec3::Zero(), b.g);
  compute_internal_force(b.p, b.s, b.g);
  return b;
}

void expect_equilibrium_after_fold(InterpolatorKind kind, int ppc) {
  Block b = make_block(kind, ppc);
  // Without the fold: the node one cell inside the x- face (interior in y, z)
  // carries the wall's reaction, f_x = sigma0_xx S_1(0) h^2 summed over the
  // face, about sigma0_xx h^2 / 8 (quadratic B-spline: S_1(0) = 1/8).
  const std::size_t n1 = b.g.index(2, 3, 3);
  EXPECT_GT(std::abs(b.g.internal_force[n1][0]), 0.05 * b.sigma0(0, 0) * b.h * b.h);
  fold_symmetry_particle_sums(b.bcs, b.g);
  fold_symmetry_internal_force(b.bcs, b.g);
  const double scale = b.sigma0.norm() * b.h * b.h;  // one node's share of |sigma| per face
  for (int k = 2; k <= 4; ++k)
    for (int j = 2; j <= 4; ++j)
      for (int i = 2; i <= 4; ++i) {  // the nodes strictly inside the faces
        const std::size_t n = b.g.index(i, j, k);
        EXPECT_NEAR(b.g.internal_force[n].norm(), 0.0, 1e-13 * scale) << i << " " << j << " " << k;
        EXPECT_NEAR(b.g.mass[n], b.rho * b.h * b.h * b.h, 1e-13) << i << " " << j << " " << k;
      }
}

TEST(MpmSymmetryFold, QuadraticBsplineBlockInEquilibrium) {
  // 2 and 3 particles per cell direction: the first particle (h/4, h/6 from
  // the face) lies within h/2 of it and weights the extra-cell node. (With 1
  // per cell, or gimp/cpdi on this undeformed lattice, no particle reaches
  // the extra nodes until it moves toward the face.)
  expect_equilibrium_after_fold(InterpolatorKind::QuadraticBspline, 2);
  expect_equilibrium_after_fold(InterpolatorKind::QuadraticBspline, 3);
}

// The MUSL velocity v = (sum m_p v_p S) / m_g over a folded m_g: a uniform
// tangential velocity u0 e_y (even under the x mirror) stays u0 at every node
// inside the faces after fold_symmetry_velocity.
TEST(MpmSymmetryFold, VelocityOfAUniformTangentialMotion) {
  // Symmetry on the x faces only (a y velocity is odd under the y mirrors).
  Block b = make_block(InterpolatorKind::QuadraticBspline, 2, /*x_faces_only=*/true);
  fold_symmetry_particle_sums(b.bcs, b.g);
  std::vector<Vec3> v(b.g.count(), Vec3::Zero());
  for (std::size_t i = 0; i < b.p.size(); ++i)
    for (int k = 0; k < b.s.width; ++k)
      v[b.s.node[i * b.s.width + k]] += b.s.w[i * b.s.width + k] * b.p.mass[i] * Vec3(0.0, 1.5, 0.0);
  for (std::size_t n = 0; n < v.size(); ++n) v[n] = b.g.mass[n] > 0 ? Vec3(v[n] / b.g.mass[n]) : Vec3::Zero();
  // Node (2, 3, 3) misses the mirrored momentum until the fold: v_y < 1.5.
  EXPECT_LT(v[b.g.index(2, 3, 3)][1], 1.5 - 1e-3);
  fold_symmetry_velocity(b.bcs, b.g, v);
  for (int i = 1; i <= 5; ++i) EXPECT_NEAR(v[b.g.index(i, 3, 3)][1], 1.5, 1e-13) << i;
}

}  // namespace
}  // namespace tephra
