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

// Calls kernel(view) with the view of s's storage form.
template <class Kernel>
void visit_stencils(const Stencils& s, Kernel&& kernel) {
  if (s.axis_nodes == 2) kernel(AxisStencilView<2>{s});
  else if (s.axis_nodes == 3) kernel(AxisStencilView<3>{s});
  else kernel(FlatStencilView{s});
}

}  // namespace tephra
