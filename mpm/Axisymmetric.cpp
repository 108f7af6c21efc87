#include "mpm/Axisymmetric.h"

#include <algorithm>
#include <cmath>

#include "mpm/shape/ShapeAxisymmetric.h"
#include "mpm/shape/ShapeBspline.h"
#include "mpm/shape/ShapeBsplineCubic.h"
#include "mpm/shape/ShapeGimp.h"

namespace tephra {

void make_axisymmetric_particles(const Vec3& h, double density, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dz = p.psize[i](2, 2) * h[2];
    const double V = p.volume0[i] / dz * p.x[i][0];
    p.volume0[i] = p.volume[i] = V;
    p.mass[i] = density * V;
  }
}

std::vector<double> axisymmetric_full_node_volumes(const NodeGrid& g) {
  const double h = g.h[0];
  std::vector<double> full(std::size_t(std::max(g.n[0], 0)));
  for (int i = 0; i < g.n[0]; ++i) {
    const double r = std::abs(g.origin[0] + i * h);
    double J = r * h;  // r >= h: the whole hat
    if (r < h) {       // the rising piece clipped at the axis (L = r), the falling piece whole
      const double L = r;
      J = 0.5 * r * h + h * h / 6.0 + (r * h * L - 0.5 * (h + r) * L * L + L * L * L / 3.0) / h;
    }
    full[std::size_t(i)] = 0.5 * J * g.h[1];
  }
  return full;
}

namespace {

// Linear (Vaango's AxiLinearInterpolator): 2 x 2 in-plane nodes.
bool linear_entries(const Particles& p, std::size_t i, const NodeGrid& g, int k0, std::size_t* node, double* w,
                    Vec3* grad) {
  const double r = p.x[i][0];
  const double xi = (p.x[i][0] - g.origin[0]) / g.h[0], eta = (p.x[i][1] - g.origin[1]) / g.h[1];
  const int ix = int(std::floor(xi)), iy = int(std::floor(eta));
  if (!(r > 0.0) || ix < 0 || iy < 0 || ix + 1 >= g.n[0] || iy + 1 >= g.n[1]) return false;
  const double fx = xi - ix, fy = eta - iy;
  const double Nx[2] = {1.0 - fx, fx}, Ny[2] = {1.0 - fy, fy};
  const double dNx[2] = {-1.0 / g.h[0], 1.0 / g.h[0]}, dNy[2] = {-1.0 / g.h[1], 1.0 / g.h[1]};
  int e = 0;
  for (int b = 0; b < 2; ++b)
    for (int a = 0; a < 2; ++a)
      for (int c = 0; c < 2; ++c, ++e) {
        const double S = 0.5 * Nx[a] * Ny[b];
        node[e] = g.index(ix + a, iy + b, k0 + c);
        w[e] = S;
        grad[e] = Vec3(0.5 * dNx[a] * Ny[b], 0.5 * Nx[a] * dNy[b], S / r);
      }
  return true;
}

// Axisymmetric GIMP (ShapeAxisymmetric.h): 3 radial x 3 axial nodes. A node
// outside the grid is accepted only with a zero factor (it then points at a
// valid node, weight 0).
bool gimp_entries(const Particles& p, std::size_t i, const NodeGrid& g, int k0, std::size_t* node, double* w,
                  Vec3* grad) {
  const double r = p.x[i][0];
  if (!(r > 0.0)) return false;
  const double lr = 0.5 * p.psize[i](0, 0) * g.h[0], lz = 0.5 * p.psize[i](1, 1);  // lz in index units
  double a, b;
  axi_gimp_interval(r, lr, a, b);
  const int first = int(std::floor((a - g.origin[0]) / g.h[0]));
  AxiRadialFactor fr[3];
  for (int k = 0; k < 3; ++k) fr[k] = axi_gimp_radial(g.origin[0] + (first + k) * g.h[0], g.h[0], a, b);
  const ShapeAxis az = gimp_axis((p.x[i][1] - g.origin[1]) / g.h[1], lz);
  int e = 0;
  for (int bz = 0; bz < 3; ++bz)
    for (int ar = 0; ar < 3; ++ar) {
      const int ix = first + ar, iy = az.first + bz;
      const double S = 0.5 * fr[ar].S * az.S[bz];
      const Vec3 gr(0.5 * fr[ar].G * az.S[bz], 0.5 * fr[ar].S * az.dS[bz] / g.h[1], 0.5 * fr[ar].T * az.S[bz]);
      const bool inside = ix >= 0 && iy >= 0 && ix < g.n[0] && iy < g.n[1];
      if (!inside && (S != 0.0 || gr != Vec3::Zero())) return false;
      for (int c = 0; c < 2; ++c, ++e) {
        node[e] = inside ? g.index(ix, iy, k0 + c) : g.index(0, 0, k0 + c);
        w[e] = inside ? S : 0.0;
        grad[e] = inside ? gr : Vec3::Zero();
      }
    }
  return true;
}

// Axisymmetric CPDI (ShapeAxisymmetric.h): 4 corners x 2 x 2 in-plane nodes.
bool cpdi_entries(const Particles& p, std::size_t i, const NodeGrid& g, int k0, std::size_t* node, double* w,
                  Vec3* grad) {
  const double r = p.x[i][0];
  if (!(r > 0.0)) return false;
  const Eigen::Matrix2d e2 = p.F[i].topLeftCorner<2, 2>() * p.psize[i].topLeftCorner<2, 2>();
  const Vec3 xi((p.x[i][0] - g.origin[0]) / g.h[0], (p.x[i][1] - g.origin[1]) / g.h[1], 0.0);
  Vec3 corner[4];
  Eigen::Vector2d gfac[4];
  if (!axi_cpdi_corners(xi, e2, g.h, corner, gfac)) return false;
  int e = 0;
  for (int c = 0; c < 4; ++c) {
    const int ix = int(std::floor(corner[c][0])), iy = int(std::floor(corner[c][1]));
    if (ix < 0 || iy < 0 || ix + 1 >= g.n[0] || iy + 1 >= g.n[1]) return false;
    const double fx = corner[c][0] - ix, fy = corner[c][1] - iy;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a) {
        const double hat = (a ? fx : 1.0 - fx) * (b ? fy : 1.0 - fy);
        const double S = 0.5 * 0.25 * hat;
        const Vec3 gr(0.5 * hat * gfac[c][0], 0.5 * hat * gfac[c][1], S / r);
        for (int k = 0; k < 2; ++k, ++e) {
          node[e] = g.index(ix + a, iy + b, k0 + k);
          w[e] = S;
          grad[e] = gr;
        }
      }
  }
  return true;
}

