// compute_stencils: one template instance per interpolator, chosen once.
#include <algorithm>
#include <cmath>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/AxisShape.h"
#include "mpm/shape/Interpolator.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeBsplineCubic.h"
#include "mpm/shape/ShapeCpdi.h"
#include "mpm/shape/ShapeCpti.h"
#include "mpm/shape/ShapeGimp.h"
#include "mpm/shape/ShapeLinear.h"

namespace tephra {

int stencil_width(InterpolatorKind k) {
  switch (k) {
    case InterpolatorKind::Linear: return 8;
    case InterpolatorKind::Gimp: return 27;
    case InterpolatorKind::QuadraticBspline: return 27;
    case InterpolatorKind::Cpdi: return 64;
    case InterpolatorKind::CpGimp: return 64;
    case InterpolatorKind::Cpti: return 32;
    case InterpolatorKind::CubicBspline: return 64;
  }
  return 0;
}

std::string interpolator_name(InterpolatorKind k) {
  switch (k) {
    case InterpolatorKind::Linear: return "linear";
    case InterpolatorKind::Gimp: return "gimp";
    case InterpolatorKind::QuadraticBspline: return "3rdorderBS";
    case InterpolatorKind::Cpdi: return "cpdi";
    case InterpolatorKind::CpGimp: return "cpgimp";
    case InterpolatorKind::Cpti: return "cpti";
    case InterpolatorKind::CubicBspline: return "4thorderBS";
  }
  return "?";
}

namespace {

// Fills the W entries of particle i; false when its support leaves the grid
// (or its CPDI domain is degenerate). Writes only particle i's entries.
template <InterpolatorKind K>
bool fill_particle(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, std::size_t i,
                   Stencils& s) {
  constexpr int W = K == InterpolatorKind::Linear ? 8
                    : K == InterpolatorKind::Cpti ? 32
                    : (K == InterpolatorKind::Cpdi || K == InterpolatorKind::CpGimp ||
                       K == InterpolatorKind::CubicBspline)
                        ? 64
                        : 27;
  IntVec3 node[64];
  double w[64];
  Vec3 grad[64];
  // Range check in floating point first: a NaN or huge coordinate must not
  // reach the float -> int conversion of a node index.
  Vec3 xi;
  for (int d = 0; d < 3; ++d) {
    xi[d] = (p.x[i][d] - g.origin[d]) / g.h[d];
    if (!(xi[d] >= 0.0 && xi[d] < g.n[d] - 1)) return false;
  }
  int count = 0;
  bool support_inside = false;  // tensor-product support inside the grid on every axis
  if constexpr (K == InterpolatorKind::Cpdi) {
    const Mat3 edges = p.F[i] * p.psize[i];
    if (!edges.allFinite() || edges.cwiseAbs().maxCoeff() > 4.0 * (g.n.maxCoeff() + 1)) return false;
    if (!cpdi_stencil(xi, edges, spec.cpdi_lcrit, g.h, node, w, grad)) return false;
    count = 64;
  } else if constexpr (K == InterpolatorKind::Cpti) {
    const Mat3 edges = p.F[i] * p.psize[i];
    if (!edges.allFinite() || edges.cwiseAbs().maxCoeff() > 4.0 * (g.n.maxCoeff() + 1)) return false;
    if (!cpti_stencil(xi, edges, spec.cpdi_lcrit, g.h, node, w, grad)) return false;
    count = 32;
  } else {
    ShapeAxis ax[3];
    [[maybe_unused]] double l_cp[3] = {0.0, 0.0, 0.0};
    if constexpr (K == InterpolatorKind::CpGimp) {
      // cpGIMP half-lengths (index units): eq. 1.93 l = F l0 in 1-D; in 3-D
      // the cuboid circumscribing the deformed domain F size (theory manual
      // §1.6.3, ref. [17]): l_d = (1/2) sum_j |(F size)_dj|, = l0_d F_dd for
      // a diagonal F. The convolution of gimp_axis_any holds for 0 < l <= 1.
      const Mat3 edges = p.F[i] * p.psize[i];
      for (int d = 0; d < 3; ++d) {
        l_cp[d] = 0.5 * edges.row(d).cwiseAbs().sum();
        if (!(l_cp[d] > 0.0 && l_cp[d] <= 1.0) || !(p.F[i].determinant() > 0.0)) return false;
      }
    }
    for (int d = 0; d < 3; ++d) {
      if constexpr (K == InterpolatorKind::Linear) ax[d] = linear_axis(xi[d]);
      if constexpr (K == InterpolatorKind::Gimp) ax[d] = gimp_axis(xi[d], 0.5 * p.psize[i](d, d));
      if constexpr (K == InterpolatorKind::QuadraticBspline) ax[d] = quadratic_bspline_axis(xi[d]);
      if constexpr (K == InterpolatorKind::CpGimp) ax[d] = gimp_axis_any(xi[d], l_cp[d]);
      if constexpr (K == InterpolatorKind::CubicBspline) {
        // The support stays within the domain's faces, the node planes
        // extra and n - 1 - extra (no extra-cell node; ShapeBsplineCubic.h).
        const int lo = g.extra[d], top = g.n[d] - 1 - g.extra[d];
        if (!(xi[d] >= lo && xi[d] <= top) || top - lo < 3) return false;
        ax[d] = cubic_bspline_axis(xi[d], lo, top);
      }
    }
    count = tensor_product(ax, g.h, node, w, grad);
    support_inside = true;
    for (int d = 0; d < 3; ++d)
      support_inside = support_inside && ax[d].first >= 0 && ax[d].first + ax[d].count <= g.n[d];
  }
  // Every node with a weight or gradient must exist; a zero entry that falls
  // outside (a support touching the last node layer) is clamped harmlessly.
  const std::size_t base = i * W;
  if (support_inside) {  // the common case: no per-entry range check or clamping
    for (int k = 0; k < count; ++k) {
      s.node[base + k] = g.index(node[k]);
      s.w[base + k] = w[k];
      s.grad[base + k] = grad[k];
    }
    for (int k = count; k < W; ++k) {
      s.node[base + k] = s.node[base];
      s.w[base + k] = 0.0;
      s.grad[base + k] = Vec3::Zero();
    }
    return true;
  }
  for (int k = 0; k < count; ++k) {
    bool inside = true;
    for (int d = 0; d < 3; ++d) inside = inside && node[k][d] >= 0 && node[k][d] < g.n[d];
    if (!inside) {
      if (w[k] != 0.0 || grad[k] != Vec3::Zero()) return false;
      node[k] = node[k].cwiseMax(IntVec3::Zero()).cwiseMin(g.n - IntVec3::Ones());
    }
    s.node[base + k] = g.index(node[k]);
    s.w[base + k] = w[k];
    s.grad[base + k] = grad[k];
  }
  for (int k = count; k < W; ++k) {
    s.node[base + k] = s.node[base];
    s.w[base + k] = 0.0;
    s.grad[base + k] = Vec3::Zero();
  }
  return true;
}

// All particles, split among the OpenMP threads (each writes its own
// entries, so the stencils do not depend on the thread count). The result is
// the lowest failing index, as a serial loop that stops at the first would
// return; -1 when every particle is fine.
template <InterpolatorKind K>
long fill(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s) {
  const long np = static_cast<long>(p.size());
  long bad = np;
#pragma omp parallel for schedule(static) reduction(min : bad) if (np >= 4096)
  for (long i = 0; i < np; ++i)
    if (!fill_particle<K>(p, g, spec, std::size_t(i), s)) bad = std::min(bad, i);
  return bad < np ? bad : -1;
}

// The per-axis form of particle i (Interpolator.h); false when its support
// leaves the grid. Same 1-D factors as fill_particle.
template <InterpolatorKind K, int N>
bool fill_axis_particle(const Particles& p, const NodeGrid& g, const Vec3& inv_h, std::size_t i, Stencils& s) {
  ShapeAxis ax[3];
  for (int d = 0; d < 3; ++d) {
    const double half_length = K == InterpolatorKind::Gimp ? 0.5 * p.psize[i](d, d) : 0.0;
    if (!axis_shape<K, N>(p.x[i][d], g.origin[d], g.h[d], g.n[d], half_length, ax[d])) return false;
  }
  s.base[i] = g.index(ax[0].first, ax[1].first, ax[2].first);
  double* f = s.factors.data() + i * 6 * N;
  for (int d = 0; d < 3; ++d)
    for (int a = 0; a < N; ++a) {
      f[d * N + a] = ax[d].S[a];
      // Linear: dS/dxi = -1, +1 exactly (ShapeLinear.h), and -1/h = -(1/h) in
      // IEEE arithmetic, so G = +-inv_h is the bits of dS / h without a division per entry.
      if constexpr (K == InterpolatorKind::Linear) f[(3 + d) * N + a] = a == 0 ? -inv_h[d] : inv_h[d];
      else f[(3 + d) * N + a] = ax[d].dS[a] / g.h[d];
    }
  return true;
}

template <InterpolatorKind K, int N>
bool fill_axis(const Particles& p, const NodeGrid& g, Stencils& s) {
  const long np = static_cast<long>(p.size());
  s.axis_nodes = N;
  s.width = N * N * N;
  s.stride_y = std::size_t(g.n[0]);
  s.stride_z = std::size_t(g.n[0]) * std::size_t(g.n[1]);
  s.base.resize(std::size_t(np));
  s.factors.resize(std::size_t(np) * 6 * N);
  bool ok = true;
  const Vec3 inv_h(1.0 / g.h[0], 1.0 / g.h[1], 1.0 / g.h[2]);  // linear's G factors (fill_axis_particle)
#pragma omp parallel for schedule(static) reduction(&& : ok) if (np >= 4096)
  for (long i = 0; i < np; ++i) ok = fill_axis_particle<K, N>(p, g, inv_h, std::size_t(i), s) && ok;
  return ok;
}

template <class T>
void release(std::vector<T>& v) {
  std::vector<T>().swap(v);
}

}  // namespace

bool compute_axis_stencils(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s) {
  release(s.node);
  release(s.w);
  release(s.grad);
  s.order.particles = 0;
  s.hoop_factor = false;
  bool ok = false;
  switch (spec.kind) {
    case InterpolatorKind::Linear: ok = fill_axis<InterpolatorKind::Linear, 2>(p, g, s); break;
    case InterpolatorKind::Gimp: ok = fill_axis<InterpolatorKind::Gimp, 3>(p, g, s); break;
    case InterpolatorKind::QuadraticBspline: ok = fill_axis<InterpolatorKind::QuadraticBspline, 3>(p, g, s); break;
    default: s.axis_nodes = 0; return false;
  }
  if (ok) order_scatter(g, s);
  return ok;
}

long compute_stencils(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s) {
  s.width = stencil_width(spec.kind);
  s.axis_nodes = 0;
  s.hoop_factor = false;
  release(s.base);
  release(s.factors);
  const std::size_t n = p.size() * std::size_t(s.width);
  s.node.resize(n);
  s.w.resize(n);
  s.grad.resize(n);
  s.order.particles = 0;
  long bad = -1;
  switch (spec.kind) {
    case InterpolatorKind::Linear: bad = fill<InterpolatorKind::Linear>(p, g, spec, s); break;
    case InterpolatorKind::Gimp: bad = fill<InterpolatorKind::Gimp>(p, g, spec, s); break;
    case InterpolatorKind::QuadraticBspline: bad = fill<InterpolatorKind::QuadraticBspline>(p, g, spec, s); break;
    case InterpolatorKind::Cpdi: bad = fill<InterpolatorKind::Cpdi>(p, g, spec, s); break;
    case InterpolatorKind::CpGimp: bad = fill<InterpolatorKind::CpGimp>(p, g, spec, s); break;
    case InterpolatorKind::Cpti: bad = fill<InterpolatorKind::Cpti>(p, g, spec, s); break;
    case InterpolatorKind::CubicBspline: bad = fill<InterpolatorKind::CubicBspline>(p, g, spec, s); break;
  }
  if (bad < 0) order_scatter(g, s);
  return bad;
}

void order_scatter(const NodeGrid& g, Stencils& s) {
  const std::size_t np = s.particles();
  const long count = static_cast<long>(np);
  ScatterOrder& o = s.order;
  o.particles = 0;
  if (np == 0) return;
  const std::size_t nx = std::size_t(g.n[0]), nxy = nx * std::size_t(g.n[1]);
  if (s.axis_nodes) {
    // Per-axis form: footprint N x N node rows from the base node.
    const int N = s.axis_nodes;
    o.prepare(np, g.n[1], g.n[2], N, N);
    o.span = N;
#pragma omp parallel for schedule(static) if (count >= 4096)
    for (long i = 0; i < count; ++i) {
      const std::size_t b = s.base[std::size_t(i)];
      o.key[std::size_t(i)] = o.block_key(int((b / nx) % std::size_t(g.n[1])), int(b / nxy));
    }
  } else {
    // Flat form: the bounding rows of each particle's entries (any
    // interpolator); the widths from the largest footprint of all particles.
    const std::size_t W = std::size_t(s.width);
    std::vector<int> y0(np), z0(np);
    int span_x = 1, span_y = 1, span_z = 1;
#pragma omp parallel for schedule(static) reduction(max : span_x, span_y, span_z) if (count >= 4096)
    for (long i = 0; i < count; ++i) {
      int xlo = g.n[0], xhi = -1, ylo = g.n[1], yhi = -1, zlo = g.n[2], zhi = -1;
      for (std::size_t k = std::size_t(i) * W; k < std::size_t(i + 1) * W; ++k) {
        const int x = int(s.node[k] % nx);
        const int y = int((s.node[k] / nx) % std::size_t(g.n[1])), z = int(s.node[k] / nxy);
        xlo = std::min(xlo, x), xhi = std::max(xhi, x);
        ylo = std::min(ylo, y), yhi = std::max(yhi, y), zlo = std::min(zlo, z), zhi = std::max(zhi, z);
      }
      span_x = std::max(span_x, xhi - xlo + 1);
      y0[std::size_t(i)] = ylo;
      z0[std::size_t(i)] = zlo;
      span_y = std::max(span_y, yhi - ylo + 1);
      span_z = std::max(span_z, zhi - zlo + 1);
    }
    o.prepare(np, g.n[1], g.n[2], span_y, span_z);
    o.span = std::max({span_x, span_y, span_z});
    for (std::size_t i = 0; i < np; ++i) o.key[i] = o.block_key(y0[i], z0[i]);
  }
  o.finish();
}

}  // namespace tephra
