// CheckpointStore: the restartable state as HDF5 files, bit for bit.
// Doubles are stored as IEEE binary64 little-endian (H5T_IEEE_F64LE) and read
// back into native doubles, integers as int64 (H5T_STD_I64LE): on any
// little-endian IEEE machine both conversions are the identity, so a restart
// continues with exactly the bits that were saved.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/io/OutputWriter.h"
#include "core/io/RankCheckpoint.h"
#include "core/io/StateArchive.h"
#include "core/io/detail/ArchiveNames.h"
#include "core/io/detail/Files.h"
#include "core/io/detail/H5.h"

namespace tephra {
namespace fs = std::filesystem;
namespace {

const char* kFormat = "tephra-checkpoint-1";

int parse_checkpoint_name(const std::string& name) {
  // c + digits + .h5
  if (name.size() < 5 || name[0] != 'c' || name.compare(name.size() - 3, 3, ".h5") != 0) return -1;
  const std::string digits = name.substr(1, name.size() - 4);
  if (digits.empty() || digits.size() > 9) return -1;
  for (char c : digits)
    if (c < '0' || c > '9') return -1;
  return std::stoi(digits);
}

}  // namespace

CheckpointStore::CheckpointStore(const std::string& output_dir, int cycle)
    : dir_((fs::path(output_dir) / "checkpoints").string()), cycle_(cycle) {
  if (cycle < 1)
    throw std::invalid_argument("checkpoint cycle must be at least 1, got " + std::to_string(cycle));
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw RuntimeFailure(dir_ + ": cannot create directory (" + ec.message() + ")");
}

std::string CheckpointStore::path(int step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "c%05d.h5", step);
  return (fs::path(dir_) / buf).string();
}

void CheckpointStore::write(int step, const StateArchive& state) {
  files::write_via_tmp(path(step), [&](const std::string& tmp) {
    h5::Handle file = h5::create_file(tmp);
    h5::set_attr_string(file.id(), "format", kFormat, tmp);
    h5::set_attr_int64s(file.id(), "step", {step}, tmp);
    h5::Handle d = h5::create_group(file.id(), "doubles", tmp);
    for (const auto& [name, v] : state.all_doubles())
      h5::write_doubles(d.id(), archive_names::escape(name), {hsize_t(v.size())}, v.data(), tmp, true);
    h5::Handle i = h5::create_group(file.id(), "ints", tmp);
    for (const auto& [name, v] : state.all_ints())
      h5::write_int64s(i.id(), archive_names::escape(name), {hsize_t(v.size())}, v.data(), tmp, true);
    h5::flush(file, tmp);
  });
  keep_newest_up_to(step, 0);
}

std::string CheckpointStore::rank_path(int step, int rank) const {
  return (fs::path(dir_) / rank_checkpoint_file_name(step, rank)).string();
}

void CheckpointStore::write_rank_part(int step, const StateArchive& state, int rank, int ranks) const {
  files::write_via_tmp(rank_path(step, rank), [&](const std::string& tmp) { write_rank_checkpoint_file(tmp, step, state, rank, ranks); });
}

void CheckpointStore::write_manifest(int step, int ranks) {
  files::write_via_tmp(path(step), [&](const std::string& tmp) { write_checkpoint_manifest(tmp, dir_, step, ranks); });
  keep_newest_up_to(step, ranks);
}

// Retention: drop checkpoints newer than `step` (an abandoned continuation),
// then the oldest until `cycle` remain; then every rank file that belongs to
// no kept checkpoint (a dropped one's, or one whose manifest was never
// written: an interrupted write), and those of `step` itself beyond its
// `ranks` files (left by an interrupted write of the same step on more ranks;
// a one-file checkpoint has 0 rank files).
void CheckpointStore::keep_newest_up_to(int step, int ranks) {
  std::vector<int> kept;
  for (int s : steps()) {
    if (s > step) files::remove_if_present(path(s));
    else kept.push_back(s);
  }
  while (kept.size() > std::size_t(cycle_)) {
    files::remove_if_present(path(kept.front()));
    kept.erase(kept.begin());
  }
  std::vector<std::string> doomed;
  for (const auto& e : fs::directory_iterator(dir_)) {
    const auto [s, rank] = parse_rank_checkpoint_file_name(e.path().filename().string());
    if (s < 0) continue;
    if (std::find(kept.begin(), kept.end(), s) == kept.end() || (s == step && rank >= ranks))
      doomed.push_back(e.path().string());
  }
  for (const std::string& p : doomed) files::remove_if_present(p);
}

std::vector<int> CheckpointStore::steps() const {
  std::vector<int> out;
  for (const auto& e : fs::directory_iterator(dir_)) {
    const int s = parse_checkpoint_name(e.path().filename().string());
    if (s >= 0 && e.is_regular_file()) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

StateArchive CheckpointStore::read(int step) const {
  const std::string p = path(step);
  h5::Handle file = h5::open_file_readonly(p);
  const std::string format = h5::has_attr(file.id(), "format") ? h5::attr_string(file.id(), "format", p) : "";
  if (format == kCheckpointManifestFormat) {
    file.close();
    return read_checkpoint_manifest(p);
  }
  if (format != kFormat) throw RuntimeFailure(p + ": not a Tephra checkpoint (format attribute missing or unknown)");
  StateArchive out;
  h5::Handle d = h5::open_group(file.id(), "doubles", p);
  for (const std::string& name : h5::children(d.id(), p))
    out.put(archive_names::unescape(name, p), h5::read_doubles(d.id(), name, p));
  h5::Handle i = h5::open_group(file.id(), "ints", p);
  for (const std::string& name : h5::children(i.id(), p))
    out.put(archive_names::unescape(name, p), h5::read_int64s(i.id(), name, p));
  return out;
}

}  // namespace tephra
