// <type>friction_LR</type>: Coulomb friction with the logistic-regression
// separation test of Nairn, Hammerquist & Smith (2020, VT §1.7 eqs.
// 1.129-1.145; Vaango's FrictionContactLR with the node data of
// SerialMPM::computeLogisticRegression, checked in its source, not copied).
//
// At each node where two or more of the contacting materials have mass:
//  1. alpha = the material with the most mass; every other one is a beta.
//  2. The point cloud: the particles of those materials whose stencil
//     weights the node (S_gp > 1e-100), positions relative to the node.
//  3. Separating plane by logistic regression (eqs. 1.132-1.144): labels
//     c_p = -1 (alpha), +1 (beta); N = (n, N4) minimises
//       E = sum_p (L(X_p . N) - c_p)^2 + sum_j lambda_j N_j^2,
//       L(t) = 2/(1 + e^-t) - 1,  X_p = (x_p - x_g, 1),
//     lambda = (l, l, l, 0), l = 1e-7 h_x^2 (Vaango's), by Gauss-Newton:
//       N += H^-1 [sum_p (c_p - L) psi X_p - lambda o N],
//       H = diag(lambda) + sum_p psi^2 X_p X_p^T,  psi = dL/dt = 2 e^-t/(1 + e^-t)^2,
//     from N = (1, 0, 0, 0) until 1 - n_k+1 . n_k < 1e-5 (at most 16
//     iterations, then the iterate of least change). n = N/|N| points from
//     alpha to beta.
//  4. Prominence (eq. 1.145): the particles' extent along n, from the
//     centres of the six faces of each particle domain x_p +- (F size h)_i / 2:
//     alpha's is the largest x . n, each beta's the smallest. (Vaango counts
//     surface particles only; Tephra all particles of the cloud, which gives
//     the same extremes unless an interior particle reaches past the surface.)
//  5. Contact for a beta when separation = prominence_beta - prominence_alpha
//     <= 0.01 h_x (overlap or within 1% of a cell) and the pair approaches:
//     dv = v_beta - v_cm, normal m = -n (from beta towards alpha),
//     dv_n = dv . m > 0. Then
//       Dv = -dv_n m - min(mu, dv_t/dv_n) dv_n t,   t = tangential direction,
//       v_beta += Dv,  v_alpha -= Dv m_beta / m_alpha,
//     equal and opposite momentum at every node. With
//     <do_contact_friction_heating> the pair's frictional work goes to
//     nodes.friction_work as in the other Coulomb models (CoulombExchange.h). (Vaango also scales Dv by
//     ff = max(1, (0.01 dx - sep)/.01*dx), which as written is
//     100 dx (0.01 dx - sep) and exceeds 1 only for overlaps of about
//     1/(100 dx) metres; Tephra uses ff = 1.)
// v_cm is the mass-weighted velocity of all contacting materials at the node,
// and the volume constraint is as in friction. No traction test (as Vaango).
// Symmetry planes (Vaango: MPMBoundCond "Symmetric" on gNormAlphaToBeta
// with material 0's BCs, then renormalised): at a node on the plane of a
// symmetry face the normal's component through the face is set to zero and
// n renormalised; a normal along the face's axis becomes zero, and then no
// pair at that node approaches (dv . n = 0), as in Vaango.
#include <algorithm>
#include <cmath>

#include <Eigen/QR>

#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

namespace {

using Vec4 = Eigen::Matrix<double, 4, 1>;
using Mat4 = Eigen::Matrix<double, 4, 4>;

struct CloudPoint {
  int material;
  std::size_t particle;
  Vec3 offset;  // x_p - X_k, k the node (or periodic alias) the particle's stencil weights
};

Vec3 node_position(const NodeGrid& g, std::size_t node) {
  const int i = int(node % std::size_t(g.n[0]));
  const int j = int((node / std::size_t(g.n[0])) % std::size_t(g.n[1]));
  const int k = int(node / (std::size_t(g.n[0]) * std::size_t(g.n[1])));
  return g.position(i, j, k);
}

}  // namespace

