// The hypre solve of the implicit ICE pressure equation (ice/PressureSolver.h)
// against a dense direct solve of the same 7-point system. Oracle: the
// symmetric positive definite matrix A = D + L built from random positive face
// coefficients a_f (off-diagonal -a_f, centre kappa + sum a_f) on a small grid
// with two patches and one periodic direction; x_hypre must equal the LU
// solution of the assembled dense matrix to the solver tolerance times the
// condition number (here ~1e2): |x - x_dense| <= 1e-7 |x_dense|.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "core/grid/Loop.h"
#include "ice/PressureSolver.h"

using namespace tephra;

namespace {

Grid two_patch_grid(IntVec3 cells, IntVec3 periodic) {
  Grid g;
  g.cells = cells;
  g.dx = Vec3::Ones();
  g.periodic = periodic;
  g.extra_cells = IntVec3(periodic[0] ? 0 : 1, periodic[1] ? 0 : 1, periodic[2] ? 0 : 1);
  const std::vector<int> cut = split_evenly(cells[0], 2);
  for (int p = 0; p < 2; ++p) {
    Patch patch;
    patch.id = p;
    patch.lo = IntVec3(cut[p], 0, 0);
    patch.hi = IntVec3(cut[p + 1], cells[1], cells[2]);
    g.patches.push_back(patch);
  }
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

int wrap(int c, int n) { return ((c % n) + n) % n; }

void check_against_dense(const std::string& solver, const std::string& precond, const IntVec3& periodic) {
  const Grid g = two_patch_grid(IntVec3(6, 5, 4), periodic);
  const int n = int(g.num_interior_cells());
  auto index = [&](IntVec3 c) { return c[0] + g.cells[0] * (c[1] + g.cells[1] * c[2]); };
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(0.5, 2.0);
  // Face coefficients: a[d](i,j,k) on the low face of cell (i,j,k) along d
  // (a face per cell and direction, so a periodic wrap face is included).
  std::vector<std::vector<double>> a(3, std::vector<double>(n));
  for (int d = 0; d < 3; ++d)
    for (double& v : a[d]) v = U(rng);
  StencilCoefficients A;
  for (CellScalars& s : A) s = CellScalars(g, 1);
  CellScalars b(g, 1), x(g, 1);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n);
  Eigen::VectorXd bd(n);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 C(i, j, k);
      const int row = index(C);
      double centre = 0.1 * U(rng);  // the compressibility term sum theta kappa > 0
      for (int d = 0; d < 3; ++d)
        for (int side = 0; side < 2; ++side) {
          IntVec3 N = C;
          N[d] += side == 0 ? -1 : 1;
          const int entry = 1 + 2 * d + side;
          const bool outside = N[d] < 0 || N[d] >= g.cells[d];
          if (outside && !periodic[d]) {
            A[entry][pi](C) = 0.0;  // Neumann boundary: the face drops out
            continue;
          }
          IntVec3 Nw = N;
          Nw[d] = wrap(N[d], g.cells[d]);
          const IntVec3 low_cell = side == 0 ? C : Nw;  // the face's owner
          const double af = a[d][index(low_cell)];
          A[entry][pi](C) = -af;
          centre += af;
          M(row, index(Nw)) -= af;
        }
      A[kCenter][pi](C) = centre;
      M(row, row) += centre;
      bd[row] = b[pi](C) = U(rng) - 1.25;
    });
  ASSERT_LT((M - M.transpose()).norm(), 1e-14);  // the assembly above is symmetric
  const Eigen::VectorXd xd = M.partialPivLu().solve(bd);

  HypreSettings hs;
  hs.solver = solver;
  hs.preconditioner = precond;
  hs.tolerance = 1e-12;
  hs.max_iterations = 200;
  PressureSolver ps(g, hs);
  const LinearSolveResult r = ps.solve(A, b, x);
  EXPECT_TRUE(r.converged) << solver << "/" << precond << " residual " << r.relative_residual;
  double err = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      err = std::max(err, std::abs(x[pi](i, j, k) - xd[index(IntVec3(i, j, k))]));
    });
  EXPECT_LT(err, 1e-7 * xd.cwiseAbs().maxCoeff()) << solver << "/" << precond;
}

}  // namespace

TEST(IcePressureSolver, PcgPfmgMatchesDenseSolve) { check_against_dense("cg", "pfmg", IntVec3(0, 0, 0)); }
TEST(IcePressureSolver, PcgSmgMatchesDenseSolve) { check_against_dense("cg", "smg", IntVec3(0, 0, 0)); }
TEST(IcePressureSolver, PcgJacobiMatchesDenseSolve) { check_against_dense("cg", "jacobi", IntVec3(0, 0, 0)); }
TEST(IcePressureSolver, GmresPfmgMatchesDenseSolve) { check_against_dense("gmres", "pfmg", IntVec3(0, 0, 0)); }
TEST(IcePressureSolver, SmgAloneMatchesDenseSolve) { check_against_dense("smg", "none", IntVec3(0, 0, 0)); }
TEST(IcePressureSolver, PfmgAloneMatchesDenseSolve) { check_against_dense("pfmg", "none", IntVec3(0, 0, 0)); }
// Periodic in x (6 cells, the wrap face couples cells 0 and 5) and in z.
TEST(IcePressureSolver, PeriodicPcgMatchesDenseSolve) { check_against_dense("cg", "pfmg", IntVec3(1, 0, 1)); }
TEST(IcePressureSolver, PeriodicPcgJacobiMatchesDenseSolve) { check_against_dense("cg", "jacobi", IntVec3(1, 0, 0)); }

TEST(IcePressureSolver, ZeroRhsGivesZeroWithoutIterations) {
  const Grid g = two_patch_grid(IntVec3(4, 3, 2), IntVec3(0, 0, 0));
  StencilCoefficients A;
  for (CellScalars& s : A) s = CellScalars(g, 1);
  A[kCenter].fill(1.0);
  CellScalars b(g, 1), x(g, 1);
  b.fill(0.0);
  x.fill(3.0);
  PressureSolver ps(g, HypreSettings{});
  const LinearSolveResult r = ps.solve(A, b, x);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(x[0](0, 0, 0), 0.0);
}
