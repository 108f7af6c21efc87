#pragma once
// The ranks of a run (issue 7). A run started without mpirun, or with one
// rank, has size 1 and every collective below is a local no-op; MPI is then
// never initialised by these calls. Under mpirun (OpenMPI sets
// OMPI_COMM_WORLD_SIZE, MPICH/PMI sets PMI_SIZE) MPI is initialised on first
// use (core/base/Mpi.h) and the world communicator is used.
#include <vector>

namespace tephra {

struct Ranks {
  int rank = 0;
  int size = 1;
  bool is_root() const { return rank == 0; }
};

// Number of ranks the launcher asked for, read from the environment without
// touching MPI (1 when not launched by mpirun).
int launched_rank_count();

// This process's rank and the world size; initialises MPI when
// launched_rank_count() > 1.
Ranks world_ranks();

// Gathers every rank's `local` doubles onto every rank, concatenated in rank
// order (MPI_Allgatherv); with one rank returns `local`.
std::vector<double> all_gather(const std::vector<double>& local);

// Barrier across the world (no-op with one rank).
void barrier();

}  // namespace tephra