void symmetric_normal(const NodeGrid& g, std::size_t node, const std::array<bool, 6>& symmetry_face, Vec3& n) {
  const IntVec3 c(int(node % std::size_t(g.n[0])), int((node / std::size_t(g.n[0])) % std::size_t(g.n[1])),
                  int(node / (std::size_t(g.n[0]) * std::size_t(g.n[1]))));
  bool changed = false;
  for (int f = 0; f < 6; ++f) {
    const int d = f / 2;
    if (!symmetry_face[f] || c[d] != (f % 2 == 0 ? g.extra[d] : g.n[d] - 1 - g.extra[d])) continue;
    n[d] = 0.0, changed = true;
  }
  if (changed) n /= n.norm() + 1e-100;
}

Vec3 logistic_regression_normal(const std::vector<Vec3>& x, const std::vector<double>& label, double lambda_n) {
  const Vec4 lambda(lambda_n, lambda_n, lambda_n, 0.0);
  Vec4 N(1.0, 0.0, 0.0, 0.0);
  Vec3 n_k(1.0, 0.0, 0.0), best = n_k;
  double best_change = 2.0;
  for (int iter = 1; iter <= 16; ++iter) {
    Vec4 g = -lambda.cwiseProduct(N);
    Mat4 H = Mat4::Zero();
    H.diagonal() = lambda;
    for (std::size_t p = 0; p < x.size(); ++p) {
      const Vec4 X(x[p][0], x[p][1], x[p][2], 1.0);
      const double t = X.dot(N);
      if (t < -700.0) continue;  // saturated at L = -1, psi = 0 (e^-t would overflow)
      const double e = std::exp(-t), a = 1.0 + e;
      const double psi = 2.0 * e / (a * a), L = 2.0 / a - 1.0;
      g += X * ((label[p] - L) * psi);
      H += (psi * psi) * (X * X.transpose());
    }
    N += H.colPivHouseholderQr().solve(g);
    Vec3 n(N[0], N[1], N[2]);
    n /= n.norm() + 1e-100;
    const double change = 1.0 - n.dot(n_k);
    if (change < best_change) {
      best_change = change;
      best = n;
    }
    if (change < 1e-5) return n;
    n_k = n;
  }
  return best;
}