// The planar in-plane weights of a tensor-product interpolator (3rdorderBS,
// 4thorderBS, cpgimp), which Vaango has no axisymmetric form of:
//   S = S_r(r) S_z(z) / 2 on each hoop plane, grad S = (S_r' S_z, S_r S_z', 2 S / r_p) / 2,
// the hoop factor T = S / r_p as in AxiLinear and axiCpdi. W = 2 * 4 * 4 = 32
// entries (unused ones: weight 0 at a valid node). A node outside the grid
// is accepted only with a zero factor.
bool tensor_entries(const ShapeAxis& ar, const ShapeAxis& az, double r, const NodeGrid& g, int k0, int W,
                    std::size_t* node, double* w, Vec3* grad) {
  int e = 0;
  for (int bz = 0; bz < az.count; ++bz)
    for (int a = 0; a < ar.count; ++a) {
      const int ix = ar.first + a, iy = az.first + bz;
      const double S = 0.5 * ar.S[a] * az.S[bz];
      const Vec3 gr(0.5 * ar.dS[a] * az.S[bz] / g.h[0], 0.5 * ar.S[a] * az.dS[bz] / g.h[1], S / r);
      const bool inside = ix >= 0 && iy >= 0 && ix < g.n[0] && iy < g.n[1];
      if (!inside && (S != 0.0 || gr != Vec3::Zero())) return false;
      for (int c = 0; c < 2; ++c, ++e) {
        node[e] = inside ? g.index(ix, iy, k0 + c) : g.index(0, 0, k0 + c);
        w[e] = inside ? S : 0.0;
        grad[e] = inside ? gr : Vec3::Zero();
      }
    }
  for (; e < W; ++e) {
    node[e] = node[0];
    w[e] = 0.0;
    grad[e] = Vec3::Zero();
  }
  return true;
}

