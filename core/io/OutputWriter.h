#pragma once
// Everything a run writes into its output directory (the deck's <filebase>
// or --output DIR):
//   input.ups               the deck with its includes resolved
//   tephra.xdmf             XDMF index of all frames (ParaView / VisIt open it)
//   frames/t<step>.h5       one HDF5 file per output time: grid fields on the
//                           structured grid, particles as point clouds; under
//                           mpirun (session 25) the small index of the rank
//                           files frames/t<step>.r<rank>.h5 (core/io/RankFrameFile.h)
//   <Label>.dat             reduction labels: "time value" or "time x y z" rows
//   checkpoints/            see CheckpointStore
//   tephra-reductions.txt   the reduction labels written (so that a fresh run
//                           removes only Tephra's own .dat files)
// Every file is written under a temporary name and renamed, so an interrupted
// run never leaves a half-written file. .dat rows are appended with a single
// write(2) each (see core/io/detail/Files.h), so no partial row is left either.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/io/OutputFrame.h"

namespace tephra {

class OutputWriter {
 public:
  // Creates `dir` if needed. When `restarting` is false, stale frames, .dat
  // files and the XDMF index from an earlier run in `dir` are removed (also
  // its input.ups and checkpoints/c*.h5, which belong to that run). When
  // restarting, the frames on disk are indexed again.
  OutputWriter(const std::string& dir, bool restarting);

  const std::string& dir() const { return dir_; }

  void write_deck_copy(const std::string& resolved_xml);

  // Writes frames/t<step>.h5 and rewrites tephra.xdmf to list every frame.
  void write_frame(const OutputFrame& frame);

  // Multi-rank frame (rank 0, after every rank's write_rank_frame): writes
  // the index frames/t<step>.h5 last and lists the rank files in tephra.xdmf.
  // RuntimeFailure naming the file when a rank file is missing or unreadable.
  void write_frame_index(int step, double time, int ranks);

  // Appends one row per label to <label>.dat, full precision (%.17g).
  // A label must be a plain file name (no '/', no whitespace).
  void append_reductions(double time, const std::map<std::string, std::vector<double>>& values);

  // For a restart from `step`/`time`: drops .dat rows with time > `time`
  // and frames with step > `step`, so the continued run appends exactly
  // the rows an uninterrupted run would have written.
  void truncate_after(int step, double time);

 private:
  void write_index() const;               // rewrites tephra.xdmf from frame_index_
  void add_reduction_label(const std::string& label);

  std::string dir_;
  std::map<int, std::string> frame_index_;  // step -> its XDMF <Grid> element
  std::set<std::string> reduction_labels_;  // as listed in tephra-reductions.txt
};

// One rank's part of a frame (core/io/RankFrameFile.h): frames/t<step>.r<rank>.h5
// under `dir` (which exists), tmp+rename. Any rank; returns the path.
std::string write_rank_frame(const std::string& dir, const OutputFrame& frame, int rank, int ranks);

// Checkpoints: checkpoints/c<step>.h5 (step zero-padded to 5+ digits) with
// every array of a StateArchive, keeping only the newest `cycle` of them.
// Writing step s also removes checkpoints newer than s: after a restart from
// an older checkpoint they belong to an abandoned continuation.
// File layout: attrs format "tephra-checkpoint-1", step; /doubles/<name> (f64)
// and /ints/<name> (i64), 1-D, with HDF5's Fletcher-32 checksum so a
// corrupted file is detected on read. In names, '%', '/' and a leading '.'
// are written as %25, %2F and %2E.
// Under mpirun (session 27, core/io/RankCheckpoint.h) every rank writes
// c<step>.r<rank>.h5 (write_rank_part) and rank 0, after a barrier, the
// manifest c<step>.h5 (write_manifest); read() merges them. steps() lists a
// checkpoint only when its c<step>.h5 exists; retention removes a dropped
// checkpoint's rank files and rank files without a manifest.
class StateArchive;

class CheckpointStore {
 public:
  CheckpointStore(const std::string& output_dir, int cycle);  // cycle >= 1
  const std::string& dir() const { return dir_; }             // output_dir/checkpoints
  std::string path(int step) const;                           // dir()/c<step>.h5
  void write(int step, const StateArchive& state);
  std::string rank_path(int step, int rank) const;  // dir()/c<step>.r<rank>.h5
  void write_rank_part(int step, const StateArchive& state, int rank, int ranks) const;  // any rank
  void write_manifest(int step, int ranks);  // rank 0, once every rank part is written
  std::vector<int> steps() const;                   // available checkpoints, ascending
  StateArchive read(int step) const;                // throws RuntimeFailure if absent or corrupt

 private:
  void keep_newest_up_to(int step, int ranks);  // retention after writing `step` on `ranks` files
  std::string dir_;
  int cycle_;
};

}  // namespace tephra
