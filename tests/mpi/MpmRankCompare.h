#pragma once
// 1-rank vs N-rank comparison of two MPM components (tests/mpi/test_mpi_mpm_*.cpp):
// the particle fields `labels` gathered from every rank in ascending id, and
// the .dat sums `sums`, each against the whole-level run `a`.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "core/io/OutputFrame.h"
#include "mpm/MpmComponent.h"
#include "tests/mpi/RankCompare.h"

namespace tephra::test {

// Worst relative difference; every difference is asserted <= bound:
//  * particle fields and positions: max |a - b| / max |a| per field;
//  * sums: |a - b| / |a| per label, except TotalMomentum (0 to round-off in
//    symmetric runs: relative to sum m |v| <= M max |v|) and the labels of
//    `scales` (relative to the given scale, e.g. the initial kinetic energy for
//    the energy-ledger terms, which may be 0 to round-off themselves).
inline double compare_mpm_runs(const MpmComponent& a, const MpmComponent& b, const std::set<std::string>& labels,
                               const std::set<std::string>& sums, double bound,
                               const std::map<std::string, double>& scales = {}) {
  OutputFrame fa, fb;
  a.fill_output(labels, fa);
  b.fill_output(labels, fb);  // gathered from every rank, ascending id
  double worst = 0;
  EXPECT_EQ(fa.particles.size(), fb.particles.size());
  for (std::size_t k = 0; k < std::min(fa.particles.size(), fb.particles.size()); ++k) {
    const ParticleBlock& x = fa.particles[k];
    const ParticleBlock& y = fb.particles[k];
    EXPECT_EQ(x.id, y.id) << "every id exactly once, material " << x.material;
    const double dx = relative_difference(flat(x.position), flat(y.position));
    EXPECT_LE(dx, bound) << "p.x";
    worst = std::max(worst, dx);
    EXPECT_EQ(x.fields.size(), y.fields.size());
    for (std::size_t f = 0; f < std::min(x.fields.size(), y.fields.size()); ++f) {
      const double d = relative_difference(x.fields[f].values, y.fields[f].values);
      EXPECT_LE(d, bound) << x.fields[f].label;
      worst = std::max(worst, d);
    }
  }
  auto ra = a.reductions(sums);
  auto rb = b.reductions(sums);
  double vmax = 0;
  for (const ParticleBlock& x : fa.particles)
    for (const FieldArray& f : x.fields)
      if (f.label == "p.velocity")
        for (double v : f.values) vmax = std::max(vmax, std::abs(v));
  for (const auto& [label, values] : ra) {
    double d = relative_difference(values, rb[label]);
    double scale = 0;
    if (label == "TotalMomentum" && ra.count("TotalMass")) scale = ra.at("TotalMass").at(0) * std::max(vmax, 1e-300);
    if (scales.count(label)) scale = scales.at(label);
    if (scale > 0) {
      d = 0;
      for (std::size_t k = 0; k < std::min(values.size(), rb[label].size()); ++k)
        d = std::max(d, std::abs(values[k] - rb[label][k]) / scale);
    }
    EXPECT_LE(d, bound) << label;
    worst = std::max(worst, d);
  }
  return worst;
}

}  // namespace tephra::test
