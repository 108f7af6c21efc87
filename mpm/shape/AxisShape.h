#pragma once
// The 1-D factors of one particle along one axis for the tensor-product
// interpolators (linear, gimp, 3rdorderBS), with the validity rule of the
// per-axis stencils: xi = (x - origin)/h in [0, n - 1), the support of N
// nodes inside the grid. Shared by compute_axis_stencils
// (mpm/shape/ComputeStencils.cpp) and MPMICE's solid mass fluxes
// (mpmice/SolidVolumeFlux.cpp), so both form the same bits.
#include "mpm/shape/Interpolator.h"
#include "mpm/shape/ShapeAxis.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeGimp.h"
#include "mpm/shape/ShapeLinear.h"

namespace tephra {

// Nodes per axis of the per-axis form of `k`; 0 when it has none.
inline int axis_nodes_of(InterpolatorKind k) {
  switch (k) {
    case InterpolatorKind::Linear: return 2;
    case InterpolatorKind::Gimp: return 3;
    case InterpolatorKind::QuadraticBspline: return 3;
    default: return 0;
  }
}

// ax = the factors of coordinate x (half_length: the GIMP particle's half
// size along the axis); false where the per-axis form does not apply.
template <InterpolatorKind K, int N>
inline bool axis_shape(double x, double origin, double h, int n, double half_length, ShapeAxis& ax) {
  const double xi = (x - origin) / h;
  if (!(xi >= 0.0 && xi < n - 1)) return false;
  if constexpr (K == InterpolatorKind::Linear) ax = linear_axis(xi);
  if constexpr (K == InterpolatorKind::Gimp) ax = gimp_axis(xi, half_length);
  if constexpr (K == InterpolatorKind::QuadraticBspline) ax = quadratic_bspline_axis(xi);
  return ax.count == N && ax.first >= 0 && ax.first + N <= n;
}

// The same with the interpolator chosen at run time (kind must have a per-axis form).
inline bool axis_shape(InterpolatorKind kind, double x, double origin, double h, int n, double half_length,
                       ShapeAxis& ax) {
  switch (kind) {
    case InterpolatorKind::Linear: return axis_shape<InterpolatorKind::Linear, 2>(x, origin, h, n, half_length, ax);
    case InterpolatorKind::Gimp: return axis_shape<InterpolatorKind::Gimp, 3>(x, origin, h, n, half_length, ax);
    case InterpolatorKind::QuadraticBspline:
      return axis_shape<InterpolatorKind::QuadraticBspline, 3>(x, origin, h, n, half_length, ax);
    default: return false;
  }
}

}  // namespace tephra
