#include "core/parallel/Ranks.h"

#include <mpi.h>

#include <cstdlib>

#include "core/base/Mpi.h"

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

void barrier() {
  if (world_ranks().size > 1) MPI_Barrier(MPI_COMM_WORLD);
}

}  // namespace tephra
