#include "core/io/FrameFile.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/io/detail/FrameParts.h"
#include "core/io/detail/H5.h"
#include "core/io/RankFrameFile.h"

namespace tephra {
namespace {
const char* kFormat = "tephra-frame-1";
}  // namespace

// Shared with the per-rank frame files (core/io/detail/FrameParts.h).
namespace frame_detail {

long long product(const IntVec3& n) { return 1LL * n[0] * n[1] * n[2]; }

void check_label(const std::string& label, const std::string& what) {
  if (label.empty() || label.find('/') != std::string::npos || label == "." || label == "..")
    throw std::invalid_argument("output frame: invalid " + what + " label '" + label + "'");
}

void check_components(const FieldArray& f) {
  if (f.components != 1 && f.components != 3 && f.components != 9)
    throw std::invalid_argument("output frame: field '" + f.label + "' has " +
                                std::to_string(f.components) + " components (expected 1, 3 or 9)");
}

// The stored extent of a grid field, from its size: either the interior
// (cells, or cells+1 nodes) or the interior plus the extra cells on each side.
SavedGridField locate(const GridFieldArray& g, const Grid& grid) {
  const long long n = static_cast<long long>(g.data.values.size()) / g.data.components;
  const IntVec3 node = location_stagger(g.location);
  SavedGridField s;
  s.field = g;
  if (n * g.data.components == static_cast<long long>(g.data.values.size())) {
    if (n == product(grid.cells + node)) {
      s.first_index = IntVec3::Zero();
      s.extent = grid.cells + node;
      return s;
    }
    const IntVec3 with_extra = grid.cells + 2 * grid.extra_cells + node;
    if (n == product(with_extra)) {
      s.first_index = -grid.extra_cells;
      s.extent = with_extra;
      return s;
    }
  }
  throw std::invalid_argument("output frame: grid field '" + g.data.label + "' (material " +
                              std::to_string(g.data.material) + ") has " +
                              std::to_string(g.data.values.size()) +
                              " values, which fits neither the interior nor the interior plus "
                              "extra cells");
}

std::vector<long long> to_i64(const IntVec3& v) { return {v[0], v[1], v[2]}; }
IntVec3 to_ivec(const std::vector<long long>& v, const std::string& where) {
  if (v.size() != 3) throw RuntimeFailure(where + ": expected a 3-vector attribute");
  return IntVec3(int(v[0]), int(v[1]), int(v[2]));
}
Vec3 to_vec(const std::vector<double>& v, const std::string& where) {
  if (v.size() != 3) throw RuntimeFailure(where + ": expected a 3-vector attribute");
  return Vec3(v[0], v[1], v[2]);
}

std::string mat_group(int m) { return "mat" + std::to_string(m); }

int parse_mat_group(const std::string& name, const std::string& where) {
  int m = 0;
  char extra = 0;
  if (std::sscanf(name.c_str(), "mat%d%c", &m, &extra) != 1)
    throw RuntimeFailure(where + ": unexpected group '" + name + "' (expected mat<M>)");
  return m;
}

// Components of a dataset from its rank: grid fields carry a 4th dimension
// and particle fields a 2nd one only when they are vectors or tensors.
int components_from(const std::vector<hsize_t>& dims, size_t scalar_rank) {
  return dims.size() == scalar_rank + 1 ? int(dims.back()) : 1;
}

h5::Handle write_grid_geometry(hid_t file, const Grid& grid, const std::string& path) {
  h5::Handle g = h5::create_group(file, "grid", path);
  h5::set_attr_doubles(g.id(), "lower", {grid.lower[0], grid.lower[1], grid.lower[2]}, path);
  h5::set_attr_doubles(g.id(), "dx", {grid.dx[0], grid.dx[1], grid.dx[2]}, path);
  h5::set_attr_int64s(g.id(), "cells", to_i64(grid.cells), path);
  h5::set_attr_int64s(g.id(), "extra_cells", to_i64(grid.extra_cells), path);
  return g;
}

void read_grid_geometry(hid_t g, Grid& grid, const std::string& path) {
  grid.lower = to_vec(h5::attr_doubles(g, "lower", path), path);
  grid.dx = to_vec(h5::attr_doubles(g, "dx", path), path);
  grid.cells = to_ivec(h5::attr_int64s(g, "cells", path), path);
  grid.extra_cells = to_ivec(h5::attr_int64s(g, "extra_cells", path), path);
  grid.upper = grid.lower + grid.dx.cwiseProduct(grid.cells.cast<double>());
}

GridLocation parse_location(const std::string& centering, const std::string& where) {
  for (GridLocation l : {GridLocation::Cell, GridLocation::Node, GridLocation::FaceX, GridLocation::FaceY,
                         GridLocation::FaceZ})
    if (centering == location_name(l)) return l;
  throw RuntimeFailure(where + ": unknown centering '" + centering + "'");
}

void write_grid(hid_t file, const OutputFrame& frame, const std::string& path) {
  const Grid& grid = *frame.grid;
  h5::Handle g = write_grid_geometry(file, grid, path);
  std::map<int, h5::Handle> mats;
  for (const GridFieldArray& f : frame.grid_fields) {
    check_label(f.data.label, "grid field");
    check_components(f.data);
    SavedGridField s = locate(f, grid);
    auto it = mats.find(f.data.material);
    if (it == mats.end())
      it = mats.emplace(f.data.material, h5::create_group(g.id(), mat_group(f.data.material), path))
               .first;
    std::vector<hsize_t> dims = {hsize_t(s.extent[2]), hsize_t(s.extent[1]), hsize_t(s.extent[0])};
    if (f.data.components > 1) dims.push_back(hsize_t(f.data.components));
    h5::write_doubles(it->second.id(), f.data.label, dims, f.data.values.data(), path);
    h5::Handle set(H5Dopen2(it->second.id(), f.data.label.c_str(), H5P_DEFAULT),
                   h5::Handle::Kind::Dataset);
    h5::set_attr_string(set.id(), "centering",
                        location_name(f.location), path);
    h5::set_attr_int64s(set.id(), "first_index", to_i64(s.first_index), path);
  }
}

void write_particles(hid_t file, const OutputFrame& frame, const std::string& path) {
  h5::Handle root = h5::create_group(file, "particles", path);
  for (const ParticleBlock& b : frame.particles) {
    const size_t n = b.position.size();
    if (b.id.size() != n)
      throw std::invalid_argument("output frame: material " + std::to_string(b.material) +
                                  " has " + std::to_string(n) + " positions but " +
                                  std::to_string(b.id.size()) + " particle ids");
    if (h5::exists(root.id(), mat_group(b.material)))
      throw std::invalid_argument("output frame: two particle blocks for material " +
                                  std::to_string(b.material));
    h5::Handle m = h5::create_group(root.id(), mat_group(b.material), path);
    // Vec3 is three contiguous doubles, so a vector of them is an [n][3] array.
    std::vector<double> xyz(3 * n);
    for (size_t p = 0; p < n; ++p)
      for (int c = 0; c < 3; ++c) xyz[3 * p + c] = b.position[p][c];
    h5::write_doubles(m.id(), "position", {hsize_t(n), 3}, xyz.data(), path);
    h5::write_int64s(m.id(), "particleID", {hsize_t(n)}, b.id.data(), path);
    for (const FieldArray& f : b.fields) {
      check_label(f.label, "particle field");
      check_components(f);
      if (f.label == "position" || f.label == "particleID")
        throw std::invalid_argument("output frame: particle field label '" + f.label +
                                    "' is reserved");
      if (f.values.size() != n * size_t(f.components))
        throw std::invalid_argument("output frame: particle field '" + f.label + "' of material " +
                                    std::to_string(b.material) + " has " +
                                    std::to_string(f.values.size()) + " values for " +
                                    std::to_string(n) + " particles x " +
                                    std::to_string(f.components) + " components");
      std::vector<hsize_t> dims = {hsize_t(n)};
      if (f.components > 1) dims.push_back(hsize_t(f.components));
      h5::write_doubles(m.id(), f.label, dims, f.values.data(), path);
    }
  }
}

void read_grid(hid_t file, SavedFrame& out, bool with_values, const std::string& only,
               const std::string& path) {
  h5::Handle g = h5::open_group(file, "grid", path);
  out.has_grid = true;
  read_grid_geometry(g.id(), out.grid, path);
  for (const std::string& mname : h5::children(g.id(), path)) {
    const int material = parse_mat_group(mname, path);
    h5::Handle m = h5::open_group(g.id(), mname, path);
    for (const std::string& label : h5::children(m.id(), path)) {
      const std::string where = path + ":/grid/" + mname + "/" + label;
      std::vector<hsize_t> dims = h5::dataset_dims(m.id(), label, path);
      if (dims.size() != 3 && dims.size() != 4)
        throw RuntimeFailure(where + ": expected a 3- or 4-dimensional dataset");
      h5::Handle set(H5Dopen2(m.id(), label.c_str(), H5P_DEFAULT), h5::Handle::Kind::Dataset);
      SavedGridField s;
      s.field.data.label = label;
      s.field.data.material = material;
      s.field.data.components = components_from(dims, 3);
      s.field.location = parse_location(h5::attr_string(set.id(), "centering", where), where);
      s.first_index = to_ivec(h5::attr_int64s(set.id(), "first_index", where), where);
      s.extent = IntVec3(int(dims[2]), int(dims[1]), int(dims[0]));
      if (with_values && (only.empty() || only == label))
        s.field.data.values = h5::read_doubles(m.id(), label, path);
      out.grid_fields.push_back(std::move(s));
    }
  }
  std::stable_sort(out.grid_fields.begin(), out.grid_fields.end(),
                   [](const SavedGridField& a, const SavedGridField& b) {
                     return a.field.data.material < b.field.data.material;
                   });
}

void read_particles(hid_t file, SavedFrame& out, bool with_values, const std::string& only,
                    const std::string& path) {
  h5::Handle root = h5::open_group(file, "particles", path);
  for (const std::string& mname : h5::children(root.id(), path)) {
    const std::string where = path + ":/particles/" + mname;
    h5::Handle m = h5::open_group(root.id(), mname, path);
    SavedParticles p;
    p.block.material = parse_mat_group(mname, path);
    std::vector<hsize_t> pdims = h5::dataset_dims(m.id(), "position", where);
    if (pdims.size() != 2 || pdims[1] != 3) throw RuntimeFailure(where + ": position is not [n][3]");
    p.count = static_cast<long long>(pdims[0]);
    std::vector<hsize_t> idims = h5::dataset_dims(m.id(), "particleID", where);
    if (idims.size() != 1 || idims[0] != pdims[0])
      throw RuntimeFailure(where + ": particleID is not [n]");
    const std::vector<std::string> labels = h5::children(m.id(), path);
    const bool holds_only =
        only.empty() || only == "p.x" || std::find(labels.begin(), labels.end(), only) != labels.end();
    if (with_values && holds_only) {
      std::vector<double> xyz = h5::read_doubles(m.id(), "position", where);
      p.block.position.resize(p.count);
      for (long long i = 0; i < p.count; ++i)
        p.block.position[i] = Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
      p.block.id = h5::read_int64s(m.id(), "particleID", where);
    }
    for (const std::string& label : labels) {
      if (label == "position" || label == "particleID") continue;
      std::vector<hsize_t> dims = h5::dataset_dims(m.id(), label, where);
      if (dims.empty() || dims.size() > 2 || dims[0] != pdims[0])
        throw RuntimeFailure(where + "/" + label + ": expected [n] or [n][ncomp]");
      FieldArray f;
      f.label = label;
      f.material = p.block.material;
      f.components = components_from(dims, 1);
      if (with_values && (only.empty() || only == label))
        f.values = h5::read_doubles(m.id(), label, where);
      p.block.fields.push_back(std::move(f));
    }
    out.particles.push_back(std::move(p));
  }
  std::sort(out.particles.begin(), out.particles.end(),
            [](const SavedParticles& a, const SavedParticles& b) {
              return a.block.material < b.block.material;
            });
}

}  // namespace frame_detail

using namespace frame_detail;

std::string frame_file_name(int step) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "t%05d.h5", step);
  return buf;
}

