#pragma once
// Where the output gathers deliver (issue 7 item 4, session 23).
//
// Under mpirun every rank writes its own part of a frame (session 25) and of
// a checkpoint (session 27) inside an OutputPerRank scope (below); the
// OutputToRoot scope (session 23: rank 0 alone wrote, Debian's HDF5 being
// serial) is kept for tests and tools that want the whole on rank 0. The components
// assemble the whole-level arrays of a frame or of the restart state by
// gathering their patches (ICE: PatchLayout::gather_blocks; MPM: the
// particles and RankNodeSums::whole). Outside an OutputToRoot scope these
// gathers deliver to every rank (MPI_Allgatherv: what the tests that compare
// a distributed component with the whole level on every rank need). Inside
// the scope, which TimeLoop opens around fill_output and save_state, they
// deliver to rank 0 only (MPI_Gatherv): the other ranks send their part and
// receive nothing, so the frame or archive they assemble is empty
// (`output_gather_lands_here()` is false there) and must not be used.
//
// Session 25 (issue 7 item 4, per-rank output): inside an OutputPerRank
// scope, which TimeLoop opens around fill_output and (session 27)
// save_state under mpirun, the gathers
// do not communicate at all: gather_output returns this rank's `local`,
// gather_patch_blocks returns this rank's blocks in their places (the other
// patches' blocks empty). The component marks which part of each grid array
// it owns (GridFieldArray::pieces, core/io/OutputFrame.h) and every rank
// writes its own frame file (core/io/RankFrameFile.h).
//
// Traffic per process (doubles of field data, the counts of the
// variable-size gathers not included):
//   to every rank: sent = n_local (size - 1), received = n_total - n_local
//   to rank 0:     rank 0 receives n_total - n_0, rank r > 0 sends n_r.
#include <vector>

namespace tephra {

class OutputToRoot {
 public:
  OutputToRoot();
  ~OutputToRoot();
  OutputToRoot(const OutputToRoot&) = delete;
  OutputToRoot& operator=(const OutputToRoot&) = delete;

 private:
  int previous_;
};

// Per-rank output: the gathers keep each rank's own data (see above).
class OutputPerRank {
 public:
  OutputPerRank();
  ~OutputPerRank();
  OutputPerRank(const OutputPerRank&) = delete;
  OutputPerRank& operator=(const OutputPerRank&) = delete;

 private:
  int previous_;
};

// True inside an OutputPerRank scope on more than one rank (one rank: the
// gathers are the identity anyway and the single-file layout is written).
bool output_per_rank();

// True inside an OutputToRoot scope.
bool output_gathers_to_root();

// True when this process receives the output gathers: outside a scope every
// rank, inside OutputToRoot rank 0 only, inside OutputPerRank every rank (its
// own part only).
bool output_gather_lands_here();

// Every rank's `local` concatenated in rank order, on every rank (outside a
// scope: all_gather) or on rank 0 only (inside: the other ranks get an empty
// vector). One rank, or inside OutputPerRank: `local`.
std::vector<double> gather_output(const std::vector<double>& local);

// Doubles this process contributed, sent to and received from other ranks in
// gather_output since the start (or the last reset). With the contributions
// n_r of every rank the traffic of either mode follows from the formulas above.
struct OutputGatherTraffic {
  long long calls = 0;
  long long doubles_own = 0;       // this rank's contributions (n_local summed over the calls)
  long long doubles_sent = 0;
  long long doubles_received = 0;
};
OutputGatherTraffic output_gather_traffic();
void reset_output_gather_traffic();

}  // namespace tephra
