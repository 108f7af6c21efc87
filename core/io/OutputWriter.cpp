#include "core/io/OutputWriter.h"

#include <filesystem>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/io/FrameFile.h"
#include "core/io/RankCheckpoint.h"
#include "core/io/RankFrameFile.h"
#include "core/io/Reductions.h"
#include "core/io/Xdmf.h"
#include "core/io/detail/Files.h"

namespace tephra {
namespace fs = std::filesystem;
namespace {

const char* kIndex = "tephra.xdmf";

void make_dirs(const fs::path& p) {
  std::error_code ec;
  fs::create_directories(p, ec);
  if (ec) throw RuntimeFailure(p.string() + ": cannot create directory (" + ec.message() + ")");
}

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Removes what an earlier, unrelated run left: frames, their tmp files,
// checkpoints. Only names Tephra itself writes are touched.
void remove_matching(const fs::path& folder, bool (*ours)(const std::string&)) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return;
  std::vector<fs::path> doomed;
  for (const auto& e : fs::directory_iterator(folder))
    if (ours(e.path().filename().string())) doomed.push_back(e.path());
  for (const fs::path& p : doomed) files::remove_if_present(p.string());
}

bool is_frame_or_tmp(const std::string& name) {
  const std::string n = ends_with(name, ".h5.tmp") ? name.substr(0, name.size() - 4) : name;
  return parse_frame_file_name(n) >= 0 || parse_rank_frame_file_name(n).first >= 0;
}

// The XDMF element of the frame file `path` (a single file, or the index of
// rank files), built from the files as written, so it cannot disagree with them.
std::string frame_xdmf(const std::string& path, int step) {
  if (!is_frame_index_file(path)) return xdmf_frame_grid(read_frame_file(path, false), "frames/" + frame_file_name(step));
  std::vector<std::pair<SavedFrame, std::string>> ranks;
  for (const std::string& f : rank_files_of_index(path))
    ranks.emplace_back(read_rank_file_layout(f), "frames/" + fs::path(f).filename().string());
  return xdmf_rank_frame_grid(ranks);
}

bool is_checkpoint_or_tmp(const std::string& name) {
  std::string n = ends_with(name, ".tmp") ? name.substr(0, name.size() - 4) : name;
  if (parse_rank_checkpoint_file_name(n).first >= 0) return true;  // a rank's part (RankCheckpoint.h)
  if (n.size() < 4 || n[0] != 'c' || !ends_with(n, ".h5")) return false;
  for (size_t i = 1; i + 3 < n.size(); ++i)
    if (n[i] < '0' || n[i] > '9') return false;
  return n.size() > 4;
}

// Rank frame files (t<step>.r<rank>.h5) of the steps after `step`.
void remove_matching_rank_frames(const fs::path& folder, int step) {
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return;
  std::vector<fs::path> doomed;
  for (const auto& e : fs::directory_iterator(folder))
    if (parse_rank_frame_file_name(e.path().filename().string()).first > step) doomed.push_back(e.path());
  for (const fs::path& p : doomed) files::remove_if_present(p.string());
}

bool is_tmp(const std::string& name) { return ends_with(name, ".tmp"); }

void check_reduction_label(const std::string& label) {
  if (label.empty() || label == "." || label == ".." ||
      label.find_first_of("/ \t\n\r") != std::string::npos)
    throw std::invalid_argument("reduction label '" + label + "' is not a plain file name");
}

}  // namespace

OutputWriter::OutputWriter(const std::string& dir, bool restarting) : dir_(dir) {
  const fs::path root(dir_);
  make_dirs(root / "frames");
  // Temporary files are never valid output: a run died while writing them.
  remove_matching(root / "frames", is_tmp);
  for (const char* name : {kIndex, kReductionManifest, "input.ups"})
    files::remove_if_present(files::tmp_name((root / name).string()));
  if (!restarting) {
    remove_matching(root / "frames", is_frame_or_tmp);
    remove_matching(root / "checkpoints", is_checkpoint_or_tmp);
    for (const std::string& label : read_reduction_labels(dir_)) {
      files::remove_if_present(reduction_file(dir_, label));
      files::remove_if_present(files::tmp_name(reduction_file(dir_, label)));
    }
    for (const char* name : {kIndex, kReductionManifest, "input.ups"})
      files::remove_if_present((root / name).string());
    return;
  }
  for (const std::string& label : read_reduction_labels(dir_)) {
    reduction_labels_.insert(label);
    const std::string path = reduction_file(dir_, label);
    files::remove_if_present(files::tmp_name(path));
    // A row torn by a system crash (no final newline) would otherwise fuse
    // with the next appended row: keep only the complete rows.
    if (fs::exists(path)) {
      const std::string text = files::read_all(path);
      if (!text.empty() && text.back() != '\n')
        files::write_atomic(path, text.substr(0, text.rfind('\n') + 1));
    }
  }
  for (const auto& [step, path] : list_frame_files(dir_)) frame_index_[step] = frame_xdmf(path, step);
  write_index();
}

