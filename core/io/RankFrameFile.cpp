// Per-rank frame files and their index (see RankFrameFile.h for the layout).
#include "core/io/RankFrameFile.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "core/base/Errors.h"
#include "core/io/detail/FrameParts.h"
#include "core/io/detail/H5.h"

namespace tephra {

const char* const kFrameIndexFormat = "tephra-frame-index-1";

namespace fs = std::filesystem;
using namespace frame_detail;

namespace {

const char* kRankFormat = "tephra-frame-rank-1";

// One stored piece of a field in a rank file.
struct Piece {
  IntVec3 offset = IntVec3::Zero();  // from the whole field's first entry
  IntVec3 extent = IntVec3::Zero();
  std::string dataset;               // HDF5 path in the rank file
  std::vector<double> values;        // empty for a layout-only read
};

// A field group of a rank file: the whole field's layout and this rank's pieces.
struct FieldGroup {
  SavedGridField whole;  // values empty
  std::vector<Piece> pieces;
};

struct RankFile {
  int step = 0, rank = 0, ranks = 0;
  double time = 0.0;
  bool has_grid = false;
  Grid grid;
  std::vector<FieldGroup> fields;
  std::vector<SavedParticles> particles;
};

long long one_int(hid_t obj, const char* name, const std::string& where) {
  const std::vector<long long> v = h5::attr_int64s(obj, name, where);
  if (v.size() != 1) throw RuntimeFailure(where + ": bad '" + name + "' attribute");
  return v[0];
}

double one_double(hid_t obj, const char* name, const std::string& where) {
  const std::vector<double> v = h5::attr_doubles(obj, name, where);
  if (v.size() != 1) throw RuntimeFailure(where + ": bad '" + name + "' attribute");
  return v[0];
}

bool inside(const IntVec3& offset, const IntVec3& extent, const IntVec3& whole) {
  return (offset.array() >= 0).all() && ((offset + extent).array() <= whole.array()).all();
}

RankFile read_rank(const std::string& path, bool with_values, const std::string& only) {
  h5::Handle file = h5::open_file_readonly(path);
  if (!h5::has_attr(file.id(), "format") || h5::attr_string(file.id(), "format", path) != kRankFormat)
    throw RuntimeFailure(path + ": not a Tephra rank frame file (format attribute missing or unknown)");
  RankFile out;
  out.time = one_double(file.id(), "time", path);
  out.step = static_cast<int>(one_int(file.id(), "step", path));
  out.rank = static_cast<int>(one_int(file.id(), "rank", path));
  out.ranks = static_cast<int>(one_int(file.id(), "ranks", path));
  if (h5::exists(file.id(), "grid")) {
    h5::Handle g = h5::open_group(file.id(), "grid", path);
    out.has_grid = true;
    read_grid_geometry(g.id(), out.grid, path);
    for (const std::string& mname : h5::children(g.id(), path)) {
      const int material = parse_mat_group(mname, path);
      h5::Handle m = h5::open_group(g.id(), mname, path);
      for (const std::string& label : h5::children(m.id(), path)) {
        const std::string where = path + ":/grid/" + mname + "/" + label;
        h5::Handle lg = h5::open_group(m.id(), label, where);
        FieldGroup fg;
        SavedGridField& w = fg.whole;
        w.field.data.label = label;
        w.field.data.material = material;
        w.field.data.components = static_cast<int>(one_int(lg.id(), "components", where));
        w.field.location = parse_location(h5::attr_string(lg.id(), "centering", where), where);
        w.first_index = to_ivec(h5::attr_int64s(lg.id(), "first_index", where), where);
        w.extent = to_ivec(h5::attr_int64s(lg.id(), "extent", where), where);
        const int nc = w.field.data.components;
        if (nc != 1 && nc != 3 && nc != 9) throw RuntimeFailure(where + ": components must be 1, 3 or 9");
        for (const std::string& bname : h5::children(lg.id(), where)) {
          const std::string bwhere = where + "/" + bname;
          const std::vector<hsize_t> dims = h5::dataset_dims(lg.id(), bname, bwhere);
          if (dims.size() != (nc > 1 ? 4u : 3u) || (nc > 1 && dims[3] != hsize_t(nc)))
            throw RuntimeFailure(bwhere + ": expected [nk][nj][ni]" + (nc > 1 ? "[" + std::to_string(nc) + "]" : ""));
          h5::Handle set(H5Dopen2(lg.id(), bname.c_str(), H5P_DEFAULT), h5::Handle::Kind::Dataset);
          Piece p;
          p.offset = to_ivec(h5::attr_int64s(set.id(), "offset", bwhere), bwhere);
          p.extent = IntVec3(int(dims[2]), int(dims[1]), int(dims[0]));
          if (!inside(p.offset, p.extent, w.extent))
            throw RuntimeFailure(bwhere + ": piece lies outside the field's extent");
          p.dataset = "/grid/" + mname + "/" + label + "/" + bname;
          if (with_values && (only.empty() || only == label)) p.values = h5::read_doubles(lg.id(), bname, bwhere);
          fg.pieces.push_back(std::move(p));
        }
        out.fields.push_back(std::move(fg));
      }
    }
  }
  if (h5::exists(file.id(), "particles")) {
    SavedFrame parts;
    read_particles(file.id(), parts, with_values, only, path);
    out.particles = std::move(parts.particles);
  }
  return out;
}

// Puts a merged particle set in ascending id (the single file's order): the
// ranks' sets are each in id order, their concatenation is not.
void sort_by_id(SavedParticles& p) {
  ParticleBlock& b = p.block;
  const std::size_t n = b.id.size();
  if (n != static_cast<std::size_t>(p.count) || std::is_sorted(b.id.begin(), b.id.end())) return;
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return b.id[a] < b.id[c]; });
  auto permute = [&](auto& column, std::size_t per) {
    if (column.size() != n * per) return;
    auto old = column;
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < per; ++k) column[j * per + k] = old[order[j] * per + k];
  };
  permute(b.position, 1);
  permute(b.id, 1);
  for (FieldArray& f : b.fields) permute(f.values, std::size_t(f.components));
}

}  // namespace

