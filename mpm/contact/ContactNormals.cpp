#include "mpm/contact/ContactNormals.h"

#include "mpm/SymmetryFold.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {

void mass_gradient(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i)
      view.entries(i, [&](std::size_t gi, double, const Vec3& gr) { out[gi] += p.mass[i] * gr; });
  });
  // Axisymmetric stencils: grad[2] is the hoop factor, not a derivative; the
  // mass gradient (and so every contact normal) lies in the r-z plane.
  if (s.hoop_factor)
    for (Vec3& v : out) v[2] = 0.0;
}

void mirror_gradient_at_symmetry_faces(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<Vec3>& gradient,
                                       int dims) {
  fold_symmetry_vectors(bcs, g, gradient, dims);  // extra-cell layers onto their mirrors
  for (int f = 0; f < 2 * dims; ++f) {
    if (bcs.face[f].kind != FaceVelocityBC::Kind::Symmetry) continue;
    const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
    IntVec3 c;
    c[d] = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
    for (c[b] = 0; c[b] < g.n[b]; ++c[b])
      for (c[a] = 0; c[a] < g.n[a]; ++c[a]) gradient[g.index(c)][d] = 0.0;
  }
}

void collinear_normals(const std::vector<const NodeGrid*>& grids, std::vector<std::vector<Vec3>>& gradient) {
  const std::size_t materials = gradient.size();
  if (materials < 2) return;
  const std::size_t count = gradient[0].size();
  std::vector<Vec3> averaged(materials);
  for (std::size_t g = 0; g < count; ++g) {
    for (std::size_t a = 0; a < materials; ++a) {
      averaged[a] = Vec3::Zero();
      if (!(grids[a]->mass[g] > 0.0)) continue;
      Vec3 others = Vec3::Zero();
      double mass = 0.0;
      for (std::size_t b = 0; b < materials; ++b)
        if (b != a) others += grids[b]->mass[g] * gradient[b][g], mass += grids[b]->mass[g];
      averaged[a] = mass > 0.0 ? Vec3(0.5 * (gradient[a][g] - others / mass)) : Vec3(0.5 * gradient[a][g]);
    }
    for (std::size_t a = 0; a < materials; ++a) gradient[a][g] = averaged[a];
  }
}

void mass_weighted_position(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i)
      view.weights(i, [&](std::size_t gi, double w) { out[gi] += p.mass[i] * w * p.x[i]; });
  });
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (g.mass[gi] > 0.0) out[gi] /= g.mass[gi];
}

void mass_weighted_offset(const Particles& p, const Stencils& s, const NodeGrid& g, std::vector<Vec3>& out) {
  out.assign(g.count(), Vec3::Zero());
  const std::size_t nx = std::size_t(g.n[0]), ny = std::size_t(g.n[1]);
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i)
      view.weights(i, [&](std::size_t gi, double w) {
        const Vec3 X = g.position(int(gi % nx), int((gi / nx) % ny), int(gi / (nx * ny)));
        out[gi] += p.mass[i] * w * (p.x[i] - X);
      });
  });
  for (std::size_t gi = 0; gi < g.count(); ++gi)
    if (g.mass[gi] > 0.0) out[gi] /= g.mass[gi];
}

}  // namespace tephra
