#pragma once
// Everything a run writes into its output directory (the deck's <filebase>
// or --output DIR):
//   input.ups               the deck with its includes resolved
//   tephra.xdmf             XDMF index of all frames (ParaView / VisIt open it)
//   frames/t<step>.h5       one HDF5 file per output time: grid fields on the
//                           structured grid, particles as point clouds
//   <Label>.dat             reduction labels: "time value" or "time x y z" rows
//   checkpoints/            see CheckpointStore
// Every file is written under a temporary name and renamed, so an interrupted
// run never leaves a half-written file.
#include <map>
#include <string>
#include <vector>

#include "core/io/OutputFrame.h"

namespace tephra {

class OutputWriter {
 public:
  // Creates `dir` if needed. When `restarting` is false, stale frames, .dat
  // files and the XDMF index from an earlier run in `dir` are removed.
  OutputWriter(const std::string& dir, bool restarting);

  const std::string& dir() const { return dir_; }

  void write_deck_copy(const std::string& resolved_xml);

  // Writes frames/t<step>.h5 and rewrites tephra.xdmf to list every frame.
  void write_frame(const OutputFrame& frame);

  // Appends one row per label to <label>.dat, full precision (%.17g).
  void append_reductions(double time, const std::map<std::string, std::vector<double>>& values);

  // For a restart from `step`/`time`: drops .dat rows with time > `time`
  // and frames with step > `step`, so the continued run appends exactly
  // the rows an uninterrupted run would have written.
  void truncate_after(int step, double time);

 private:
  std::string dir_;
};

// Checkpoints: checkpoints/c<step>.h5 with every array of a StateArchive,
// keeping only the newest `cycle` of them.
class StateArchive;

class CheckpointStore {
 public:
  CheckpointStore(const std::string& output_dir, int cycle);
  void write(int step, const StateArchive& state);
  std::vector<int> steps() const;                   // available checkpoints, ascending
  StateArchive read(int step) const;                // throws RuntimeFailure if absent or corrupt

 private:
  std::string dir_;
  int cycle_;
};

}  // namespace tephra