// 3rdorderBS, 4thorderBS (boundary-modified at the domain faces, the axis
// r = 0 included: ShapeBsplineCubic.h) and cpgimp (the GIMP convolution with
// the half-lengths of the rectangle circumscribing F_2x2 size_2x2, as the
// planar cpgimp of mpm/shape/ComputeStencils.cpp).
bool planar_entries(const Particles& p, std::size_t i, const NodeGrid& g, InterpolatorKind kind, int k0, int W,
                    std::size_t* node, double* w, Vec3* grad) {
  const double r = p.x[i][0];
  if (!(r > 0.0)) return false;
  double xi[2];
  for (int d = 0; d < 2; ++d) {
    xi[d] = (p.x[i][d] - g.origin[d]) / g.h[d];
    if (!(xi[d] >= 0.0 && xi[d] < g.n[d] - 1)) return false;
  }
  ShapeAxis ax[2];
  for (int d = 0; d < 2; ++d) {
    if (kind == InterpolatorKind::QuadraticBspline) {
      ax[d] = quadratic_bspline_axis(xi[d]);
    } else if (kind == InterpolatorKind::CubicBspline) {
      const int lo = g.extra[d], top = g.n[d] - 1 - g.extra[d];
      if (!(xi[d] >= lo && xi[d] <= top) || top - lo < 3) return false;
      ax[d] = cubic_bspline_axis(xi[d], lo, top);
    } else {  // CpGimp
      const Eigen::Matrix2d e2 = p.F[i].topLeftCorner<2, 2>() * p.psize[i].topLeftCorner<2, 2>();
      const double l = 0.5 * e2.row(d).cwiseAbs().sum();
      if (!(l > 0.0 && l <= 1.0) || !(e2.determinant() > 0.0)) return false;
      ax[d] = gimp_axis_any(xi[d], l);
    }
  }
  return tensor_entries(ax[0], ax[1], r, g, k0, W, node, w, grad);
}

}  // namespace

int axisymmetric_stencil_width(InterpolatorKind kind) {
  switch (kind) {
    case InterpolatorKind::Linear: return 8;
    case InterpolatorKind::Gimp: return 18;
    case InterpolatorKind::Cpdi: return 32;
    case InterpolatorKind::Cpti: return 32;              // Uintah's axiCptiInterpolator = the axiCpdi form
    case InterpolatorKind::QuadraticBspline: return 18;  // 3 x 3 in-plane nodes x 2 planes
    case InterpolatorKind::CubicBspline: return 32;      // up to 4 x 4 x 2
    case InterpolatorKind::CpGimp: return 32;            // up to 4 x 4 x 2
  }
  return 0;
}

long compute_axisymmetric_stencils(const Particles& p, const NodeGrid& g, InterpolatorKind kind, Stencils& s) {
  const std::size_t np = p.size();
  const int W = axisymmetric_stencil_width(kind);
  s.width = W;
  s.axis_nodes = 0;  // the flat form
  s.hoop_factor = true;
  s.node.resize(np * W);
  s.w.resize(np * W);
  s.grad.resize(np * W);
  const int k0 = g.extra[2];  // the two hoop planes: the domain's one cell
  if (k0 + 1 >= g.n[2]) return np ? 0 : -1;
  for (std::size_t i = 0; i < np; ++i) {
    std::size_t* node = &s.node[i * W];
    double* w = &s.w[i * W];
    Vec3* grad = &s.grad[i * W];
    bool ok = false;
    switch (kind) {
      case InterpolatorKind::Linear: ok = linear_entries(p, i, g, k0, node, w, grad); break;
      case InterpolatorKind::Gimp: ok = gimp_entries(p, i, g, k0, node, w, grad); break;
      case InterpolatorKind::Cpdi:
      case InterpolatorKind::Cpti: ok = cpdi_entries(p, i, g, k0, node, w, grad); break;
      default: ok = planar_entries(p, i, g, kind, k0, W, node, w, grad); break;
    }
    if (!ok) return long(i);
  }
  return -1;
}

void axisymmetric_internal_force(const Particles& p, const Stencils& s, NodeGrid& g) {
  const std::size_t W = s.width;
  for (std::size_t i = 0; i < p.size(); ++i) {
    // sigma - q I: the artificial bulk viscosity acts in the force only.
    const Mat3 sig = p.stress[i] - p.q[i] * Mat3::Identity();
    const double V = p.volume[i];
    for (std::size_t e = i * W; e < (i + 1) * W; ++e) {
      const Vec3& gr = s.grad[e];
      Vec3& f = g.internal_force[s.node[e]];
      f[0] -= V * (sig(0, 0) * gr[0] + sig(0, 1) * gr[1] + sig(2, 2) * gr[2]);
      f[1] -= V * (sig(1, 0) * gr[0] + sig(1, 1) * gr[1]);
    }
  }
}

void axisymmetric_velocity_gradients(const Stencils& s, const NodeGrid& g, std::vector<Mat3>& L) {
  const std::size_t W = s.width, np = s.particles();
  L.resize(np);
  for (std::size_t i = 0; i < np; ++i) {
    Mat3 l = Mat3::Zero();
    for (std::size_t e = i * W; e < (i + 1) * W; ++e) {
      const Vec3& v = g.velocity_star[s.node[e]];
      const Vec3& gr = s.grad[e];
      for (int a = 0; a < 2; ++a)
        for (int b = 0; b < 2; ++b) l(a, b) += v[a] * gr[b];
      l(2, 2) += v[0] * gr[2];  // v_r S / r
    }
    L[i] = l;
  }
}

}  // namespace tephra
