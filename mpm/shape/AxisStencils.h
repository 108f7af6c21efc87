#pragma once
// Entry-by-entry access to a particle's stencil in either storage form of
// Stencils (mpm/shape/Interpolator.h), for the transfer kernels. A kernel is
// written once as a generic lambda over a view and instantiated for the flat
// form and the per-axis forms N = 2 (linear) and N = 3 (gimp, 3rdorderBS):
//   visit_stencils(s, [&](const auto& view) { ... view.weights(i, f) ... });
// view.weights(i, f) calls f(node, S_gp) and view.entries(i, f) calls
// f(node, S_gp, grad S_gp) for every entry of particle i, in the flat order
// (x fastest, then y, then z).
//
// Per-axis form: S_gp = S_x[a] S_y[b] S_z[c] (the same product, in the same
// order, as tensor_product in ShapeAxis.h, so the same bits);
// grad S_gp = (G_x[a] S_y[b] S_z[c], S_x[a] G_y[b] S_z[c], S_x[a] S_y[b] G_z[c])
// with G_d = (dS_d/dxi)/h_d (the theory manual's eq. 1.89 for linear, 1.92
// for GIMP, per axis).
#include <cstddef>

#include "core/base/Types.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

struct FlatStencilView {
  const Stencils& s;
  template <class F>
  void weights(std::size_t i, F&& f) const {
    const std::size_t W = std::size_t(s.width);
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) f(s.node[k], s.w[k]);
  }
  template <class F>
  void entries(std::size_t i, F&& f) const {
    const std::size_t W = std::size_t(s.width);
    for (std::size_t k = i * W; k < (i + 1) * W; ++k) f(s.node[k], s.w[k], s.grad[k]);
  }
};

template <int N>
struct AxisStencilView {
  const Stencils& s;
  template <class F>
  void weights(std::size_t i, F&& f) const {
    const double* S = s.factors.data() + i * 6 * N;
    const std::size_t base = s.base[i];
    for (int c = 0; c < N; ++c)
      for (int b = 0; b < N; ++b) {
        const std::size_t row = base + s.stride_y * b + s.stride_z * c;
        const double sy = S[N + b], sz = S[2 * N + c];
        for (int a = 0; a < N; ++a) f(row + a, S[a] * sy * sz);
      }
  }
  template <class F>
  void entries(std::size_t i, F&& f) const {
    const double* S = s.factors.data() + i * 6 * N;
    const double* G = S + 3 * N;
    const std::size_t base = s.base[i];
    for (int c = 0; c < N; ++c)
      for (int b = 0; b < N; ++b) {
        const std::size_t row = base + s.stride_y * b + s.stride_z * c;
        const double sy = S[N + b], sz = S[2 * N + c], gy = G[N + b], gz = G[2 * N + c];
        const double syz = sy * sz;
        for (int a = 0; a < N; ++a) {
          const double sx = S[a];
          f(row + a, sx * sy * sz, Vec3(G[a] * syz, sx * gy * sz, sx * sy * gz));
        }
      }
  }
};

// l_p = sum_g v_g (grad S_gp)^T (theory manual eq. 1.73) of particle i.
// Flat form: entry by entry. Per-axis form: sum factorization, the sums over
// a, then b, then c taken one axis at a time (about half the products of the
// entry-by-entry sum; the same value to round-off):
//   l(:,x) = sum_c S_z[c] sum_b S_y[b] sum_a G_x[a] v_abc,
//   l(:,y) = sum_c S_z[c] sum_b G_y[b] sum_a S_x[a] v_abc,
//   l(:,z) = sum_c G_z[c] sum_b S_y[b] sum_a S_x[a] v_abc.
inline Mat3 particle_velocity_gradient(const FlatStencilView& view, std::size_t i, const Vec3* v) {
  double l[3][3] = {};
  view.entries(i, [&](std::size_t gi, double, const Vec3& gr) {
    const Vec3& vg = v[gi];
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) l[r][c] += vg[r] * gr[c];
  });
  Mat3 L;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) L(r, c) = l[r][c];
  return L;
}

template <int N>
Mat3 particle_velocity_gradient(const AxisStencilView<N>& view, std::size_t i, const Vec3* v) {
  const Stencils& s = view.s;
  const double* S = s.factors.data() + i * 6 * N;
  const double* G = S + 3 * N;
  const std::size_t base = s.base[i];
  double lx[3] = {}, ly[3] = {}, lz[3] = {};
  for (int c = 0; c < N; ++c) {
    double ss[3] = {}, gs[3] = {}, sg[3] = {};  // sum_b S_y A, sum_b S_y B, sum_b G_y A
    for (int b = 0; b < N; ++b) {
      const Vec3* row = v + base + s.stride_y * b + s.stride_z * c;
      double A[3] = {}, B[3] = {};  // sum_a S_x v, sum_a G_x v
      for (int a = 0; a < N; ++a)
        for (int r = 0; r < 3; ++r) {
          A[r] += S[a] * row[a][r];
          B[r] += G[a] * row[a][r];
        }
      for (int r = 0; r < 3; ++r) {
        ss[r] += S[N + b] * A[r];
        gs[r] += S[N + b] * B[r];
        sg[r] += G[N + b] * A[r];
      }
    }
    for (int r = 0; r < 3; ++r) {
      lx[r] += S[2 * N + c] * gs[r];
      ly[r] += S[2 * N + c] * sg[r];
      lz[r] += G[2 * N + c] * ss[r];
    }
  }
  Mat3 L;
  for (int r = 0; r < 3; ++r) {
    L(r, 0) = lx[r];
    L(r, 1) = ly[r];
    L(r, 2) = lz[r];
  }
  return L;
}

// Calls kernel(view) with the view of s's storage form.
template <class Kernel>
void visit_stencils(const Stencils& s, Kernel&& kernel) {
  if (s.axis_nodes == 2) kernel(AxisStencilView<2>{s});
  else if (s.axis_nodes == 3) kernel(AxisStencilView<3>{s});
  else kernel(FlatStencilView{s});
}

}  // namespace tephra
