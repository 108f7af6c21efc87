// hypre structured-interface solve of the implicit pressure equation
// (PressureSolver.h). One hypre grid box per patch; the stencil is the
// 7-point one (centre, -x, +x, -y, +y, -z, +z) in the order of StencilEntry.
#include "ice/PressureSolver.h"

#include <HYPRE_struct_ls.h>
#include <HYPRE_utilities.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <mutex>
#include <vector>

#include "core/base/Errors.h"
#include "core/base/Mpi.h"
#include "core/grid/Loop.h"
#include "core/parallel/Ranks.h"

namespace tephra {

namespace {

// hypre's library state (HYPRE_Init/HYPRE_Finalize) after MPI, once per process.
void ensure_hypre_initialized() {
  static std::once_flag once;
  std::call_once(once, [] {
    ensure_mpi_initialized();
    HYPRE_Init();
  });
}

void check(HYPRE_Int err, const char* what) {
  // hypre returns a non-zero error flag also for "not converged"
  // (HYPRE_ERROR_CONV), which the caller judges from the residual.
  if (err != 0 && !HYPRE_CheckError(err, HYPRE_ERROR_CONV)) {
    HYPRE_ClearAllErrors();
    throw NumericalFailure(std::string("hypre: ") + what + " failed (error flag " + std::to_string(err) + ")");
  }
  HYPRE_ClearAllErrors();
}

struct Box {
  HYPRE_Int lo[3], hi[3];
  std::size_t size;
};

}  // namespace

struct PressureSolver::Impl {
  const Grid* grid = nullptr;
  HypreSettings settings;
  HYPRE_StructGrid hgrid = nullptr;
  HYPRE_StructStencil stencil = nullptr;
  std::vector<Box> boxes;  // one per patch
  MPI_Comm comm = MPI_COMM_SELF;
  bool distributed = false;
};

PressureSolver::PressureSolver(const Grid& g, const HypreSettings& settings, bool distributed)
    : impl_(std::make_unique<Impl>()) {
  ensure_hypre_initialized();
  Impl& im = *impl_;
  im.grid = &g;
  im.settings = settings;
  im.distributed = distributed;
  im.comm = distributed ? MPI_COMM_WORLD : MPI_COMM_SELF;
  check(HYPRE_StructGridCreate(im.comm, 3, &im.hgrid), "StructGridCreate");
  for (const Patch& p : g.patches) {
    Box b;
    b.size = 1;
    for (int d = 0; d < 3; ++d) {
      b.lo[d] = p.lo[d];
      b.hi[d] = p.hi[d] - 1;
      b.size *= std::size_t(p.hi[d] - p.lo[d]);
    }
    im.boxes.push_back(b);
    check(HYPRE_StructGridSetExtents(im.hgrid, im.boxes.back().lo, im.boxes.back().hi), "StructGridSetExtents");
  }
  HYPRE_Int periodic[3];
  for (int d = 0; d < 3; ++d) periodic[d] = g.periodic[d] ? g.cells[d] : 0;
  check(HYPRE_StructGridSetPeriodic(im.hgrid, periodic), "StructGridSetPeriodic");
  check(HYPRE_StructGridAssemble(im.hgrid), "StructGridAssemble");
  check(HYPRE_StructStencilCreate(3, kStencilSize, &im.stencil), "StructStencilCreate");
  HYPRE_Int offsets[kStencilSize][3] = {{0, 0, 0}, {-1, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 1, 0}, {0, 0, -1}, {0, 0, 1}};
  for (int s = 0; s < kStencilSize; ++s) check(HYPRE_StructStencilSetElement(im.stencil, s, offsets[s]), "StencilSetElement");
}

PressureSolver::~PressureSolver() {
  if (impl_->stencil) HYPRE_StructStencilDestroy(impl_->stencil);
  if (impl_->hgrid) HYPRE_StructGridDestroy(impl_->hgrid);
}

LinearSolveResult PressureSolver::solve(const StencilCoefficients& A, const CellScalars& b, CellScalars& x) {
  Impl& im = *impl_;
  const Grid& g = *im.grid;
  const HypreSettings& hs = im.settings;
  LinearSolveResult result;

  // b = 0: x = 0 exactly (hypre's relative residual would be 0/0).
  double bmax = 0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) { bmax = std::max(bmax, std::abs(b[pi](i, j, k))); });
  if (im.distributed) bmax = all_max(bmax);  // every rank takes the same branch
  if (bmax == 0.0) {
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) { x[pi](i, j, k) = 0.0; });
    result.converged = true;
    return result;
  }

  HYPRE_StructMatrix HA = nullptr;
  HYPRE_StructVector hb = nullptr, hx = nullptr;
  check(HYPRE_StructMatrixCreate(im.comm, im.hgrid, im.stencil, &HA), "StructMatrixCreate");
  check(HYPRE_StructMatrixInitialize(HA), "StructMatrixInitialize");
  check(HYPRE_StructVectorCreate(im.comm, im.hgrid, &hb), "StructVectorCreate");
  check(HYPRE_StructVectorCreate(im.comm, im.hgrid, &hx), "StructVectorCreate");
  check(HYPRE_StructVectorInitialize(hb), "StructVectorInitialize");
  check(HYPRE_StructVectorInitialize(hx), "StructVectorInitialize");

  // Assembly per patch: values ordered stencil entry fastest, then i, j, k.
  HYPRE_Int entries[kStencilSize];
  for (int s = 0; s < kStencilSize; ++s) entries[s] = s;
  std::vector<double> vals, bv, xv;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    Box& box = im.boxes[pi];
    vals.assign(box.size * kStencilSize, 0.0);
    bv.assign(box.size, 0.0);
    xv.assign(box.size, 0.0);
    std::size_t n = 0;
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      for (int s = 0; s < kStencilSize; ++s) vals[n * kStencilSize + s] = A[s][pi](i, j, k);
      bv[n] = b[pi](i, j, k);
      ++n;
    });
    check(HYPRE_StructMatrixSetBoxValues(HA, box.lo, box.hi, kStencilSize, entries, vals.data()), "MatrixSetBoxValues");
    check(HYPRE_StructVectorSetBoxValues(hb, box.lo, box.hi, bv.data()), "VectorSetBoxValues");
    check(HYPRE_StructVectorSetBoxValues(hx, box.lo, box.hi, xv.data()), "VectorSetBoxValues");
  }
  check(HYPRE_StructMatrixAssemble(HA), "StructMatrixAssemble");
  check(HYPRE_StructVectorAssemble(hb), "StructVectorAssemble");
  check(HYPRE_StructVectorAssemble(hx), "StructVectorAssemble");

  const double tol = std::max(hs.tolerance, kRoundOffFloor);
  HYPRE_StructSolver solver = nullptr, precond = nullptr;
  HYPRE_Int its = 0;
  HYPRE_Real res = 0;

  // Multigrid preconditioner: one V-cycle from a zero guess.
  auto make_precond = [&]() {
    if (hs.preconditioner == "pfmg") {
      HYPRE_StructPFMGCreate(im.comm, &precond);
      HYPRE_StructPFMGSetMaxIter(precond, 1);
      HYPRE_StructPFMGSetTol(precond, 0.0);
      HYPRE_StructPFMGSetZeroGuess(precond);
      HYPRE_StructPFMGSetRelaxType(precond, hs.relax_type);
      HYPRE_StructPFMGSetNumPreRelax(precond, hs.npre);
      HYPRE_StructPFMGSetNumPostRelax(precond, hs.npost);
      HYPRE_StructPFMGSetSkipRelax(precond, hs.skip);
    } else if (hs.preconditioner == "smg") {
      HYPRE_StructSMGCreate(im.comm, &precond);
      HYPRE_StructSMGSetMaxIter(precond, 1);
      HYPRE_StructSMGSetTol(precond, 0.0);
      HYPRE_StructSMGSetZeroGuess(precond);
      HYPRE_StructSMGSetNumPreRelax(precond, hs.npre);
      HYPRE_StructSMGSetNumPostRelax(precond, hs.npost);
    }
  };
  auto destroy_precond = [&]() {
    if (!precond) return;
    if (hs.preconditioner == "pfmg") HYPRE_StructPFMGDestroy(precond);
    else if (hs.preconditioner == "smg") HYPRE_StructSMGDestroy(precond);
  };

  if (hs.solver == "cg") {
    HYPRE_StructPCGCreate(im.comm, &solver);
    HYPRE_StructPCGSetTol(solver, tol);
    HYPRE_StructPCGSetMaxIter(solver, hs.max_iterations);
    HYPRE_StructPCGSetTwoNorm(solver, 1);
    HYPRE_StructPCGSetRelChange(solver, 0);
    make_precond();
    if (hs.preconditioner == "pfmg")
      HYPRE_StructPCGSetPrecond(solver, HYPRE_StructPFMGSolve, HYPRE_StructPFMGSetup, precond);
    else if (hs.preconditioner == "smg")
      HYPRE_StructPCGSetPrecond(solver, HYPRE_StructSMGSolve, HYPRE_StructSMGSetup, precond);
    else if (hs.preconditioner == "jacobi")
      HYPRE_StructPCGSetPrecond(solver, HYPRE_StructDiagScale, HYPRE_StructDiagScaleSetup, nullptr);
    check(HYPRE_StructPCGSetup(solver, HA, hb, hx), "PCG setup");
    check(HYPRE_StructPCGSolve(solver, HA, hb, hx), "PCG solve");
    HYPRE_StructPCGGetNumIterations(solver, &its);
    HYPRE_StructPCGGetFinalRelativeResidualNorm(solver, &res);
    HYPRE_StructPCGDestroy(solver);
    destroy_precond();
  } else if (hs.solver == "gmres") {
    HYPRE_StructGMRESCreate(im.comm, &solver);
    HYPRE_StructGMRESSetTol(solver, tol);
    HYPRE_StructGMRESSetMaxIter(solver, hs.max_iterations);
    make_precond();
    if (hs.preconditioner == "pfmg")
      HYPRE_StructGMRESSetPrecond(solver, HYPRE_StructPFMGSolve, HYPRE_StructPFMGSetup, precond);
    else if (hs.preconditioner == "smg")
      HYPRE_StructGMRESSetPrecond(solver, HYPRE_StructSMGSolve, HYPRE_StructSMGSetup, precond);
    else if (hs.preconditioner == "jacobi")
      HYPRE_StructGMRESSetPrecond(solver, HYPRE_StructDiagScale, HYPRE_StructDiagScaleSetup, nullptr);
    check(HYPRE_StructGMRESSetup(solver, HA, hb, hx), "GMRES setup");
    check(HYPRE_StructGMRESSolve(solver, HA, hb, hx), "GMRES solve");
    HYPRE_StructGMRESGetNumIterations(solver, &its);
    HYPRE_StructGMRESGetFinalRelativeResidualNorm(solver, &res);
    HYPRE_StructGMRESDestroy(solver);
    destroy_precond();
  } else if (hs.solver == "pfmg") {
    HYPRE_StructPFMGCreate(im.comm, &solver);
    HYPRE_StructPFMGSetTol(solver, tol);
    HYPRE_StructPFMGSetMaxIter(solver, hs.max_iterations);
    HYPRE_StructPFMGSetRelaxType(solver, hs.relax_type);
    HYPRE_StructPFMGSetNumPreRelax(solver, hs.npre);
    HYPRE_StructPFMGSetNumPostRelax(solver, hs.npost);
    HYPRE_StructPFMGSetSkipRelax(solver, hs.skip);
    check(HYPRE_StructPFMGSetup(solver, HA, hb, hx), "PFMG setup");
    check(HYPRE_StructPFMGSolve(solver, HA, hb, hx), "PFMG solve");
    HYPRE_StructPFMGGetNumIterations(solver, &its);
    HYPRE_StructPFMGGetFinalRelativeResidualNorm(solver, &res);
    HYPRE_StructPFMGDestroy(solver);
  } else {  // smg
    HYPRE_StructSMGCreate(im.comm, &solver);
    HYPRE_StructSMGSetTol(solver, tol);
    HYPRE_StructSMGSetMaxIter(solver, hs.max_iterations);
    HYPRE_StructSMGSetNumPreRelax(solver, hs.npre);
    HYPRE_StructSMGSetNumPostRelax(solver, hs.npost);
    check(HYPRE_StructSMGSetup(solver, HA, hb, hx), "SMG setup");
    check(HYPRE_StructSMGSolve(solver, HA, hb, hx), "SMG solve");
    HYPRE_StructSMGGetNumIterations(solver, &its);
    HYPRE_StructSMGGetFinalRelativeResidualNorm(solver, &res);
    HYPRE_StructSMGDestroy(solver);
  }
  HYPRE_ClearAllErrors();

  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    Box& box = im.boxes[pi];
    xv.assign(box.size, 0.0);
    check(HYPRE_StructVectorGetBoxValues(hx, box.lo, box.hi, xv.data()), "VectorGetBoxValues");
    std::size_t n = 0;
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) { x[pi](i, j, k) = xv[n++]; });
  }
  HYPRE_StructMatrixDestroy(HA);
  HYPRE_StructVectorDestroy(hb);
  HYPRE_StructVectorDestroy(hx);

  result.iterations = int(its);
  result.relative_residual = double(res);
  result.converged = std::isfinite(result.relative_residual) && result.relative_residual <= tol;
  return result;
}

}  // namespace tephra
