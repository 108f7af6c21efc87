// The implicit pressure matrix against the finite-difference Jacobian of the
// residual (a check of ImplicitPressureMatrix.cpp, and the trace of a stalled
// outer iteration).
//
// The outer iteration (ImplicitPressure.cpp) solves A dp = rhs with
// rhs = -R(p), so Newton's method needs A = dR/dp = -d(rhs)/dp. Row c of A
// holds A_cc (kCenter) and A_cn (the six neighbours). The finite-difference
// row perturbs p in cell n by +-h (h = 1e-7 |p_n|, at least 1e-3 Pa),
// recomputes the face velocities, their exchange and the residual exactly as
// an outer iteration does, and takes
//   J+_cn = -(rhs_c(p + h e_n) - rhs_c(p)) / h,  J-_cn = -(rhs_c(p) - rhs_c(p - h e_n)) / h.
// Where the residual is smooth J+ = J- = A_cn up to O(h); J+ != J- marks a
// switch (donor cell, clamp, positivity limit) at p. The state (p, the face
// velocities, rhs_) is restored on return; the matrix is not touched.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <vector>

#include "core/grid/Loop.h"
#include "ice/IceComponent.h"

namespace tephra {

namespace {
// The patch of this process whose interior holds c (or -1).
int owner_patch(const Grid& g, const IntVec3& c) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    if (g.patches[pi].cells().contains(c)) return static_cast<int>(pi);
  return -1;
}
}  // namespace

double IceComponent::residual_after_shift(double dt, const IntVec3& n, double shift, const IntVec3& c) {
  const Grid& g = setup_.grid;
  const int pn = owner_patch(g, n);
  if (pn >= 0) press_CC_[pn](n) += shift;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) apply_pressure_bc(pi, press_CC_);
  halo_->exchange(press_CC_);
  compute_face_velocities(dt, press_CC_);
  add_exchange_to_face_velocities(dt);
  pressure_residual(dt);
  const int pc = owner_patch(g, c);
  const double r = pc >= 0 ? rhs_[pc](c) : 0.0;
  if (pn >= 0) press_CC_[pn](n) -= shift;
  return r;
}

IceComponent::JacobianRow IceComponent::implicit_jacobian_row(double dt, const IntVec3& cell) {
  const IntVec3 c = cell;  // a copy: `cell` may be max_rhs_cell_, which pressure_residual rewrites
  const Grid& g = setup_.grid;
  JacobianRow row;
  row.cell = c;
  const int pc = owner_patch(g, c);
  if (pc < 0) return row;
  const CellScalars saved = press_CC_;
  for (int s = 0; s < kStencilSize; ++s) {
    IntVec3 n = c;
    if (s > 0) n[(s - 1) / 2] += (s - 1) % 2 == 0 ? -1 : 1;  // kWest, kEast, kSouth, ...
    row.matrix[s] = stencil_[s][pc](c);
    const int pn = owner_patch(g, n);
    if (pn < 0) continue;  // outside the domain (or another rank's)
    const double h = std::max(1e-3, 1e-7 * std::abs(press_CC_[pn](n)));
    const double r0 = residual_after_shift(dt, n, 0.0, c);
    const double rp = residual_after_shift(dt, n, h, c);
    const double rm = residual_after_shift(dt, n, -h, c);
    row.fd_plus[s] = -(rp - r0) / h;
    row.fd_minus[s] = -(r0 - rm) / h;
  }
  press_CC_ = saved;
  compute_face_velocities(dt, press_CC_);
  add_exchange_to_face_velocities(dt);
  pressure_residual(dt);
  return row;
}

// TEPHRA_IMPLICIT_TRACE=1: per outer iteration, the largest residuals, the
// volume fractions there and the matrix row against the finite-difference
// Jacobian (stderr). A diagnostic of stalled solves, off by default.
bool IceComponent::implicit_trace_enabled() {
  static const bool on = [] {
    const char* v = std::getenv("TEPHRA_IMPLICIT_TRACE");
    return v != nullptr && v[0] != '\0' && v[0] != '0';
  }();
  return on;
}

void IceComponent::trace_outer_iteration(double dt, int step, int it, double max_rhs) {
  const Grid& g = setup_.grid;
  std::ostringstream os;
  os << std::setprecision(4) << "implicit trace: step " << step << " outer " << it << " max|R| " << max_rhs;
  // The five largest |rhs| cells.
  std::vector<std::pair<double, IntVec3>> top;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      top.emplace_back(std::abs(rhs_[pi](i, j, k)), IntVec3(i, j, k));
    });
  const std::size_t n = std::min<std::size_t>(5, top.size());
  std::partial_sort(top.begin(), top.begin() + static_cast<long>(n), top.end(),
                    [](const auto& a, const auto& b) { return a.first > b.first; });
  for (std::size_t q = 0; q < n; ++q) {
    const IntVec3& c = top[q].second;
    const int pc = owner_patch(g, c);
    os << "\n  cell (" << c[0] << "," << c[1] << "," << c[2] << ") rhs " << rhs_[pc](c) << " p " << press_CC_[pc](c)
       << " p_eq " << press_equil_CC_[pc](c) << " theta";
    for (const IceMaterialFields& f : mats_) os << " " << f.vol_frac_CC[pc](c);
    if (q < 3) {
      // Per face: every solid's theta_s,face and phi_s, the fluids' phi.
      for (int d = 0; d < 2; ++d)
        for (int side = 0; side < 2; ++side) {
          const IntVec3 R = side == 0 ? c : IntVec3(c + IntVec3::Unit(d));
          os << "\n    face " << "xy"[d] << (side == 0 ? "-" : "+") << ":";
          for (std::size_t m = 0; m < mats_.size(); ++m) {
            const double phi = mats_[m].vel_FCME.at(d, pc)(R) * dt / g.dx[d];
            if (has_lagrangian_flux(m)) {
              const SolidFaceFraction sf = solid_face_fraction(m, d, pc, R, dt);
              os << " [s" << m << " F " << lag_mass_flux_[m].at(d, pc)(R) * mats_[m].sp_vol_CC[pc](c) / g.cell_volume()
                 << " phi " << phi << " th " << sf.theta << "]";
            } else {
              os << " [f" << m << " phi " << phi << " lim " << lag_limit_[pc](c) << "]";
            }
          }
        }
      const JacobianRow row = implicit_jacobian_row(dt, c);
      os << "\n    A   ";
      for (double a : row.matrix) os << " " << a;
      os << "\n    J+  ";
      for (double a : row.fd_plus) os << " " << a;
      os << "\n    J-  ";
      for (double a : row.fd_minus) os << " " << a;
    }
  }
  std::cerr << os.str() << std::endl;
}

}  // namespace tephra