void OutputWriter::write_deck_copy(const std::string& resolved_xml) {
  files::write_atomic((fs::path(dir_) / "input.ups").string(), resolved_xml);
}

void OutputWriter::write_frame(const OutputFrame& frame) {
  const std::string name = frame_file_name(frame.step);
  const std::string path = (fs::path(dir_) / "frames" / name).string();
  files::write_via_tmp(path, [&](const std::string& tmp) { write_frame_file(tmp, frame); });
  // The index is built from the file as written, so it cannot disagree with it.
  frame_index_[frame.step] = frame_xdmf(path, frame.step);
  write_index();
}

std::string write_rank_frame(const std::string& dir, const OutputFrame& frame, int rank, int ranks) {
  const std::string path = (fs::path(dir) / "frames" / rank_frame_file_name(frame.step, rank)).string();
  files::write_via_tmp(path, [&](const std::string& tmp) { write_rank_frame_file(tmp, frame, rank, ranks); });
  return path;
}

void OutputWriter::write_frame_index(int step, double time, int ranks) {
  const std::string path = (fs::path(dir_) / "frames" / frame_file_name(step)).string();
  // Every rank file is read (its layout) before the index names it.
  std::vector<std::pair<SavedFrame, std::string>> layouts;
  for (int r = 0; r < ranks; ++r) {
    const std::string name = rank_frame_file_name(step, r);
    const std::string f = (fs::path(dir_) / "frames" / name).string();
    std::error_code ec;
    if (!fs::is_regular_file(f, ec))
      throw RuntimeFailure(f + ": rank file missing (rank " + std::to_string(r) + " of " + std::to_string(ranks) + ")");
    layouts.emplace_back(read_rank_file_layout(f), "frames/" + name);
  }
  files::write_via_tmp(path, [&](const std::string& tmp) { write_frame_index_file(tmp, step, time, ranks); });
  frame_index_[step] = xdmf_rank_frame_grid(layouts);
  write_index();
}

void OutputWriter::write_index() const {
  const std::string path = (fs::path(dir_) / kIndex).string();
  if (frame_index_.empty()) {
    files::remove_if_present(path);
    return;
  }
  std::vector<std::string> grids;
  for (const auto& [step, grid] : frame_index_) grids.push_back(grid);
  files::write_atomic(path, xdmf_document(grids));
}

void OutputWriter::add_reduction_label(const std::string& label) {
  if (reduction_labels_.count(label)) return;
  reduction_labels_.insert(label);
  // The manifest is updated before the first row exists, so every .dat
  // file on disk is always listed.
  std::string text;
  for (const std::string& l : reduction_labels_) text += l + "\n";
  files::write_atomic((fs::path(dir_) / kReductionManifest).string(), text);
}

void OutputWriter::append_reductions(double time,
                                     const std::map<std::string, std::vector<double>>& values) {
  for (const auto& [label, v] : values) {
    check_reduction_label(label);
    if (v.empty()) throw std::invalid_argument("reduction '" + label + "' has no value");
    add_reduction_label(label);
    files::append_row(reduction_file(dir_, label), format_reduction_row(time, v));
  }
}

void OutputWriter::truncate_after(int step, double time) {
  for (const std::string& label : reduction_labels_) {
    const std::string path = reduction_file(dir_, label);
    if (!fs::exists(path)) continue;
    std::string kept;
    for (const ReductionRow& row : read_reduction_file(path))
      if (row.time <= time) kept += format_reduction_row(row.time, row.values);
    files::write_atomic(path, kept);
  }
  for (auto it = frame_index_.begin(); it != frame_index_.end();) {
    if (it->first > step) {
      files::remove_if_present((fs::path(dir_) / "frames" / frame_file_name(it->first)).string());
      it = frame_index_.erase(it);
    } else {
      ++it;
    }
  }
  // Frames on disk that were not indexed (e.g. unreadable) but lie past the
  // restart point go too, and so do the rank files of those frames (index first:
  // a frame is never listed without its rank files).
  for (const auto& [s, path] : list_frame_files(dir_))
    if (s > step) files::remove_if_present(path);
  remove_matching_rank_frames(fs::path(dir_) / "frames", step);
  write_index();
}

}  // namespace tephra
