#include "core/parallel/Ranks.h"

#include <mpi.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

#include "core/base/Mpi.h"
#include "core/parallel/OutputGather.h"

namespace tephra {

int launched_rank_count() {
  for (const char* var : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* v = std::getenv(var)) {
      const int n = std::atoi(v);
      if (n > 0) return n;
    }
  }
  return 1;
}

Ranks world_ranks() {
  Ranks r;
  if (launched_rank_count() <= 1 && !mpi_is_initialized()) return r;
  ensure_mpi_initialized();
  MPI_Comm_rank(MPI_COMM_WORLD, &r.rank);
  MPI_Comm_size(MPI_COMM_WORLD, &r.size);
  return r;
}

std::vector<double> all_gather(const std::vector<double>& local) {
  const Ranks r = world_ranks();
  if (r.size == 1) return local;
  int n = static_cast<int>(local.size());
  std::vector<int> counts(r.size), offsets(r.size, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int i = 1; i < r.size; ++i) offsets[i] = offsets[i - 1] + counts[i - 1];
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(local.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 MPI_COMM_WORLD);
  return all;
}

std::vector<std::vector<double>> exchange_blocks(const std::vector<std::vector<double>>& to_rank) {
  const Ranks r = world_ranks();
  if (static_cast<int>(to_rank.size()) != r.size)
    throw std::invalid_argument("exchange_blocks: one block per rank");
  if (r.size == 1) return to_rank;
  std::vector<int> send_counts(r.size), recv_counts(r.size), send_offsets(r.size, 0), recv_offsets(r.size, 0);
  for (int s = 0; s < r.size; ++s) send_counts[s] = static_cast<int>(to_rank[s].size());
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, recv_counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
  for (int s = 1; s < r.size; ++s) {
    send_offsets[s] = send_offsets[s - 1] + send_counts[s - 1];
    recv_offsets[s] = recv_offsets[s - 1] + recv_counts[s - 1];
  }
  std::vector<double> send(static_cast<std::size_t>(send_offsets.back() + send_counts.back()));
  for (int s = 0; s < r.size; ++s) std::copy(to_rank[s].begin(), to_rank[s].end(), send.begin() + send_offsets[s]);
  std::vector<double> recv(static_cast<std::size_t>(recv_offsets.back() + recv_counts.back()));
  MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_DOUBLE, recv.data(), recv_counts.data(),
                recv_offsets.data(), MPI_DOUBLE, MPI_COMM_WORLD);
  std::vector<std::vector<double>> from_rank(r.size);
  for (int s = 0; s < r.size; ++s)
    from_rank[s].assign(recv.begin() + recv_offsets[s], recv.begin() + recv_offsets[s] + recv_counts[s]);
  return from_rank;
}

void barrier() {
  if (world_ranks().size > 1) MPI_Barrier(MPI_COMM_WORLD);
}

void abort_other_ranks(int code) {
  if (launched_rank_count() <= 1 || !mpi_is_initialized()) return;
  int size = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  if (size > 1) MPI_Abort(MPI_COMM_WORLD, code);
}

double all_min(double v) {
  if (world_ranks().size == 1) return v;
  double out = v;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MIN, MPI_COMM_WORLD);
  return out;
}

double all_max(double v) {
  if (world_ranks().size == 1) return v;
  double out = v;
  MPI_Allreduce(&v, &out, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

bool any_rank(bool flag) {
  if (world_ranks().size == 1) return flag;
  int in = flag ? 1 : 0, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out != 0;
}

std::vector<std::vector<double>> gather_patch_blocks(const std::vector<int>& owner,
                                                     const std::vector<int>& own_patches,
                                                     const std::vector<std::vector<double>>& own_blocks) {
  if (own_patches.size() != own_blocks.size())
    throw std::invalid_argument("gather_patch_blocks: one block per own patch");
  const Ranks r = world_ranks();
  std::vector<std::vector<double>> all(owner.size());
  // One rank, or per-rank output (OutputPerRank, core/parallel/OutputGather.h):
  // this rank's blocks in their places, no messages.
  if (r.size == 1 || output_per_rank()) {
    for (std::size_t n = 0; n < own_patches.size(); ++n) all[static_cast<std::size_t>(own_patches[n])] = own_blocks[n];
    return all;
  }
  // Block sizes first (as doubles: exact below 2^53), then the values; both
  // arrive concatenated in rank order, each rank's patches in its own order.
  std::vector<double> sizes, values;
  for (std::size_t n = 0; n < own_blocks.size(); ++n) {
    sizes.push_back(static_cast<double>(own_patches[n]));
    sizes.push_back(static_cast<double>(own_blocks[n].size()));
    values.insert(values.end(), own_blocks[n].begin(), own_blocks[n].end());
  }
  // Inside an OutputToRoot scope (core/parallel/OutputGather.h) only rank 0
  // receives: the other ranks return empty blocks.
  const std::vector<double> all_sizes = gather_output(sizes);
  const std::vector<double> all_values = gather_output(values);
  std::size_t pos = 0;
  for (std::size_t s = 0; s + 1 < all_sizes.size(); s += 2) {
    const auto p = static_cast<std::size_t>(all_sizes[s]);
    const auto n = static_cast<std::size_t>(all_sizes[s + 1]);
    if (p >= all.size()) throw std::invalid_argument("gather_patch_blocks: patch index out of range");
    all[p].assign(all_values.begin() + static_cast<long>(pos), all_values.begin() + static_cast<long>(pos + n));
    pos += n;
  }
  return all;
}

}  // namespace tephra
