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

// Personalised all-to-all (MPI_Alltoall of the counts, then MPI_Alltoallv):
// `to_rank[s]` goes to rank s (to_rank has one entry per rank; the entry of
// this rank is returned to itself), the result's entry s is what rank s sent
// here. One process: returns `to_rank`. Used by MPM for the node sums of
// overlapping rank boxes and for particle migration (mpm/RankNodeSums, MpmRanks).
std::vector<std::vector<double>> exchange_blocks(const std::vector<std::vector<double>>& to_rank);

// Barrier across the world (no-op with one rank).
void barrier();

// Under mpirun with more than one rank: stops every rank with exit `code`
// (MPI_Abort), so that an error on one rank does not leave the others waiting
// in a collective. Returns (does nothing) with one rank.
void abort_other_ranks(int code);

// The minimum / maximum of `v` over all ranks (exact in any order, so every
// rank gets the same bits); `v` itself with one rank.
double all_min(double v);
double all_max(double v);
// True on every rank when `flag` is true on at least one rank.
bool any_rank(bool flag);

// Per-patch blocks of doubles, gathered onto every rank in patch order:
// `own_blocks[n]` is this rank's block of patch `own_patches[n]`; the result
// has one block per patch, result[p] from the rank that owns patch p
// (`owner[p]`, the same vector on every rank). One process: the blocks
// themselves. Used to write rank-local fields as the one-rank run does.
// Inside an OutputToRoot scope (core/parallel/OutputGather.h) only rank 0
// receives the blocks; every block is empty on the other ranks.
std::vector<std::vector<double>> gather_patch_blocks(const std::vector<int>& owner,
                                                     const std::vector<int>& own_patches,
                                                     const std::vector<std::vector<double>>& own_blocks);

}  // namespace tephra
