// Per-rank checkpoint files and their manifest: see RankCheckpoint.h.
#include "core/io/RankCheckpoint.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>

#include "core/base/Errors.h"
#include "core/io/detail/ArchiveNames.h"
#include "core/io/detail/H5.h"

namespace tephra {
namespace fs = std::filesystem;

const char* const kCheckpointManifestFormat = "tephra-checkpoint-manifest-1";

namespace {

const char* kRankFormat = "tephra-checkpoint-rank-1";

// One array of one rank file.
template <class T>
struct RankArray {
  std::vector<T> values;
  ArchivePart part;
  bool has_part = false;
};

struct RankFileContent {
  std::string path;
  std::map<std::string, RankArray<double>> doubles;
  std::map<std::string, RankArray<long long>> ints;
};

std::string kind_name(ArchivePart::Kind k) { return k == ArchivePart::Kind::runs ? "runs" : "rows"; }

template <class T>
void write_array(hid_t group, hid_t runs, const std::string& name, const std::vector<T>& v, const ArchivePart* part,
                 const std::string& where) {
  const std::string link = archive_names::escape(name);
  if constexpr (std::is_same_v<T, double>)
    h5::write_doubles(group, link, {hsize_t(v.size())}, v.data(), where, true);
  else
    h5::write_int64s(group, link, {hsize_t(v.size())}, v.data(), where, true);
  if (!part) return;
  h5::Handle set = h5::open_dataset(group, link, where);
  h5::set_attr_string(set.id(), "part", kind_name(part->kind), where + ": " + name);
  if (part->kind == ArchivePart::Kind::runs) {
    h5::set_attr_int64s(set.id(), "whole_size", {static_cast<long long>(part->whole_size)}, where + ": " + name);
    std::vector<long long> flat;
    flat.reserve(2 * part->runs.size());
    for (const auto& [offset, length] : part->runs) {
      flat.push_back(static_cast<long long>(offset));
      flat.push_back(static_cast<long long>(length));
    }
    h5::write_int64s(runs, link, {hsize_t(part->runs.size()), 2}, flat.data(), where, true);
  } else {
    h5::set_attr_string(set.id(), "key", part->key, where + ": " + name);
    h5::set_attr_int64s(set.id(), "width", {static_cast<long long>(part->width)}, where + ": " + name);
  }
}

template <class T>
void read_arrays(hid_t group, hid_t runs, const std::string& where, std::map<std::string, RankArray<T>>& out) {
  for (const std::string& link : h5::children(group, where)) {
    const std::string name = archive_names::unescape(link, where);
    RankArray<T>& a = out[name];
    if constexpr (std::is_same_v<T, double>)
      a.values = h5::read_doubles(group, link, where);
    else
      a.values = h5::read_int64s(group, link, where);
    h5::Handle set = h5::open_dataset(group, link, where);
    if (!h5::has_attr(set.id(), "part")) continue;
    a.has_part = true;
    const std::string what = where + ": array '" + name + "'";
    const std::string kind = h5::attr_string(set.id(), "part", what);
    if (kind == "runs") {
      a.part.kind = ArchivePart::Kind::runs;
      a.part.whole_size = static_cast<std::size_t>(h5::attr_int64s(set.id(), "whole_size", what).at(0));
      const std::vector<long long> flat = h5::read_int64s(runs, link, what + " runs");
      std::size_t total = 0;
      for (std::size_t r = 0; r + 1 < flat.size(); r += 2) {
        if (flat[r] < 0 || flat[r + 1] < 0 ||
            static_cast<std::size_t>(flat[r] + flat[r + 1]) > a.part.whole_size)
          throw RuntimeFailure(what + ": a run outside the whole array");
        a.part.runs.emplace_back(static_cast<std::size_t>(flat[r]), static_cast<std::size_t>(flat[r + 1]));
        total += static_cast<std::size_t>(flat[r + 1]);
      }
      if (flat.size() % 2 != 0 || total != a.values.size())
        throw RuntimeFailure(what + ": its runs do not match its " + std::to_string(a.values.size()) + " values");
    } else if (kind == "rows") {
      a.part.kind = ArchivePart::Kind::rows;
      a.part.key = h5::attr_string(set.id(), "key", what);
      const long long width = h5::attr_int64s(set.id(), "width", what).at(0);
      if (width < 1) throw RuntimeFailure(what + ": row width " + std::to_string(width));
      a.part.width = static_cast<std::size_t>(width);
    } else {
      throw RuntimeFailure(what + ": unknown part kind '" + kind + "'");
    }
  }
}

RankFileContent read_rank_file(const std::string& path, int step, int rank, int ranks) {
  RankFileContent c;
  c.path = path;
  h5::Handle file = h5::open_file_readonly(path);
  if (!h5::has_attr(file.id(), "format") || h5::attr_string(file.id(), "format", path) != kRankFormat)
    throw RuntimeFailure(path + ": not a Tephra rank checkpoint file (format attribute missing or unknown)");
  if (h5::attr_int64s(file.id(), "step", path).at(0) != step || h5::attr_int64s(file.id(), "rank", path).at(0) != rank ||
      h5::attr_int64s(file.id(), "ranks", path).at(0) != ranks)
    throw RuntimeFailure(path + ": its step, rank or rank count is not that of the manifest (step " +
                         std::to_string(step) + ", rank " + std::to_string(rank) + " of " + std::to_string(ranks) + ")");
  h5::Handle runs = h5::open_group(file.id(), "runs", path);
  h5::Handle d = h5::open_group(file.id(), "doubles", path);
  read_arrays(d.id(), runs.id(), path, c.doubles);
  h5::Handle i = h5::open_group(file.id(), "ints", path);
  read_arrays(i.id(), runs.id(), path, c.ints);
  return c;
}

// The permutation that puts the concatenated keys of every rank in ascending
// order (stable: equal keys keep rank order), and each rank's key count.
struct RowOrder {
  std::vector<std::size_t> order;
  std::vector<std::size_t> count;  // rows per rank
};

RowOrder row_order(const std::vector<RankFileContent>& files, const std::string& key, const std::string& manifest) {
  RowOrder o;
  std::vector<long long> keys;
  for (const RankFileContent& f : files) {
    auto it = f.ints.find(key);
    if (it == f.ints.end())
      throw RuntimeFailure(f.path + ": has no key array '" + key + "' (checkpoint " + manifest + ")");
    o.count.push_back(it->second.values.size());
    keys.insert(keys.end(), it->second.values.begin(), it->second.values.end());
  }
  o.order.resize(keys.size());
  std::iota(o.order.begin(), o.order.end(), std::size_t(0));
  std::stable_sort(o.order.begin(), o.order.end(), [&](std::size_t a, std::size_t b) { return keys[a] < keys[b]; });
  return o;
}

// Merges one array over the rank files (the ranks that hold it).
template <class T>
std::vector<T> merge_array(const std::string& name, const std::vector<RankFileContent>& files,
                           const std::vector<const RankArray<T>*>& parts, std::map<std::string, RowOrder>& orders,
                           const std::string& manifest) {
  const RankArray<T>* first = nullptr;
  for (const RankArray<T>* p : parts)
    if (p) first = first ? first : p;
  if (!first->has_part) {  // whole: rank 0's copy
    if (!parts[0]) throw RuntimeFailure(files[0].path + ": has no array '" + name + "' (checkpoint " + manifest + ")");
    return parts[0]->values;
  }
  for (std::size_t r = 0; r < parts.size(); ++r)
    if (!parts[r] || !parts[r]->has_part || parts[r]->part.kind != first->part.kind)
      throw RuntimeFailure(files[r].path + ": array '" + name + "' is missing or not the " +
                           kind_name(first->part.kind) + " part the other rank files hold (checkpoint " + manifest + ")");
  if (first->part.kind == ArchivePart::Kind::runs) {
    std::vector<T> whole(first->part.whole_size, T(0));
    for (std::size_t r = 0; r < parts.size(); ++r) {
      const RankArray<T>& a = *parts[r];
      if (a.part.whole_size != first->part.whole_size)
        throw RuntimeFailure(files[r].path + ": array '" + name + "' has another whole size than rank 0's");
      std::size_t pos = 0;
      for (const auto& [offset, length] : a.part.runs) {
        std::copy(a.values.begin() + long(pos), a.values.begin() + long(pos + length), whole.begin() + long(offset));
        pos += length;
      }
    }
    return whole;
  }
  const std::size_t w = first->part.width;
  auto it = orders.find(first->part.key);
  if (it == orders.end()) it = orders.emplace(first->part.key, row_order(files, first->part.key, manifest)).first;
  const RowOrder& o = it->second;
  std::vector<T> cat;
  for (std::size_t r = 0; r < parts.size(); ++r) {
    const RankArray<T>& a = *parts[r];
    if (a.part.width != w || a.part.key != first->part.key || a.values.size() != o.count[r] * w)
      throw RuntimeFailure(files[r].path + ": array '" + name + "' does not have " + std::to_string(w) +
                           " values per entry of '" + first->part.key + "'");
    cat.insert(cat.end(), a.values.begin(), a.values.end());
  }
  std::vector<T> out(cat.size());
  for (std::size_t j = 0; j < o.order.size(); ++j)
    std::copy(cat.begin() + long(o.order[j] * w), cat.begin() + long((o.order[j] + 1) * w), out.begin() + long(j * w));
  return out;
}

template <class T>
void merge_all(const std::vector<RankFileContent>& files, std::map<std::string, RankArray<T>> RankFileContent::*arrays,
               std::map<std::string, RowOrder>& orders, const std::string& manifest, StateArchive& out) {
  std::map<std::string, std::vector<const RankArray<T>*>> by_name;
  for (std::size_t r = 0; r < files.size(); ++r)
    for (const auto& [name, a] : files[r].*arrays) {
      auto& v = by_name[name];
      v.resize(files.size(), nullptr);
      v[r] = &a;
    }
  for (const auto& [name, parts] : by_name) out.put(name, merge_array(name, files, parts, orders, manifest));
}

}  // namespace

std::string rank_checkpoint_file_name(int step, int rank) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "c%05d.r%d.h5", step, rank);
  return buf;
}

