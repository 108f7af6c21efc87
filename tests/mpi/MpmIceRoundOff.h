#pragma once
// The round-off rule of the 1-rank vs N-rank MPMICE tests
// (tests/mpi/test_mpi_mpmice.cpp, test_mpi_mpmice_migration.cpp): each field of
// the distributed run lies within kMargin times the 1-rank answer's own
// sensitivity to a 4 u change of every particle (the backward error of the
// re-associated node sums), measured on a third, whole-level run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/io/OutputFrame.h"
#include "core/parallel/Ranks.h"
#include "mpmice/MpmIceComponent.h"
#include "tests/mpi/RankCompare.h"

namespace tephra::test {

// Per field (label, material) the relative difference max |a - b| / max |a|
// between two frames (particles by id, cells in level order).
using FieldDiffs = std::map<std::pair<std::string, int>, double>;

inline FieldDiffs frame_differences(const OutputFrame& a, const OutputFrame& b) {
  FieldDiffs out;
  auto note = [&](const std::string& label, int m, double d) {
    double& x = out[{label, m}];
    x = std::max(x, d);
  };
  EXPECT_EQ(a.particles.size(), b.particles.size());
  for (std::size_t k = 0; k < std::min(a.particles.size(), b.particles.size()); ++k) {
    const ParticleBlock& x = a.particles[k];
    const ParticleBlock& y = b.particles[k];
    EXPECT_EQ(x.id, y.id) << "every id exactly once, material " << x.material;
    note("p.x", x.material, relative_difference(flat(x.position), flat(y.position)));
    EXPECT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < std::min(x.fields.size(), y.fields.size()); ++f)
      note(x.fields[f].label, x.material, relative_difference(x.fields[f].values, y.fields[f].values));
  }
  EXPECT_EQ(a.grid_fields.size(), b.grid_fields.size());
  EXPECT_GT(a.grid_fields.size(), 0u);
  for (std::size_t k = 0; k < std::min(a.grid_fields.size(), b.grid_fields.size()); ++k) {
    const FieldArray& x = a.grid_fields[k].data;
    const FieldArray& y = b.grid_fields[k].data;
    EXPECT_EQ(x.label, y.label);
    EXPECT_EQ(x.material, y.material);
    note(x.label, x.material, relative_difference(x.values, y.values));
  }
  return out;
}

// The round-off reference (backward error): the rank split only re-associates
// the node sums at nodes two ranks reach, so the distributed node sums are the
// exact sums of the particle terms each changed by a relative amount of at most
// (n - 1) u, n the number of terms, u = 2^-53 (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., eq. (4.4)); the cut re-association adds one
// rounding per rank, a few u in all. The answer's sensitivity to such a change
// is measured on a third, whole-level run whose particles are each made
// larger or smaller by 4u (mass, volume and reference volume together, so the
// density and the stress are unchanged; the sign from a hash of the id, so
// the weighted node means change too). The distributed answer must lie within
// kMargin times that run's difference from the reference, per field.
// kMargin = 10: the two perturbations have the same size but different sign
// patterns, so their responses differ by a factor of order one, not ten; a
// missing or doubled rank sum gives differences of order one (1e12 u).
constexpr double kUlp = 0x1p-53;
constexpr double kMargin = 10;

inline void perturb_particles(MpmIceComponent& c) {
  for (MpmMaterial& m : c.mpm().materials()) {
    Particles& p = m.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      std::uint64_t h = std::uint64_t(p.id[i]) * 0x9E3779B97F4A7C15ull;  // Fibonacci hash
      h ^= h >> 29;
      const double f = 1 + ((h >> 17) & 1 ? 4 : -4) * kUlp;
      p.mass[i] *= f;
      p.volume[i] *= f;
      p.volume0[i] *= f;
    }
  }
}

// The second sample (session 18): the same 4u, its sign coherent per rank of
// the distributed run (`owner`: patch -> rank of that run; the sign is + on
// even ranks, - on odd): each rank's partial sums then carry one signed
// rounding, as the re-associated node sums at a cut do. The hashed signs
// above average out in sums over many particles (KineticEnergy of massX:
// 4.4e-15 relative against 1.0e-12 between 1 and 2 ranks, after the pressure
// force of mpmice/ was given one association on any rank count); the
// coherent signs do not. Under one rank every sign is + (a uniform scaling).
inline void perturb_particles_by_rank(MpmIceComponent& c, const std::vector<int>& owner) {
  const Grid& level = c.mpm().layout().level;
  for (MpmMaterial& m : c.mpm().materials()) {
    Particles& p = m.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      IntVec3 cell;
      for (int d = 0; d < 3; ++d)
        cell[d] = std::clamp(int(std::floor((p.x[i][d] - level.lower[d]) / level.dx[d])), 0, level.cells[d] - 1);
      const int patch = level.patch_owning_cell(cell);
      const int rank = patch >= 0 && std::size_t(patch) < owner.size() ? owner[std::size_t(patch)] : 0;
      const double f = 1 + (rank % 2 == 0 ? 4 : -4) * kUlp;
      p.mass[i] *= f;
      p.volume[i] *= f;
      p.volume0[i] *= f;
    }
  }
}

// Per key the larger of two sensitivity samples.
inline FieldDiffs larger_of(const FieldDiffs& a, const FieldDiffs& b) {
  FieldDiffs out = a;
  for (const auto& [key, d] : b) out[key] = std::max(out.count(key) ? out[key] : 0.0, d);
  return out;
}

// Asserts each field of `ranks` within kMargin x its round-off sensitivity
// `pert` (both relative to the field's max, from frame_differences) + `floor`
// (fields the perturbation leaves unchanged may still differ by a few
// rounding steps: 8u for fields; for the .dat sums see sums_floor). Returns
// the worst ratio ranks / (sensitivity + floor).
inline double expect_within_round_off(const FieldDiffs& ranks, const FieldDiffs& pert, const char* what,
                               double floor = 8 * kUlp) {
  double worst = 0;
  for (const auto& [key, d] : ranks) {
    const auto it = pert.find(key);
    const double sens = it == pert.end() ? 0.0 : it->second;
    const double bound = kMargin * sens + floor;
    EXPECT_LE(d, bound) << what << ": " << key.first << " material " << key.second << " differs " << d
                        << ", its round-off sensitivity " << sens;
    worst = std::max(worst, d / (sens + floor));
    if (world_ranks().is_root() && std::getenv("TEPHRA_MPI_PRINT_FIELDS"))
      std::printf("[ mpi-mpmice ] %s %-22s m%d ranks %.3e  1-ulp-perturbed %.3e\n", what, key.first.c_str(),
                  key.second, d, sens);
  }
  return worst;
}

}  // namespace tephra::test
