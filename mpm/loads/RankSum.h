#pragma once
// The loads' surface totals on MPI ranks (issue 7, docs/parallel.md "MPM on
// ranks"): a pressure or heat-flux surface shares p A (q A) equally among the
// N particles on it, and a moment is normalised by sum d_q^2 over its
// particles. N and sum d^2 are sums over the particles of every rank, so each
// process's partial sums go through a RankSum: per entry, the partials of all
// ranks added in rank order (the same bits on every rank). Counts are exact
// as doubles (below 2^53), so N is the one-process N; sum d^2 agrees with one
// process to round-off. An empty RankSum: one process, the partials are the totals.
#include <functional>
#include <utility>
#include <vector>

namespace tephra {

using RankSum = std::function<std::vector<double>(std::vector<double>)>;

inline std::vector<double> total_over_ranks(const RankSum& sum, std::vector<double> partial) {
  return sum ? sum(std::move(partial)) : partial;
}

}  // namespace tephra
