// Donor outflow bounds of second-order advection (the math: AdvectionBounds.h).
#include "ice/AdvectionBounds.h"

#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"
#include "ice/RowLoop.h"

namespace tephra {

namespace {
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }

// for_each_row (ice/RowLoop.h) with a kernel that returns whether its row
// marked a cell; returns whether any row did. Every row runs; the OR is
// exact, so the result does not depend on the thread count.
template <class Kernel>
bool any_row_marks(const IndexRange& r, Kernel&& kernel) {
  if (r.empty()) return false;
  bool any = false;
#pragma omp parallel for collapse(2) schedule(static) reduction(|| : any) if (r.size() >= kMinCellsPerParallelLoop)
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      if (kernel(j, k)) any = true;
  return any;
}
}  // namespace

// Row kernel (ice/RowLoop.h): one pointer per face array and row; the sums
// F1 and F run over the faces in the order x-low, x-high, y-low, y-high,
// z-low, z-high, with the expressions of the cell loop this replaced
// (phi_lo = -u r, F1 += phi w q_D with w = 1.0 when unweighted), so the
// limits are bit for bit those of that loop. Rows write only their own
// cells, and the rows' "limited" answers are OR-ed (any_row_marks), so any
// thread count gives the same result.
bool outflow_limits(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                    const FaceScalars& flux, CellScalars& limit, const RadialWeights* radial) {
  limit.fill(1.0);
  bool any = false;
  const double r[3] = {dt / g.dx[0], dt / g.dx[1], dt / g.dx[2]};
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    const bool patch_any = any_row_marks(cells, [&](int j, int k) {
      const double* qr = row_ptr(q[pi], i0, j, k);
      double* lim = row_ptr(limit[pi], i0, j, k);
      // Low and high face of each axis: (u, F, w) rows; the x high face is entry c + 1 of the low row.
      const double* ul[3] = {row_ptr(u.at(0, pi), i0, j, k), row_ptr(u.at(1, pi), i0, j, k),
                             row_ptr(u.at(2, pi), i0, j, k)};
      const double* uh[3] = {ul[0] + 1, row_ptr(u.at(1, pi), i0, j + 1, k), row_ptr(u.at(2, pi), i0, j, k + 1)};
      const double* Fl[3] = {row_ptr(flux.at(0, pi), i0, j, k), row_ptr(flux.at(1, pi), i0, j, k),
                             row_ptr(flux.at(2, pi), i0, j, k)};
      const double* Fh[3] = {Fl[0] + 1, row_ptr(flux.at(1, pi), i0, j + 1, k), row_ptr(flux.at(2, pi), i0, j, k + 1)};
      const double* wl[3] = {nullptr, nullptr, nullptr};
      const double* wh[3] = {nullptr, nullptr, nullptr};
      if (weight)
        for (int d = 0; d < 3; ++d) {
          wl[d] = row_ptr(weight->at(d, pi), i0, j, k);
          wh[d] = d == 0 ? wl[0] + 1 : row_ptr(weight->at(d, pi), i0, j + (d == 1), k + (d == 2));
        }
      bool row_limited = false;
      const double* rlo = radial ? radial->lo_row(i0) : nullptr;
      const double* rhi = radial ? radial->hi_row(i0) : nullptr;
      for (int c = 0; c < n; ++c) {
        const double qD = qr[c];
        double F1 = 0, F = 0;  // first-order and actual outflow of the cell
        for (int d = 0; d < 3; ++d) {
          const double phi_lo = -ul[d][c] * r[d], phi_hi = uh[d][c] * r[d];
          // Axisymmetric: the r-faces' share of D's volume, r_f/r_D (ice/RadialWeights.h).
          const double gl = radial && d == 0 ? rlo[c] : 1.0, gh = radial && d == 0 ? rhi[c] : 1.0;
          if (phi_lo > 0) {
            F1 += gl * (phi_lo * (weight ? wl[d][c] : 1.0) * qD);
            F -= gl * Fl[d][c];
          }
          if (phi_hi > 0) {
            F1 += gh * (phi_hi * (weight ? wh[d][c] : 1.0) * qD);
            F += gh * Fh[d][c];
          }
        }
        const double A = 0.5 * (qD + F1);
        if (F > A && F > F1) {
          lim[c] = std::max(0.0, (A - F1) / (F - F1));
          row_limited = true;
        }
      }
      return row_limited;
    });
    any = any || patch_any;
  }
  return any;
}

void limit_outflow(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                   const CellScalars& limit, FaceScalars& flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const IntVec3 e = IntVec3::Unit(d);
      const double r = dt / g.dx[d];
      GridArray<double>& F = flux.at(d, pi);
      const GridArray<double>& uf = u.at(d, pi);
      for_each_cell_serial(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 R(i, j, k);
        const double phi = uf(R) * r;
        if (phi == 0.0) return;
        const IntVec3 D = phi > 0 ? IntVec3(R - e) : R;
        const double s = limit[pi](D);
        if (s >= 1.0) return;
        const double F1 = phi * (weight ? weight->at(d, pi)(R) : 1.0) * q[pi](D);
        F(R) = F1 + s * (F(R) - F1);
      });
    }
}