std::string rank_frame_file_name(int step, int rank) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "t%05d.r%d.h5", step, rank);
  return buf;
}

std::pair<int, int> parse_rank_frame_file_name(const std::string& name) {
  const std::size_t dot = name.find(".r");
  if (dot == std::string::npos || name.size() < dot + 6 || name.compare(name.size() - 3, 3, ".h5") != 0)
    return {-1, -1};
  const int step = parse_frame_file_name(name.substr(0, dot) + ".h5");
  const std::string digits = name.substr(dot + 2, name.size() - 3 - (dot + 2));
  if (step < 0 || digits.empty() || digits.size() > 9) return {-1, -1};
  for (char c : digits)
    if (c < '0' || c > '9') return {-1, -1};
  return {step, std::stoi(digits)};
}

void write_rank_frame_file(const std::string& path, const OutputFrame& frame, int rank, int ranks) {
  if (!frame.grid && !frame.grid_fields.empty())
    throw std::invalid_argument("output frame: grid fields without a grid");
  h5::Handle file = h5::create_file(path);
  h5::set_attr_string(file.id(), "format", kRankFormat, path);
  h5::set_attr_doubles(file.id(), "time", {frame.time}, path);
  h5::set_attr_int64s(file.id(), "step", {frame.step}, path);
  h5::set_attr_int64s(file.id(), "rank", {rank}, path);
  h5::set_attr_int64s(file.id(), "ranks", {ranks}, path);
  if (frame.grid) {
    h5::Handle g = write_grid_geometry(file.id(), *frame.grid, path);
    std::map<int, h5::Handle> mats;
    for (const GridFieldArray& f : frame.grid_fields) {
      check_label(f.data.label, "grid field");
      check_components(f.data);
      const SavedGridField s = locate(f, *frame.grid);  // the whole field's extent (checks the size)
      auto it = mats.find(f.data.material);
      if (it == mats.end())
        it = mats.emplace(f.data.material, h5::create_group(g.id(), mat_group(f.data.material), path)).first;
      const std::string where = path + ":/grid/" + mat_group(f.data.material) + "/" + f.data.label;
      if (h5::exists(it->second.id(), f.data.label))
        throw std::invalid_argument("output frame: two grid fields '" + f.data.label + "' of material " +
                                    std::to_string(f.data.material));
      h5::Handle lg = h5::create_group(it->second.id(), f.data.label, where);
      h5::set_attr_string(lg.id(), "centering", location_name(f.location), where);
      h5::set_attr_int64s(lg.id(), "first_index", to_i64(s.first_index), where);
      h5::set_attr_int64s(lg.id(), "extent", to_i64(s.extent), where);
      h5::set_attr_int64s(lg.id(), "components", {f.data.components}, where);
      std::vector<ArrayBox> pieces = f.pieces;
      if (!f.partial) pieces = rank == 0 ? std::vector<ArrayBox>{{IntVec3::Zero(), s.extent}} : std::vector<ArrayBox>{};
      const int nc = f.data.components;
      for (std::size_t n = 0; n < pieces.size(); ++n) {
        const ArrayBox& b = pieces[n];
        if (b.empty()) continue;
        if (!inside(b.lo, b.hi - b.lo, s.extent))
          throw std::invalid_argument("output frame: a piece of '" + f.data.label + "' lies outside the field");
        std::vector<double> block;
        block.reserve(static_cast<std::size_t>(b.count()) * nc);
        for (int k = b.lo[2]; k < b.hi[2]; ++k)
          for (int j = b.lo[1]; j < b.hi[1]; ++j) {
            const std::size_t row = (std::size_t(k) * s.extent[1] + j) * s.extent[0];
            block.insert(block.end(), f.data.values.begin() + long((row + b.lo[0]) * nc),
                         f.data.values.begin() + long((row + b.hi[0]) * nc));
          }
        const IntVec3 e = b.hi - b.lo;
        std::vector<hsize_t> dims = {hsize_t(e[2]), hsize_t(e[1]), hsize_t(e[0])};
        if (nc > 1) dims.push_back(hsize_t(nc));
        const std::string name = "b" + std::to_string(n);
        h5::write_doubles(lg.id(), name, dims, block.data(), where);
        h5::Handle set(H5Dopen2(lg.id(), name.c_str(), H5P_DEFAULT), h5::Handle::Kind::Dataset);
        h5::set_attr_int64s(set.id(), "offset", to_i64(b.lo), where + "/" + name);
      }
    }
  }
  write_particles(file.id(), frame, path);
  h5::flush(file, path);
}

