#include "ice/Diffusion.h"

#include "core/grid/Loop.h"

namespace tephra {

// Traction on the d-face whose upper cell is R (see Diffusion.h).
static Vec3 face_traction(const Grid& g, const GridArray<Vec3>& u, const GridArray<double>& theta, double mu,
                          const IntVec3& R, int d) {
  const IntVec3 L = R - IntVec3::Unit(d);
  Eigen::Matrix3d G;  // G(a, b) = du_a/dx_b on the face
  for (int b = 0; b < 3; ++b) {
    if (b == d) {
      G.col(b) = (u(R) - u(L)) / g.dx[d];
    } else {
      const IntVec3 eb = IntVec3::Unit(b);
      G.col(b) = ((u(IntVec3(R + eb)) - u(IntVec3(R - eb))) + (u(IntVec3(L + eb)) - u(IntVec3(L - eb)))) / (4.0 * g.dx[b]);
    }
  }
  const double mu_f = 0.5 * mu * (theta(L) + theta(R));
  Vec3 t = mu_f * (G.col(d) + G.row(d).transpose());
  t[d] -= 2.0 / 3.0 * mu_f * G.trace();
  return t;
}

void add_viscous_force(const Grid& g, const Patch& p, const GridArray<Vec3>& u, const GridArray<double>& theta,
                       double mu, GridArray<Vec3>& force) {
  if (mu == 0.0) return;
  for_each_cell(p.cells(), [&](int i, int j, int k) {
    const IntVec3 c(i, j, k);
    Vec3 f = Vec3::Zero();
    for (int d = 0; d < 3; ++d) {
      const IntVec3 up = c + IntVec3::Unit(d);
      f += (face_traction(g, u, theta, mu, up, d) - face_traction(g, u, theta, mu, c, d)) / g.dx[d];
    }
    force(c) += f;
  });
}

void add_heat_conduction(const Grid& g, const Patch& p, const GridArray<double>& T, const GridArray<double>& theta,
                         double k, GridArray<double>& heat) {
  if (k == 0.0) return;
  auto flux = [&](const IntVec3& R, int d) {  // k_f dT/dx_d on the d-face below R
    const IntVec3 L = R - IntVec3::Unit(d);
    const double kL = theta(L) * k, kR = theta(R) * k;
    const double kf = kL + kR > 0 ? 2.0 * kL * kR / (kL + kR) : 0.0;
    return kf * (T(R) - T(L)) / g.dx[d];
  };
  for_each_cell(p.cells(), [&](int i, int j, int k2) {
    const IntVec3 c(i, j, k2);
    double h = 0;
    for (int d = 0; d < 3; ++d) h += (flux(IntVec3(c + IntVec3::Unit(d)), d) - flux(c, d)) / g.dx[d];
    heat(c) += h;
  });
}

}  // namespace tephra