std::pair<int, int> parse_rank_checkpoint_file_name(const std::string& name) {
  // c + digits + .r + digits + .h5
  const std::size_t dot = name.find(".r");
  if (name.size() < 8 || name[0] != 'c' || dot == std::string::npos || name.compare(name.size() - 3, 3, ".h5") != 0)
    return {-1, -1};
  const std::string step = name.substr(1, dot - 1);
  const std::string rank = name.substr(dot + 2, name.size() - 3 - (dot + 2));
  for (const std::string* s : {&step, &rank}) {
    if (s->empty() || s->size() > 9) return {-1, -1};
    for (char c : *s)
      if (c < '0' || c > '9') return {-1, -1};
  }
  return {std::stoi(step), std::stoi(rank)};
}

void write_rank_checkpoint_file(const std::string& path, int step, const StateArchive& a, int rank, int ranks) {
  h5::Handle file = h5::create_file(path);
  h5::set_attr_string(file.id(), "format", kRankFormat, path);
  h5::set_attr_int64s(file.id(), "step", {step}, path);
  h5::set_attr_int64s(file.id(), "rank", {rank}, path);
  h5::set_attr_int64s(file.id(), "ranks", {ranks}, path);
  h5::Handle runs = h5::create_group(file.id(), "runs", path);
  h5::Handle d = h5::create_group(file.id(), "doubles", path);
  for (const auto& [name, v] : a.all_doubles())
    if (a.part(name) || rank == 0) write_array(d.id(), runs.id(), name, v, a.part(name), path);
  h5::Handle i = h5::create_group(file.id(), "ints", path);
  for (const auto& [name, v] : a.all_ints())
    if (a.part(name) || rank == 0) write_array(i.id(), runs.id(), name, v, a.part(name), path);
  h5::flush(file, path);
}

