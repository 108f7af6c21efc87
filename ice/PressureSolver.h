#pragma once
// The linear solve of the implicit ICE pressure equation on hypre's
// structured interface (HYPRE_Struct*): a 7-point stencil per interior cell,
// assembled patch by patch, solved by PCG or GMRES with a PFMG, SMG or
// diagonal (Jacobi) preconditioner, or by PFMG/SMG alone (HypreSettings in
// IceSetup.h). Periodic directions are periodic in the hypre grid. hypre's
// headers stay inside PressureSolver.cpp.
#include <array>
#include <memory>

#include "ice/IceFields.h"
#include "ice/IceSetup.h"

namespace tephra {

// Stencil entries of a cell, in the order of the coefficient fields.
enum StencilEntry { kCenter = 0, kWest, kEast, kSouth, kNorth, kBottom, kTop, kStencilSize };

// A[s][patch](i,j,k): the coefficient that multiplies x at the neighbour s of
// interior cell (i,j,k) in row (i,j,k). A coefficient that points out of a
// non-periodic domain must be 0 (boundary conditions fold it into the centre).
using StencilCoefficients = std::array<CellScalars, kStencilSize>;

struct LinearSolveResult {
  bool converged = false;
  int iterations = 0;
  double relative_residual = 0;  // ||b - A x||_2 / ||b||_2 as hypre reports it
};

class PressureSolver {
 public:
  // `g` holds this process's patches (one hypre box each). distributed: the
  // patches of the level are spread over MPI_COMM_WORLD's ranks and every
  // rank constructs and solves together (hypre's communicator is the world);
  // else this process holds the whole level (MPI_COMM_SELF).
  PressureSolver(const Grid& g, const HypreSettings& settings, bool distributed = false);
  ~PressureSolver();
  PressureSolver(const PressureSolver&) = delete;
  PressureSolver& operator=(const PressureSolver&) = delete;

  // Solves A x = b on the interior cells (x's ghosts and extra cells are
  // untouched). b = 0 gives x = 0 without calling hypre. Converged means
  // relative_residual <= max(tolerance, kRoundOffFloor).
  LinearSolveResult solve(const StencilCoefficients& A, const CellScalars& b, CellScalars& x);

  // Tolerances below this cannot be met in double precision (the residual of
  // the exact solution is ~ cond * eps); they are clamped to it.
  static constexpr double kRoundOffFloor = 1e-13;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace tephra
