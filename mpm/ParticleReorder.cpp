#include "mpm/ParticleReorder.h"

#include <algorithm>

#include "mpm/shape/ScatterOrder.h"

namespace tephra {

bool reorder_worthwhile(const ScatterOrder& o, std::size_t np) {
  return np >= kReorderMinParticles && o.built_for(np) && o.displaced * kReorderFraction > np;
}

namespace {

// permute_column (ParticleReorder.h) threaded, for the whole-material
// permutation: the gather, then, after the loop's barrier, the copy back in
// chunks of kChunk particles. A pure copy: the same bits for any thread count.
template <class T>
void permute_column_threaded(std::vector<T>& column, const std::vector<std::uint32_t>& order, std::byte* scratch,
                             std::size_t per = 1) {
  static_assert(std::is_trivially_destructible_v<T>, "plain per-particle values only");
  const std::size_t n = order.size(), bytes = per * sizeof(T);
  if (column.size() != n * per) return;  // not a per-particle column of this size (left alone)
  constexpr long kChunk = 4096;
  const long nl = static_cast<long>(n), chunks = (nl + kChunk - 1) / kChunk;
  std::byte* out = reinterpret_cast<std::byte*>(column.data());
#pragma omp parallel if (n >= kReorderMinParticles)
  {
#pragma omp for schedule(static)
    for (long j = 0; j < nl; ++j)
      std::memcpy(scratch + std::size_t(j) * bytes, static_cast<const void*>(column.data() + order[j] * per), bytes);
#pragma omp for schedule(static)
    for (long c = 0; c < chunks; ++c) {
      const std::size_t first = std::size_t(c * kChunk), count = std::min(n, first + std::size_t(kChunk)) - first;
      std::memcpy(out + first * bytes, scratch + first * bytes, count * bytes);
    }
  }
}

}  // namespace

void permute_particles(Particles& p, const std::vector<std::uint32_t>& order, std::vector<Mat3>& scratch) {
  const std::size_t n = p.size();
  if (order.size() != n) return;
  if (scratch.size() < n) scratch.resize(n);
  // The largest element is a Mat3 (72 B): scratch holds any column; a history
  // column of k components per particle needs k doubles = 8k B <= 72 B (k <= 9), else its own buffer.
  std::byte* s = reinterpret_cast<std::byte*>(scratch.data());
  permute_column_threaded(p.x, order, s);
  permute_column_threaded(p.v, order, s);
  permute_column_threaded(p.displacement, order, s);
  permute_column_threaded(p.external_force, order, s);
  permute_column_threaded(p.F, order, s);
  permute_column_threaded(p.stress, order, s);
  permute_column_threaded(p.psize, order, s);
  permute_column_threaded(p.mass, order, s);
  permute_column_threaded(p.volume, order, s);
  permute_column_threaded(p.volume0, order, s);
  permute_column_threaded(p.temperature, order, s);
  permute_column_threaded(p.color, order, s);
  permute_column_threaded(p.wave_speed, order, s);
  permute_column_threaded(p.energy_density, order, s);
  permute_column_threaded(p.q, order, s);
  permute_column_threaded(p.id, order, s);
  for (std::vector<double>& h : p.history) {
    const std::size_t per = n ? h.size() / n : 1;
    if (per * sizeof(double) <= sizeof(Mat3)) {
      permute_column_threaded(h, order, s, per);
    } else {
      std::vector<double> own(h.size());
      permute_column_threaded(h, order, reinterpret_cast<std::byte*>(own.data()), per);
    }
  }
}

}  // namespace tephra
