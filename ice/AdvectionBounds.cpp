// Donor outflow bounds of second-order advection (the math: AdvectionBounds.h).
#include "ice/AdvectionBounds.h"

#include <algorithm>
#include <cmath>

#include "core/grid/Loop.h"

namespace tephra {

namespace {
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }
}  // namespace

bool outflow_limits(const Grid& g, const CellScalars& q, const FaceScalars& u, const FaceScalars* weight, double dt,
                    const FaceScalars& flux, CellScalars& limit) {
  limit.fill(1.0);
  bool any = false;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      const double qD = q[pi](c);
      double F1 = 0, F = 0;  // first-order and actual outflow of c
      for (int d = 0; d < 3; ++d) {
        const IntVec3 hi = c + IntVec3::Unit(d);
        const double r = dt / g.dx[d];
        const double phi_lo = -u.at(d, pi)(c) * r, phi_hi = u.at(d, pi)(hi) * r;
        if (phi_lo > 0) {
          F1 += phi_lo * (weight ? weight->at(d, pi)(c) : 1.0) * qD;
          F -= flux.at(d, pi)(c);
        }
        if (phi_hi > 0) {
          F1 += phi_hi * (weight ? weight->at(d, pi)(hi) : 1.0) * qD;
          F += flux.at(d, pi)(hi);
        }
      }
      const double A = 0.5 * (qD + F1);
      if (F > A && F > F1) {
        limit[pi](c) = std::max(0.0, (A - F1) / (F - F1));
        any = true;
      }
    });
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
