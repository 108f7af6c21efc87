#include "mpm/ParticleReorder.h"

#include "mpm/shape/ScatterOrder.h"

namespace tephra {

bool reorder_worthwhile(const ScatterOrder& o, std::size_t np) {
  return np >= kReorderMinParticles && o.built_for(np) && o.displaced * kReorderFraction > np;
}

void permute_particles(Particles& p, const std::vector<std::uint32_t>& order, std::vector<Mat3>& scratch) {
  const std::size_t n = p.size();
  if (order.size() != n) return;
  if (scratch.size() < n) scratch.resize(n);
  // The largest element is a Mat3 (72 B): scratch holds any column; a history
  // column of k components per particle needs k doubles = 8k B <= 72 B (k <= 9), else its own buffer.
  std::byte* s = reinterpret_cast<std::byte*>(scratch.data());
  permute_column(p.x, order, s);
  permute_column(p.v, order, s);
  permute_column(p.displacement, order, s);
  permute_column(p.external_force, order, s);
  permute_column(p.F, order, s);
  permute_column(p.stress, order, s);
  permute_column(p.psize, order, s);
  permute_column(p.mass, order, s);
  permute_column(p.volume, order, s);
  permute_column(p.volume0, order, s);
  permute_column(p.temperature, order, s);
  permute_column(p.color, order, s);
  permute_column(p.wave_speed, order, s);
  permute_column(p.energy_density, order, s);
  permute_column(p.q, order, s);
  permute_column(p.id, order, s);
  for (std::vector<double>& h : p.history) {
    const std::size_t per = n ? h.size() / n : 1;
    if (per * sizeof(double) <= sizeof(Mat3)) {
      permute_column(h, order, s, per);
    } else {
      std::vector<double> own(h.size());
      permute_column(h, order, reinterpret_cast<std::byte*>(own.data()), per);
    }
  }
}

}  // namespace tephra