int parse_frame_file_name(const std::string& name) {
  // t + at least five digits + .h5
  if (name.size() < 9 || name[0] != 't' || name.compare(name.size() - 3, 3, ".h5") != 0) return -1;
  const std::string digits = name.substr(1, name.size() - 4);
  if (digits.size() < 5 || digits.size() > 9) return -1;
  for (char c : digits)
    if (c < '0' || c > '9') return -1;
  return std::stoi(digits);
}

std::map<int, std::string> list_frame_files(const std::string& output_dir) {
  std::map<int, std::string> out;
  const std::filesystem::path frames = std::filesystem::path(output_dir) / "frames";
  std::error_code ec;
  if (!std::filesystem::is_directory(frames, ec)) return out;
  for (const auto& e : std::filesystem::directory_iterator(frames)) {
    const int step = parse_frame_file_name(e.path().filename().string());
    if (step >= 0 && e.is_regular_file()) out[step] = e.path().string();
  }
  return out;
}

void write_frame_file(const std::string& path, const OutputFrame& frame) {
  if (!frame.grid && !frame.grid_fields.empty())
    throw std::invalid_argument("output frame: grid fields without a grid");
  h5::Handle file = h5::create_file(path);
  h5::set_attr_doubles(file.id(), "time", {frame.time}, path);
  h5::set_attr_int64s(file.id(), "step", {frame.step}, path);
  h5::set_attr_string(file.id(), "format", kFormat, path);
  if (frame.grid) write_grid(file.id(), frame, path);
  write_particles(file.id(), frame, path);
  h5::flush(file, path);
}

SavedFrame read_frame_file(const std::string& path, bool with_values,
                           const std::string& only_label) {
  h5::Handle file = h5::open_file_readonly(path);
  const std::string format = h5::has_attr(file.id(), "format") ? h5::attr_string(file.id(), "format", path) : "";
  if (format == kFrameIndexFormat) {  // a multi-rank frame: the rank files merged
    file.close();
    return read_rank_frames(path, with_values, only_label);
  }
  if (format != kFormat)
    throw RuntimeFailure(path + ": not a Tephra frame file (format attribute missing or unknown)");
  SavedFrame out;
  std::vector<double> t = h5::attr_doubles(file.id(), "time", path);
  std::vector<long long> s = h5::attr_int64s(file.id(), "step", path);
  if (t.size() != 1 || s.size() != 1) throw RuntimeFailure(path + ": bad time/step attributes");
  out.time = t[0];
  out.step = static_cast<int>(s[0]);
  if (h5::exists(file.id(), "grid")) read_grid(file.id(), out, with_values, only_label, path);
  if (h5::exists(file.id(), "particles")) read_particles(file.id(), out, with_values, only_label, path);
  return out;
}

}  // namespace tephra
