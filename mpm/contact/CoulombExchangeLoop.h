#pragma once
// exchange_pairs (declared and documented in CoulombExchange.h).
#include <cmath>

namespace tephra {

// 2^(number of directions in which node (i,j,k) is on the grid boundary):
// the 8 * NC_CCweight factor of Vaango, which counts a boundary node's
// volume against the cells that exist.
double boundary_volume_factor(const NodeGrid& g, std::size_t node);

template <class Decide>
void exchange_pairs(ContactNodes& nodes, const std::vector<int>& materials, double volume_constraint,
                    double mu, Decide&& decide) {
  const std::size_t count = nodes.nodes();
  const bool positions = !nodes.position.empty();
  std::vector<int> here;
  here.reserve(materials.size());
  for (std::size_t g = 0; g < count; ++g) {
    here.clear();
    double mass = 0.0, volume = 0.0;
    for (int m : materials) {
      const double mg = nodes.grid[m]->mass[g];
      volume += nodes.grid[m]->volume[g];
      if (mg > 0.0) {
        here.push_back(m);
        mass += mg;
      }
    }
    if (here.size() < 2) continue;
    if (volume * boundary_volume_factor(*nodes.grid[0], g) / nodes.cell_volume() <= volume_constraint) continue;
    for (std::size_t k = 0; k + 1 < here.size(); ++k) {
      const int a = here[k];
      ContactPair p;
      p.ma = nodes.grid[a]->mass[g];
      p.va = (*nodes.velocity[a])[g];
      Vec3 pb = Vec3::Zero(), gb = Vec3::Zero(), xb = Vec3::Zero();
      Mat3 stress = p.ma * nodes.grid[a]->stress[g];
      for (int b : here) {
        if (b == a) continue;
        const double mb = nodes.grid[b]->mass[g];
        p.mb += mb;
        pb += mb * (*nodes.velocity[b])[g];
        gb += nodes.gradient[b][g];
        if (positions) xb += mb * nodes.position[b][g];
        stress += mb * nodes.grid[b]->stress[g];
      }
      p.vb = pb / p.mb;
      if (positions) {
        p.xa = nodes.position[a][g];
        p.xb = xb / p.mb;
      }
      const Vec3& ga = nodes.gradient[a][g];
      const double na = ga.norm(), nb = gb.norm();
      if (!(na > 0.0 || nb > 0.0)) continue;  // no surface: nothing to decide on
      p.n = na >= nb ? Vec3(ga / na) : Vec3(-gb / nb);
      p.traction = p.n.dot((stress / (p.ma + p.mb)) * p.n);
      if (!decide(p)) continue;
      const Vec3 dp = coulomb_exchange(p, mu, nodes.h, nodes.dt);
      record_friction_work(nodes, g, a, here, p, dp);
      (*nodes.velocity[a])[g] += dp / p.ma;
      const Vec3 dvb = -dp / p.mb;
      for (int b : here)
        if (b != a) (*nodes.velocity[b])[g] += dvb;
    }
  }
}

}  // namespace tephra
