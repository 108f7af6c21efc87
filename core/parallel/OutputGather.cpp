#include "core/parallel/OutputGather.h"

#include <mpi.h>

#include "core/parallel/Ranks.h"

namespace tephra {
namespace {

// 0: to every rank, 1: to rank 0 (OutputToRoot), 2: kept (OutputPerRank).
enum Mode { kEvery = 0, kRoot = 1, kPerRank = 2 };
int g_mode = kEvery;
OutputGatherTraffic g_traffic;

}  // namespace

OutputToRoot::OutputToRoot() : previous_(g_mode) { g_mode = kRoot; }
OutputToRoot::~OutputToRoot() { g_mode = previous_; }

OutputPerRank::OutputPerRank() : previous_(g_mode) { g_mode = kPerRank; }
OutputPerRank::~OutputPerRank() { g_mode = previous_; }

bool output_gathers_to_root() { return g_mode == kRoot; }

bool output_per_rank() { return g_mode == kPerRank && world_ranks().size > 1; }

bool output_gather_lands_here() { return g_mode != kRoot || world_ranks().is_root(); }

std::vector<double> gather_output(const std::vector<double>& local) {
  const Ranks r = world_ranks();
  if (r.size == 1 || g_mode == kPerRank) return local;
  ++g_traffic.calls;
  const long long n = static_cast<long long>(local.size());
  g_traffic.doubles_own += n;
  if (g_mode == kEvery) {
    std::vector<double> all = all_gather(local);
    g_traffic.doubles_sent += n * (r.size - 1);
    g_traffic.doubles_received += static_cast<long long>(all.size()) - n;
    return all;
  }
  int count = static_cast<int>(local.size());
  std::vector<int> counts(r.is_root() ? r.size : 0), offsets(r.is_root() ? r.size : 0, 0);
  MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
  std::vector<double> all;
  if (r.is_root()) {
    for (int s = 1; s < r.size; ++s) offsets[s] = offsets[s - 1] + counts[s - 1];
    all.resize(static_cast<std::size_t>(offsets.back() + counts.back()));
  }
  MPI_Gatherv(local.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE, 0,
              MPI_COMM_WORLD);
  if (r.is_root()) g_traffic.doubles_received += static_cast<long long>(all.size()) - n;
  else g_traffic.doubles_sent += n;
  return all;
}

OutputGatherTraffic output_gather_traffic() { return g_traffic; }
void reset_output_gather_traffic() { g_traffic = OutputGatherTraffic{}; }

}  // namespace tephra
