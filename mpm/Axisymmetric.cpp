#include "mpm/Axisymmetric.h"

#include <cmath>

namespace tephra {

void make_axisymmetric_particles(const Vec3& h, double density, Particles& p) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double dz = p.psize[i](2, 2) * h[2];
    const double V = p.volume0[i] / dz * p.x[i][0];
    p.volume0[i] = p.volume[i] = V;
    p.mass[i] = density * V;
  }
}

long compute_axisymmetric_stencils(const Particles& p, const NodeGrid& g, Stencils& s) {
  const std::size_t np = p.size();
  s.width = 8;
  s.axis_nodes = 0;  // the flat form
  s.node.resize(np * 8);
  s.w.resize(np * 8);
  s.grad.resize(np * 8);
  const int k0 = g.extra[2];  // the two hoop planes: the domain's one cell
  for (std::size_t i = 0; i < np; ++i) {
    const double r = p.x[i][0];
    const double xi = (p.x[i][0] - g.origin[0]) / g.h[0], eta = (p.x[i][1] - g.origin[1]) / g.h[1];
    const int ix = int(std::floor(xi)), iy = int(std::floor(eta));
    if (!(r > 0.0) || ix < 0 || iy < 0 || ix + 1 >= g.n[0] || iy + 1 >= g.n[1] || k0 + 1 >= g.n[2]) return long(i);
    const double fx = xi - ix, fy = eta - iy;
    const double Nx[2] = {1.0 - fx, fx}, Ny[2] = {1.0 - fy, fy};
    const double dNx[2] = {-1.0 / g.h[0], 1.0 / g.h[0]}, dNy[2] = {-1.0 / g.h[1], 1.0 / g.h[1]};
    std::size_t e = i * 8;
    for (int b = 0; b < 2; ++b)
      for (int a = 0; a < 2; ++a)
        for (int c = 0; c < 2; ++c, ++e) {
          const double S = 0.5 * Nx[a] * Ny[b];
          s.node[e] = g.index(ix + a, iy + b, k0 + c);
          s.w[e] = S;
          s.grad[e] = Vec3(0.5 * dNx[a] * Ny[b], 0.5 * Nx[a] * dNy[b], S / r);
        }
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