void write_checkpoint_manifest(const std::string& path, const std::string& dir, int step, int ranks) {
  std::vector<long long> bytes;
  for (int r = 0; r < ranks; ++r) {
    const std::string rank_path = (fs::path(dir) / rank_checkpoint_file_name(step, r)).string();
    std::error_code ec;
    const auto size = fs::file_size(rank_path, ec);
    if (ec) throw RuntimeFailure(rank_path + ": rank file of checkpoint " + path + " is missing (" + ec.message() + ")");
    bytes.push_back(static_cast<long long>(size));
  }
  h5::Handle file = h5::create_file(path);
  h5::set_attr_string(file.id(), "format", kCheckpointManifestFormat, path);
  h5::set_attr_int64s(file.id(), "step", {step}, path);
  h5::set_attr_int64s(file.id(), "ranks", {ranks}, path);
  h5::write_int64s(file.id(), "rank_file_bytes", {hsize_t(bytes.size())}, bytes.data(), path, true);
  h5::flush(file, path);
}

StateArchive read_checkpoint_manifest(const std::string& path) {
  int step = 0;
  int ranks = 0;
  std::vector<long long> bytes;
  {
    h5::Handle file = h5::open_file_readonly(path);
    step = static_cast<int>(h5::attr_int64s(file.id(), "step", path).at(0));
    ranks = static_cast<int>(h5::attr_int64s(file.id(), "ranks", path).at(0));
    bytes = h5::read_int64s(file.id(), "rank_file_bytes", path);
  }
  if (ranks < 1 || bytes.size() != std::size_t(ranks))
    throw RuntimeFailure(path + ": manifest lists " + std::to_string(bytes.size()) + " rank files for " +
                         std::to_string(ranks) + " ranks");
  const fs::path dir = fs::path(path).parent_path();
  std::vector<RankFileContent> files;
  for (int r = 0; r < ranks; ++r) {
    const std::string rank_path = (dir / rank_checkpoint_file_name(step, r)).string();
    std::error_code ec;
    const auto size = fs::file_size(rank_path, ec);
    if (ec) throw RuntimeFailure(rank_path + ": rank file of checkpoint " + path + " is missing");
    if (static_cast<long long>(size) != bytes[std::size_t(r)])
      throw RuntimeFailure(rank_path + ": rank file of checkpoint " + path + " has " + std::to_string(size) +
                           " bytes, the manifest says " + std::to_string(bytes[std::size_t(r)]) +
                           " (truncated or replaced)");
    files.push_back(read_rank_file(rank_path, step, r, ranks));
  }
  StateArchive out;
  std::map<std::string, RowOrder> orders;
  merge_all(files, &RankFileContent::ints, orders, path, out);
  merge_all(files, &RankFileContent::doubles, orders, path, out);
  return out;
}

}  // namespace tephra
