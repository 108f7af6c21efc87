#include "mpm/PeriodicGrid.h"

#include <cmath>

namespace tephra {

namespace {

// Sums `v` over each alias set and writes the sum back to every member.
template <class T>
void fold(const std::vector<std::size_t>& canonical, std::vector<T>& v, const T& zero) {
  std::vector<T> sum(v.size(), zero);
  for (std::size_t g = 0; g < v.size(); ++g) sum[canonical[g]] += v[g];
  for (std::size_t g = 0; g < v.size(); ++g) v[g] = sum[canonical[g]];
}

}  // namespace

PeriodicNodes periodic_nodes(const Grid& grid, const NodeGrid& g) {
  PeriodicNodes map;
  if ((grid.periodic.array() == 0).all()) return map;
  map.canonical.resize(g.count());
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        IntVec3 c(i, j, k);
        for (int d = 0; d < 3; ++d)
          if (grid.periodic[d]) {
            const int N = grid.cells[d];
            c[d] = g.extra[d] + (((c[d] - g.extra[d]) % N) + N) % N;
          }
        map.canonical[g.index(i, j, k)] = g.index(c);
      }
  return map;
}

void fold_particle_sums(const PeriodicNodes& map, NodeGrid& g) {
  if (!map.active()) return;
  // Back to extensive sums: momentum m v and V sigma.
  const bool stress = !g.stress.empty();  // NodeGrid::node_stress
  for (std::size_t n = 0; n < g.count(); ++n) {
    g.velocity[n] *= g.mass[n];
    if (stress) g.stress[n] *= g.volume[n];
  }
  fold(map.canonical, g.mass, 0.0);
  fold(map.canonical, g.volume, 0.0);
  fold(map.canonical, g.velocity, Vec3::Zero().eval());
  fold(map.canonical, g.stress, Mat3::Zero().eval());
  fold(map.canonical, g.external_force, Vec3::Zero().eval());
  for (std::size_t n = 0; n < g.count(); ++n) {
    if (g.mass[n] > 0.0) g.velocity[n] /= g.mass[n];
    if (stress && g.volume[n] > 0.0) g.stress[n] /= g.volume[n];
  }
}

void fold_internal_force(const PeriodicNodes& map, NodeGrid& g) {
  if (!map.active()) return;
  fold(map.canonical, g.internal_force, Vec3::Zero().eval());
}

void fold_mass_weighted(const PeriodicNodes& map, const std::vector<double>& mass, std::vector<double>& f) {
  if (!map.active()) return;
  for (std::size_t n = 0; n < f.size(); ++n) f[n] *= mass[n];  // back to the particle sum (mass already folded)
  fold(map.canonical, f, 0.0);
  for (std::size_t n = 0; n < f.size(); ++n)
    if (mass[n] > 0.0) f[n] /= mass[n];
}

void fold_vectors(const PeriodicNodes& map, std::vector<Vec3>& v) {
  if (!map.active()) return;
  fold(map.canonical, v, Vec3::Zero().eval());
}

void fold_positions(const PeriodicNodes& map, const NodeGrid& g, std::vector<Vec3>& x) {
  if (!map.active()) return;
  const std::size_t nx = std::size_t(g.n[0]), ny = std::size_t(g.n[1]);
  auto node_position = [&](std::size_t n) { return g.position(int(n % nx), int((n / nx) % ny), int(n / (nx * ny))); };
  // Back to the particle sums m_g d_g = sum m_p (x_p - X_g) S.
  for (std::size_t n = 0; n < x.size(); ++n) x[n] *= g.mass[n];
  fold(map.canonical, x, Vec3::Zero().eval());
  for (std::size_t n = 0; n < x.size(); ++n)
    x[n] = g.mass[n] > 0.0 ? Vec3(node_position(n) + x[n] / g.mass[n]) : Vec3::Zero();
}

int periodic_ghost_layers(InterpolatorKind kind) {
  switch (kind) {
    case InterpolatorKind::Linear: return 0;
    case InterpolatorKind::Gimp:
    case InterpolatorKind::QuadraticBspline: return 1;
    case InterpolatorKind::CpGimp:
    case InterpolatorKind::Cpdi:
    case InterpolatorKind::Cpti: return 2;
    case InterpolatorKind::CubicBspline: return -1;
  }
  return -1;
}

void copy_from_canonical(const PeriodicNodes& map, std::vector<Vec3>& v) {
  if (!map.active()) return;
  for (std::size_t g = 0; g < v.size(); ++g) v[g] = v[map.canonical[g]];
}

std::vector<std::size_t> nodes_without_ghosts(const NodeGrid& g) {
  std::vector<std::size_t> out;
  if ((g.ghost.array() == 0).all()) return out;
  const IntVec3 lo = g.ghost, hi = g.n - g.ghost;
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) out.push_back(g.index(i, j, k));
  return out;
}

void wrap_periodic_positions(const Grid& grid, Particles& p) {
  for (int d = 0; d < 3; ++d) {
    if (!grid.periodic[d]) continue;
    const double lo = grid.lower[d], L = grid.upper[d] - grid.lower[d];
    for (std::size_t i = 0; i < p.size(); ++i) {
      double x = lo + std::fmod(p.x[i][d] - lo, L);
      if (x < lo) x += L;
      if (x >= lo + L) x -= L;  // fmod round-off at the upper face
      p.x[i][d] = x;
    }
  }
}

}  // namespace tephra
