// Donor outflow bounds of second-order advection (the math: AdvectionBounds.h).
#include "ice/AdvectionBounds.h"

#include <algorithm>
#include <cmath>

#include <vector>

#include "core/grid/Loop.h"
#include "ice/RowLoop.h"

namespace tephra {

namespace {
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }
}  // namespace

// Row kernel (ice/RowLoop.h): one pointer per face array and row; the sums
// F1 and F run over the faces in the order x-low, x-high, y-low, y-high,
// z-low, z-high, with the expressions of the cell loop this replaced
// (phi_lo = -u r, F1 += phi w q_D with w = 1.0 when unweighted), so the
// limits are bit for bit those of that loop. Rows write only their own
// cells and their own entry of row_any, so any thread count gives the same
// result.
bool outflow_limits(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                    const FaceScalars& flux, CellScalars& limit) {
  limit.fill(1.0);
  bool any = false;
  const double r[3] = {dt / g.dx[0], dt / g.dx[1], dt / g.dx[2]};
  std::vector<unsigned char> row_any;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange cells = g.patches[pi].cells();
    if (cells.empty()) continue;
    const int i0 = cells.lo[0], n = cells.hi[0] - i0, j0 = cells.lo[1], nj = cells.hi[1] - j0, k0 = cells.lo[2];
    row_any.assign(std::size_t(nj) * std::size_t(cells.hi[2] - k0), 0);
    for_each_row(cells, [&](int j, int k) {
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
      for (int c = 0; c < n; ++c) {
        const double qD = qr[c];
        double F1 = 0, F = 0;  // first-order and actual outflow of the cell
        for (int d = 0; d < 3; ++d) {
          const double phi_lo = -ul[d][c] * r[d], phi_hi = uh[d][c] * r[d];
          if (phi_lo > 0) {
            F1 += phi_lo * (weight ? wl[d][c] : 1.0) * qD;
            F -= Fl[d][c];
          }
          if (phi_hi > 0) {
            F1 += phi_hi * (weight ? wh[d][c] : 1.0) * qD;
            F += Fh[d][c];
          }
        }
        const double A = 0.5 * (qD + F1);
        if (F > A && F > F1) {
          lim[c] = std::max(0.0, (A - F1) / (F - F1));
          row_limited = true;
        }
      }
      if (row_limited) row_any[std::size_t(k - k0) * std::size_t(nj) + std::size_t(j - j0)] = 1;
    });
    for (unsigned char a : row_any) any = any || a != 0;
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

bool flag_out_of_range_donors(const Grid& g, const CellScalars& psi, const CellScalars& mass,
                              const FaceScalars& mass_flux, const FaceScalars& psi_flux, CellScalars& flag) {
  bool any = false;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    flag[pi].fill(0.0);
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      const double p = psi[pi](c), M = mass[pi](c);
      double lo = p, hi = p, out_M = 0, out_Q = 0;
      for (int d = 0; d < 3; ++d) {
        const IntVec3 e = IntVec3::Unit(d), up = c + e;
        lo = std::min({lo, psi[pi](IntVec3(c - e)), psi[pi](up)});
        hi = std::max({hi, psi[pi](IntVec3(c - e)), psi[pi](up)});
        // Outgoing: negative flux on the low face, positive on the high face (the mass flux decides the donor).
        if (mass_flux.at(d, pi)(c) < 0) out_M -= mass_flux.at(d, pi)(c), out_Q -= psi_flux.at(d, pi)(c);
        if (mass_flux.at(d, pi)(up) > 0) out_M += mass_flux.at(d, pi)(up), out_Q += psi_flux.at(d, pi)(up);
      }
      if (out_M == 0.0) return;
      const double RM = M - out_M, RQ = M * p - out_Q;
      const double tol = 1e-12 * std::max(std::abs(lo), std::abs(hi)) * M;
      const bool bad = RM > 0 ? (RQ < lo * RM - tol || RQ > hi * RM + tol) : out_Q > M * p;
      if (bad) {
        flag[pi](c) = 1.0;
        any = true;
      }
    });
  }
  return any;
}

void donor_value_fluxes(const Grid& g, const CellScalars& psi, const FaceScalars& mass_flux, const CellScalars& flag,
                        FaceScalars& psi_flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& mf = mass_flux.at(d, pi);
      GridArray<double>& F = psi_flux.at(d, pi);
      for_each_cell_serial(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const IntVec3 f(i, j, k);
        const IntVec3 donor = mf(f) > 0.0 ? IntVec3(f - IntVec3::Unit(d)) : f;
        if (flag[pi](donor) != 0.0) F(f) = mf(f) * psi[pi](donor);
      });
    }
}

}  // namespace tephra
