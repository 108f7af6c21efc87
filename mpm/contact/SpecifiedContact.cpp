// Specified-body ("rigid") contact, after Vaango's SpecifiedBodyContact.
//
// Master velocity v^m at a node:
//   t > stop_time        -> velocity_after_stop
//   a <filename> table   -> linear interpolation in t, end values outside
//   otherwise            -> the master's own interpolated node velocity v_g:
//                           the master is not accelerated and keeps the
//                           velocity it started with (Vaango: "the master
//                           material's initial velocity remains constant").
// At nodes where the master has mass (and sum V_g / V_cell > volume_constraint):
//   master:     v*_g = v^m (all components)
//   others:     direction-based (default): v*_g,d = v^m_d for each d with
//               direction_d = 1; normal_only: v* -= min(0, n.(v* - v^m)) n with
//               n the master's outward unit mass gradient (eq. 1.110, applied
//               only when the body moves into the master).
// The master drives the others from outside, so momentum is not conserved by
// this model: the change is the force the driver applies.
#include <algorithm>

#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

bool SpecifiedContact::imposed_velocity(double t, Vec3& v) const {
  if (t > p_.stop_time) {
    v = p_.velocity_after_stop;
    return true;
  }
  if (p_.profile.empty()) return false;
  const auto& prof = p_.profile;
  auto it = std::find_if(prof.begin(), prof.end(), [t](const auto& row) { return row.first > t; });
  if (it == prof.begin()) {
    v = it->second;
  } else if (it == prof.end()) {
    v = prof.back().second;
  } else {
    const auto& lo = *(it - 1);
    const double s = (t - lo.first) / (it->first - lo.first);
    v = (1.0 - s) * lo.second + s * it->second;
  }
  return true;
}

void SpecifiedContact::exchange(ContactStage, ContactNodes& nodes) const {
  Vec3 imposed = Vec3::Zero();
  const bool prescribed = imposed_velocity(nodes.t, imposed);
  const int master = p_.master;
  std::vector<Vec3>& vm = *nodes.velocity[master];
  const std::size_t count = nodes.nodes();
  for (std::size_t g = 0; g < count; ++g) {
    if (!(nodes.grid[master]->mass[g] > 0.0)) continue;
    double volume = 0.0;
    for (std::size_t m = 0; m < nodes.materials(); ++m) volume += nodes.grid[m]->volume[g];
    if (volume * boundary_volume_factor(*nodes.grid[0], g) / nodes.cell_volume() <= p_.volume_constraint) continue;
    const Vec3 v_master = prescribed ? imposed : nodes.grid[master]->velocity[g];
    vm[g] = v_master;
    Vec3 n = Vec3::Zero();
    if (p_.normal_only) {
      const double len = nodes.gradient[master][g].norm();
      if (len > 0.0) n = nodes.gradient[master][g] / len;
    }
    for (int m : p_.materials) {
      if (m == master) continue;
      Vec3& v = (*nodes.velocity[m])[g];
      if (p_.normal_only) {
        const double dvn = n.dot(v - v_master);
        if (dvn < 0.0) v -= dvn * n;
      } else {
        for (int d = 0; d < 3; ++d)
          if (p_.direction[d]) v[d] = v_master[d];
      }
    }
  }
}

}  // namespace tephra