void write_frame_index_file(const std::string& path, int step, double time, int ranks) {
  h5::Handle file = h5::create_file(path);
  h5::set_attr_string(file.id(), "format", kFrameIndexFormat, path);
  h5::set_attr_doubles(file.id(), "time", {time}, path);
  h5::set_attr_int64s(file.id(), "step", {step}, path);
  h5::set_attr_int64s(file.id(), "ranks", {ranks}, path);
  h5::flush(file, path);
}

bool is_frame_index_file(const std::string& path) {
  h5::Handle file = h5::open_file_readonly(path);
  return h5::has_attr(file.id(), "format") && h5::attr_string(file.id(), "format", path) == kFrameIndexFormat;
}

std::vector<std::string> rank_files_of_index(const std::string& index_path) {
  h5::Handle file = h5::open_file_readonly(index_path);
  if (!h5::has_attr(file.id(), "format") || h5::attr_string(file.id(), "format", index_path) != kFrameIndexFormat)
    throw RuntimeFailure(index_path + ": not a Tephra frame index");
  const int step = static_cast<int>(one_int(file.id(), "step", index_path));
  const long long ranks = one_int(file.id(), "ranks", index_path);
  if (ranks < 1 || ranks > 1000000) throw RuntimeFailure(index_path + ": bad rank count " + std::to_string(ranks));
  std::vector<std::string> out;
  const fs::path folder = fs::path(index_path).parent_path();
  for (int r = 0; r < ranks; ++r) {
    const std::string p = (folder / rank_frame_file_name(step, r)).string();
    std::error_code ec;
    if (!fs::is_regular_file(p, ec))
      throw RuntimeFailure(p + ": rank file missing (rank " + std::to_string(r) + " of " + std::to_string(ranks) +
                           " of the frame indexed by " + index_path + ")");
    out.push_back(p);
  }
  return out;
}

SavedFrame read_rank_file_layout(const std::string& path) {
  const RankFile rf = read_rank(path, false, "");
  SavedFrame out;
  out.step = rf.step;
  out.time = rf.time;
  out.has_grid = rf.has_grid;
  out.grid = rf.grid;
  for (const FieldGroup& fg : rf.fields)
    for (const Piece& p : fg.pieces) {
      SavedGridField s = fg.whole;
      s.first_index = fg.whole.first_index + p.offset;
      s.extent = p.extent;
      s.dataset = p.dataset;
      out.grid_fields.push_back(std::move(s));
    }
  out.particles = rf.particles;
  return out;
}

