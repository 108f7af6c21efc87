// The kinetic-energy ledger of the explicit step (mpm/EnergyLedger.h).
#include "mpm/EnergyLedger.h"

namespace tephra {

const std::vector<const char*>& energy_ledger_labels() {
  static const std::vector<const char*> labels = {"ContactKineticEnergyRemoved", "BoundaryKineticEnergyRemoved",
                                                  "GridForceWork", "TransferKineticEnergyLoss"};
  return labels;
}

void add_node_terms(const NodeGrid& g, const std::vector<Vec3>& v_p2g, const std::vector<Vec3>& v_c,
                    const std::vector<Vec3>& v_star, const std::vector<Vec3>& v_contact,
                    const std::vector<Vec3>& v_final, double dt, EnergyLedger& ledger,
                    const std::vector<char>* counted) {
  const long n = static_cast<long>(g.count());
  double contact = 0.0, boundary = 0.0, work = 0.0, grid_increment = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : contact, boundary, work, grid_increment) if (n >= 65536)
  for (long i = 0; i < n; ++i) {
    const double m = g.mass[i];
    if (!(m > 0.0) || (counted && !(*counted)[std::size_t(i)])) continue;
    grid_increment += 0.5 * m * (g.acceleration[i] * dt).squaredNorm();
    for (int d = 0; d < 3; ++d) {
      const double v0 = v_p2g[i][d], vc = v_c[i][d], vs = v_star[i][d], vk = v_contact[i][d], vf = v_final[i][d];
      if (vf != vk) {  // last set by a grid BC
        boundary += 0.5 * m * (v0 * v0 - vf * vf);
      } else if (vk != vs) {  // last set by the integrated contact
        contact += 0.5 * m * (v0 * v0 - vf * vf);
      } else {  // free: the interpolated contact's change, then the force's
        contact += 0.5 * m * (v0 * v0 - vc * vc);
        work += 0.5 * m * (vs * vs - vc * vc);
      }
    }
  }
  ledger.contact_removed += contact;
  ledger.boundary_removed += boundary;
  ledger.grid_force_work += work;
  ledger.transfer_loss += grid_increment;
}

double particle_increment_energy(const Particles& p, const std::vector<Vec3>& v_old) {
  const long n = static_cast<long>(p.size());
  double e = 0.0;
#pragma omp parallel for schedule(static) reduction(+ : e) if (n >= 4096)
  for (long i = 0; i < n; ++i) e += 0.5 * p.mass[i] * (p.v[i] - v_old[i]).squaredNorm();
  return e;
}

}  // namespace tephra
