#pragma once
// Keeps the particle columns of a material in the scatter order of its
// stencils (mpm/shape/ScatterOrder.h), so that the block-ordered scatters
// (P2G, internal force, the MUSL velocity) and the particle loops (stress,
// velocity gradients, G2P) stream through the columns instead of reading
// them through the index list.
//
// The permutation: new column[j] = old column[order[j]] for EVERY per-particle
// column (Particles: x, v, displacement, external force, F, stress, psize,
// mass, volume, volume0, temperature, colour, wave speed, energy density, q,
// id, and every history column with its components per particle), so each
// particle's whole state moves together and keeps its id. Output is written
// in ascending id (MpmComponentOutput.cpp), so files do not depend on the
// storage order; the restart archive stores the columns in storage order with
// their ids (a restarted run continues in the same order, same bits).
//
// What changes: sums over particles taken in storage order (the .dat
// reductions, AccStrainEnergy, and every node sum of the scatters) are taken
// in a different order, so they differ from an unordered run by round-off
// (docs/performance.md gives the measured differences). They stay
// deterministic and the same for any thread count: the order depends only on
// the particle positions and the previous storage order (with several
// patches, on the positions and ids only: ScatterOrder::sort_blocks_by_id).
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

#include "mpm/Particles.h"

namespace tephra {

struct ScatterOrder;

// Reorder when more than 1/kReorderFraction of the particles sit elsewhere
// than the scatter order puts them (ScatterOrder::displaced). Between
// reorders the scatters read the index list, which then differs from the
// identity in a few places only (nearly sequential access).
// Below kReorderMinParticles nothing is reordered: the columns of so few
// particles (< 2.5 MB) stay in cache whatever their order, and the scatters
// run serially there anyway (for_each_scatter_particle). Small decks (and
// tests that follow particles by index) keep the seeding order.
constexpr std::size_t kReorderFraction = 16;
constexpr std::size_t kReorderMinParticles = 4096;
bool reorder_worthwhile(const ScatterOrder& o, std::size_t np);

// column[j] <- column[order[j]], `per` values per particle, through the
// caller's scratch of at least order.size() * per * sizeof(T) bytes (the
// bits are moved with memcpy: T is a plain array of doubles or integers).
template <class T>
void permute_column(std::vector<T>& column, const std::vector<std::uint32_t>& order, std::byte* scratch,
                    std::size_t per = 1) {
  static_assert(std::is_trivially_destructible_v<T>, "plain per-particle values only");
  const std::size_t n = order.size(), bytes = per * sizeof(T);
  if (column.size() != n * per) return;  // not a per-particle column of this size (left alone)
  for (std::size_t j = 0; j < n; ++j)
    std::memcpy(scratch + j * bytes, static_cast<const void*>(column.data() + order[j] * per), bytes);
  std::memcpy(static_cast<void*>(column.data()), scratch, n * bytes);
}

// Every column of `p` (above) permuted by `order` (a permutation of
// 0..p.size()-1), through `scratch` (resized to p.size() if smaller; its
// contents are overwritten: pass a dead step column).
void permute_particles(Particles& p, const std::vector<std::uint32_t>& order, std::vector<Mat3>& scratch);

}  // namespace tephra