SavedFrame read_rank_frames(const std::string& index_path, bool with_values, const std::string& only_label) {
  const std::vector<std::string> files = rank_files_of_index(index_path);
  SavedFrame out;
  std::map<std::pair<int, std::string>, SavedGridField> fields;  // (material, label): the single file's order
  std::map<int, SavedParticles> particles;
  for (std::size_t r = 0; r < files.size(); ++r) {
    RankFile rf = read_rank(files[r], with_values, only_label);
    if (rf.rank != int(r) || rf.ranks != int(files.size()))
      throw RuntimeFailure(files[r] + ": holds rank " + std::to_string(rf.rank) + " of " + std::to_string(rf.ranks) +
                           ", the index " + index_path + " expects rank " + std::to_string(r) + " of " +
                           std::to_string(files.size()));
    if (r == 0) {
      out.step = rf.step;
      out.time = rf.time;
      out.has_grid = rf.has_grid;
      out.grid = rf.grid;
    } else if (rf.step != out.step || rf.time != out.time) {
      throw RuntimeFailure(files[r] + ": step/time differ from rank 0's file " + files[0]);
    }
    for (FieldGroup& fg : rf.fields) {
      const FieldArray& d = fg.whole.field.data;
      auto key = std::make_pair(d.material, d.label);
      auto it = fields.find(key);
      if (it == fields.end()) {
        it = fields.emplace(key, fg.whole).first;
        if (with_values && (only_label.empty() || only_label == d.label))
          it->second.field.data.values.assign(static_cast<std::size_t>(product(fg.whole.extent)) * d.components, 0.0);
      } else if (it->second.extent != fg.whole.extent || it->second.first_index != fg.whole.first_index ||
                 it->second.field.data.components != d.components || it->second.field.location != fg.whole.field.location) {
        throw RuntimeFailure(files[r] + ": field '" + d.label + "' of material " + std::to_string(d.material) +
                             " has another layout than in " + files[0]);
      }
      std::vector<double>& whole = it->second.field.data.values;
      const IntVec3 n = fg.whole.extent;
      const int nc = d.components;
      for (const Piece& p : fg.pieces) {
        if (p.values.empty() || whole.empty()) continue;
        const double* v = p.values.data();
        for (int k = p.offset[2]; k < p.offset[2] + p.extent[2]; ++k)
          for (int j = p.offset[1]; j < p.offset[1] + p.extent[1]; ++j) {
            const std::size_t at = ((std::size_t(k) * n[1] + j) * n[0] + p.offset[0]) * nc;
            const std::size_t len = std::size_t(p.extent[0]) * nc;
            std::copy(v, v + len, whole.begin() + long(at));
            v += len;
          }
      }
    }
    for (SavedParticles& sp : rf.particles) {
      auto it = particles.find(sp.block.material);
      if (it == particles.end()) {
        particles.emplace(sp.block.material, std::move(sp));
        continue;
      }
      SavedParticles& m = it->second;
      if (m.block.fields.size() != sp.block.fields.size())
        throw RuntimeFailure(files[r] + ": particles of material " + std::to_string(sp.block.material) +
                             " carry other fields than in " + files[0]);
      m.count += sp.count;
      m.block.position.insert(m.block.position.end(), sp.block.position.begin(), sp.block.position.end());
      m.block.id.insert(m.block.id.end(), sp.block.id.begin(), sp.block.id.end());
      for (std::size_t f = 0; f < sp.block.fields.size(); ++f) {
        if (m.block.fields[f].label != sp.block.fields[f].label)
          throw RuntimeFailure(files[r] + ": particle field '" + sp.block.fields[f].label + "' where " + files[0] +
                               " has '" + m.block.fields[f].label + "'");
        std::vector<double>& to = m.block.fields[f].values;
        to.insert(to.end(), sp.block.fields[f].values.begin(), sp.block.fields[f].values.end());
      }
    }
  }
  for (auto& [key, f] : fields) out.grid_fields.push_back(std::move(f));
  for (auto& [m, p] : particles) {
    sort_by_id(p);
    out.particles.push_back(std::move(p));
  }
  return out;
}

}  // namespace tephra