void FrictionLRContact::exchange(ContactStage, ContactNodes& nodes) const {
  const std::size_t count = nodes.nodes();
  const NodeGrid& grid = *nodes.grid[0];
  // Periodic grids: node g's alias set is represented by home(g); every alias
  // holds the folded m, v, V (mpm/PeriodicGrid.h). The exchange runs on the
  // representatives, with the cloud of all aliases, and is copied to the others.
  auto home = [&](std::size_t g) { return nodes.canonical ? (*nodes.canonical)[g] : g; };
  // 1. alpha material per node (-1: fewer than two materials with mass).
  std::vector<int> alpha(count, -1);
  for (std::size_t g = 0; g < count; ++g) {
    if (home(g) != g) continue;
    int n = 0, best = -1;
    double most = -1.0;
    for (int m : materials_) {
      const double mg = nodes.grid[m]->mass[g];
      if (mg > 1e-16) {
        ++n;
        if (mg > most) most = mg, best = m;
      }
    }
    if (n >= 2) alpha[g] = best;
  }
  // 2. Point clouds of the multi-material nodes: each particle whose stencil
  //    weights node k, with its position relative to k, in the cloud of
  //    home(k) (on a periodic grid a particle that weights two aliases of a
  //    node enters twice, once per periodic image, as the folded sums count it).
  std::vector<int> slot(count, -1);
  std::vector<std::vector<CloudPoint>> cloud;
  for (std::size_t g = 0; g < count; ++g)
    if (alpha[g] >= 0) slot[g] = int(cloud.size()), cloud.emplace_back();
  if (cloud.empty()) return;
  for (int m : materials_) {
    const Particles& p = *nodes.particles[m];
    const Stencils& s = *nodes.stencils[m];
    std::vector<std::size_t> seen;
    for (std::size_t i = 0; i < p.size(); ++i) {
      seen.clear();
      for (std::size_t k = i * s.width; k < (i + 1) * s.width; ++k) {
        const std::size_t g = s.node[k];
        const int c = slot[home(g)];
        if (c < 0 || !(s.w[k] > 1e-100) || std::find(seen.begin(), seen.end(), g) != seen.end()) continue;
        seen.push_back(g);
        cloud[std::size_t(c)].push_back({m, i, p.x[i] - node_position(grid, g)});
      }
    }
  }
  const double lambda_n = 1e-7 * nodes.h[0] * nodes.h[0];
  std::vector<Vec3> x;
  std::vector<double> label;
  std::vector<double> prominence(nodes.materials());
  for (std::size_t g = 0; g < count; ++g) {
    if (slot[g] < 0) continue;
    const std::vector<CloudPoint>& pts = cloud[slot[g]];
    if (pts.size() < 2) continue;
    const int a = alpha[g];
    // 3. The separating plane's normal, alpha -> beta.
    x.clear();
    label.clear();
    for (const CloudPoint& c : pts) {
      x.push_back(c.offset);
      label.push_back(c.material == a ? -1.0 : 1.0);
    }
    Vec3 n = logistic_regression_normal(x, label, lambda_n);
    symmetric_normal(grid, g, nodes.symmetry_face, n);
    // 4. Prominences along n from the particle domains' face centres.
    for (int m : materials_) prominence[m] = m == a ? -9e99 : 9e99;
    for (const CloudPoint& c : pts) {
      const Particles& p = *nodes.particles[c.material];
      const Mat3 half = 0.5 * nodes.h.asDiagonal() * (p.F[c.particle] * p.psize[c.particle]);
      const double centre = c.offset.dot(n);
      for (int col = 0; col < 3; ++col) {
        const double r = std::abs(half.col(col).dot(n));
        if (c.material == a) prominence[a] = std::max(prominence[a], centre + r);
        else prominence[c.material] = std::min(prominence[c.material], centre - r);
      }
    }
    // 5. Coulomb exchange of each approaching, touching beta with alpha.
    double mass = 0.0, volume = 0.0;
    Vec3 momentum = Vec3::Zero();
    for (int m : materials_) {
      mass += nodes.grid[m]->mass[g];
      momentum += nodes.grid[m]->mass[g] * (*nodes.velocity[m])[g];
      volume += nodes.grid[m]->volume[g];
    }
    if (volume * boundary_volume_factor(grid, g) / nodes.cell_volume() <= volume_constraint_) continue;
    const Vec3 v_cm = momentum / mass;
    const double ma = nodes.grid[a]->mass[g];
    for (int b : materials_) {
      const double mb = nodes.grid[b]->mass[g];
      if (b == a || !(mb > 1e-16)) continue;
      if (prominence[b] - prominence[a] > 0.01 * nodes.h[0]) continue;  // separated
      const Vec3 m_dir = -n;
      const Vec3 dv = (*nodes.velocity[b])[g] - v_cm;
      const double dvn = dv.dot(m_dir);
      if (!(dvn > 0.0)) continue;  // not approaching
      const Vec3 tangential = dv - dvn * m_dir;
      const double dvt = tangential.norm();
      const Vec3 t = tangential / (dvt + 1e-100);
      const double mu = std::min(mu_, dvt / dvn);
      const Vec3 Dv = -dvn * m_dir - mu * dvn * t;
      if (!nodes.friction_work.empty()) {  // <do_contact_friction_heating>: beta against alpha
        ContactPair pair;
        pair.ma = mb, pair.mb = ma;
        pair.va = (*nodes.velocity[b])[g], pair.vb = (*nodes.velocity[a])[g];
        pair.n = m_dir;
        record_friction_work(nodes, g, b, {a}, pair, mb * Dv);
      }
      (*nodes.velocity[b])[g] += Dv;
      (*nodes.velocity[a])[g] -= Dv * (mb / ma);
    }
  }
  if (nodes.canonical)  // the aliases take their representative's velocities (and work)
    for (std::size_t g = 0; g < count; ++g) {
      const std::size_t c = home(g);
      if (c == g || slot[c] < 0) continue;
      for (int m : materials_) {
        (*nodes.velocity[m])[g] = (*nodes.velocity[m])[c];
        if (!nodes.friction_work.empty()) nodes.friction_work[m][g] = nodes.friction_work[m][c];
      }
    }
}

}  // namespace tephra