// Row kernels, as outflow_limits: the range over the neighbours and the
// outgoing sums in the order of the cell loop they replaced (x, y, z; low
// face before high face), so the flags are the same.
bool flag_out_of_range_donors(const Grid& g, const CellScalars& psi, const CellScalars& mass,
                              const FaceScalars& mass_flux, const FaceScalars& psi_flux, CellScalars& flag,
                              const RadialWeights* radial) {
  bool any = false;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    flag[pi].fill(0.0);
    const IndexRange cells = g.patches[pi].cells();
    const int i0 = cells.lo[0], n = cells.hi[0] - i0;
    const bool patch_any = any_row_marks(cells, [&](int j, int k) {
      const double* ps = row_ptr(psi[pi], i0, j, k);
      const double* M_row = row_ptr(mass[pi], i0, j, k);
      // Neighbour rows of psi (-d, +d) and low/high face rows of the fluxes per axis d.
      const double* pn[3][2] = {{ps - 1, ps + 1},
                                {row_ptr(psi[pi], i0, j - 1, k), row_ptr(psi[pi], i0, j + 1, k)},
                                {row_ptr(psi[pi], i0, j, k - 1), row_ptr(psi[pi], i0, j, k + 1)}};
      const double* mf[3][2];
      const double* qf[3][2];
      for (int d = 0; d < 3; ++d) {
        mf[d][0] = row_ptr(mass_flux.at(d, pi), i0, j, k);
        qf[d][0] = row_ptr(psi_flux.at(d, pi), i0, j, k);
        mf[d][1] = d == 0 ? mf[0][0] + 1 : row_ptr(mass_flux.at(d, pi), i0, j + (d == 1), k + (d == 2));
        qf[d][1] = d == 0 ? qf[0][0] + 1 : row_ptr(psi_flux.at(d, pi), i0, j + (d == 1), k + (d == 2));
      }
      double* fl = row_ptr(flag[pi], i0, j, k);
      bool row_flagged = false;
      const double* rlo = radial ? radial->lo_row(i0) : nullptr;
      const double* rhi = radial ? radial->hi_row(i0) : nullptr;
      for (int c = 0; c < n; ++c) {
        const double p = ps[c], M = M_row[c];
        double lo = p, hi = p, out_M = 0, out_Q = 0;
        for (int d = 0; d < 3; ++d) {
          lo = std::min({lo, pn[d][0][c], pn[d][1][c]});
          hi = std::max({hi, pn[d][0][c], pn[d][1][c]});
          // Outgoing: negative flux on the low face, positive on the high face (the mass flux decides the donor).
          if (radial && d == 0) {  // axisymmetric: r-faces weighted by r_f/r_D (ice/RadialWeights.h)
            if (mf[0][0][c] < 0) out_M -= rlo[c] * mf[0][0][c], out_Q -= rlo[c] * qf[0][0][c];
            if (mf[0][1][c] > 0) out_M += rhi[c] * mf[0][1][c], out_Q += rhi[c] * qf[0][1][c];
            continue;
          }
          if (mf[d][0][c] < 0) out_M -= mf[d][0][c], out_Q -= qf[d][0][c];
          if (mf[d][1][c] > 0) out_M += mf[d][1][c], out_Q += qf[d][1][c];
        }
        if (out_M == 0.0) continue;
        const double RM = M - out_M, RQ = M * p - out_Q;
        // Round-off allowance of each comparison, relative to the terms in it
        // (RQ = M p - out_Q against psi_b (M - out_M)). Not the neighbourhood's
        // largest |psi| times M: a near-vacuum trace neighbour (v = 8.4e7
        // m^3/kg beside a donor's 2.2e-3 in the axisymmetric cookoff at
        // 1.097 ms) made that allowance 1e10 times the donor's content, the
        // donor sent 1.03 times its M v and kept v = -1.2e-4 (docs/mpmice.md
        // "Session 27: the contents' range check").
        const double terms = std::abs(M * p) + std::abs(out_Q);
        const double tol_lo = 1e-12 * (terms + std::abs(lo) * (M + out_M));
        const double tol_hi = 1e-12 * (terms + std::abs(hi) * (M + out_M));
        const bool bad = RM > 0 ? (RQ < lo * RM - tol_lo || RQ > hi * RM + tol_hi) : out_Q > M * p;
        if (bad) {
          fl[c] = 1.0;
          row_flagged = true;
        }
      }
      return row_flagged;
    });
    any = any || patch_any;
  }
  return any;
}

void donor_value_fluxes(const Grid& g, const CellScalars& psi, const FaceScalars& mass_flux, const CellScalars& flag,
                        FaceScalars& psi_flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const IndexRange faces = faces_of(g.patches[pi], d);
      const int i0 = faces.lo[0], n = faces.hi[0] - i0;
      const int ex = d == 0, ey = d == 1, ez = d == 2;
      for_each_row(faces, [&](int j, int k) {
        const double* mf = row_ptr(mass_flux.at(d, pi), i0, j, k);
        double* F = row_ptr(psi_flux.at(d, pi), i0, j, k);
        // The face's low cell (donor when mf > 0) and high cell, for flag and psi.
        const double* flag_lo = row_ptr(flag[pi], i0 - ex, j - ey, k - ez);
        const double* flag_hi = row_ptr(flag[pi], i0, j, k);
        const double* psi_lo = row_ptr(psi[pi], i0 - ex, j - ey, k - ez);
        const double* psi_hi = row_ptr(psi[pi], i0, j, k);
        for (int c = 0; c < n; ++c) {
          const bool from_low = mf[c] > 0.0;
          if ((from_low ? flag_lo[c] : flag_hi[c]) != 0.0) F[c] = mf[c] * (from_low ? psi_lo[c] : psi_hi[c]);
        }
      });
    }
}

}  // namespace tephra
