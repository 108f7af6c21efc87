#pragma once
// Named arrays that make up the restartable state of a run. Components put
// every array they need to continue bit for bit; the checkpoint writer stores
// them in HDF5 exactly (doubles as IEEE doubles, integers as int64).
#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "core/base/Errors.h"

namespace tephra {

// Per-rank checkpoints (issue 7, session 27; core/io/RankCheckpoint.h): under
// mpirun each rank puts only its own part of a distributed array and says
// which part it is, so the rank files merge into the whole array the
// one-file checkpoint holds:
//   whole: the same on every rank (scalars, sums): rank 0's copy is kept;
//   runs:  the whole array has `whole_size` entries; this rank's values are
//          the entries [offset, offset + length) of each run, concatenated in
//          run order; the runs of all ranks are disjoint, entries in no run
//          are 0 (what the gather to rank 0 gave);
//   rows:  `width` values per row, one row per entry of the int array `key`
//          (particle ids); the whole array is every rank's rows in ascending
//          key (the key array itself is rows of width 1 keyed by itself).
struct ArchivePart {
  enum class Kind { whole, runs, rows };
  Kind kind = Kind::whole;
  std::size_t whole_size = 0;
  std::vector<std::pair<std::size_t, std::size_t>> runs;  // (offset, length)
  std::string key;
  std::size_t width = 1;

  static ArchivePart as_runs(std::size_t whole_size, std::vector<std::pair<std::size_t, std::size_t>> runs) {
    ArchivePart p;
    p.kind = Kind::runs;
    p.whole_size = whole_size;
    p.runs = std::move(runs);
    return p;
  }
  static ArchivePart as_rows(std::string key, std::size_t width) {
    ArchivePart p;
    p.kind = Kind::rows;
    p.key = std::move(key);
    p.width = width;
    return p;
  }
};

class StateArchive {
 public:
  void put(const std::string& name, std::vector<double> values) { doubles_[name] = std::move(values); }
  void put(const std::string& name, std::vector<long long> values) { ints_[name] = std::move(values); }
  // This rank's part of a distributed array (per-rank checkpoints, above).
  void put(const std::string& name, std::vector<double> values, ArchivePart part) {
    doubles_[name] = std::move(values);
    parts_[name] = std::move(part);
  }
  void put(const std::string& name, std::vector<long long> values, ArchivePart part) {
    ints_[name] = std::move(values);
    parts_[name] = std::move(part);
  }
  void put_scalar(const std::string& name, double v) { doubles_[name] = {v}; }
  void put_int(const std::string& name, long long v) { ints_[name] = {v}; }

  const std::vector<double>& doubles(const std::string& name) const {
    auto it = doubles_.find(name);
    if (it == doubles_.end()) throw RuntimeFailure("checkpoint has no array '" + name + "'");
    return it->second;
  }
  const std::vector<long long>& ints(const std::string& name) const {
    auto it = ints_.find(name);
    if (it == ints_.end()) throw RuntimeFailure("checkpoint has no array '" + name + "'");
    return it->second;
  }
  double scalar(const std::string& name) const { return doubles(name).at(0); }
  long long integer(const std::string& name) const { return ints(name).at(0); }
  bool has(const std::string& name) const { return doubles_.count(name) || ints_.count(name); }

  const std::map<std::string, std::vector<double>>& all_doubles() const { return doubles_; }
  const std::map<std::string, std::vector<long long>>& all_ints() const { return ints_; }
  // The part an array is of (nullptr: whole).
  const ArchivePart* part(const std::string& name) const {
    auto it = parts_.find(name);
    return it == parts_.end() ? nullptr : &it->second;
  }

 private:
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<long long>> ints_;
  std::map<std::string, ArchivePart> parts_;
};

}  // namespace tephra
