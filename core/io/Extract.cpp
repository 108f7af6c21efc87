// `tephra extract`: a saved field as CSV (see Extract.h for the columns).
// When no --material is given and the label is saved for more than one
// material, a `material` column follows `time` so that rows stay unambiguous.
#include "core/io/Extract.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "core/base/Errors.h"
#include "core/io/FrameFile.h"
#include "core/io/Reductions.h"

namespace tephra {
namespace fs = std::filesystem;
namespace {

// Particle positions are saved as the dataset `position`; users ask for p.x.
const char* kParticlePosition = "p.x";

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

std::string join(const std::set<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// Column names: LABEL; LABEL_x,_y,_z; LABEL_xx,...,_zz (row-major); other
// counts LABEL_0, LABEL_1, ...
std::string columns(const std::string& label, int components) {
  static const char* vec[] = {"x", "y", "z"};
  std::string out;
  if (components == 1) return label;
  for (int c = 0; c < components; ++c) {
    std::string suffix = components == 3   ? vec[c]
                         : components == 9 ? std::string(vec[c / 3]) + vec[c % 3]
                                           : std::to_string(c);
    out += (c ? "," : "") + label + "_" + suffix;
  }
  return out;
}

void print_values(std::ostream& out, const std::vector<double>& v, size_t first, int n) {
  for (int c = 0; c < n; ++c) out << ',' << num(v[first + c]);
}

void extract_reduction(const ExtractRequest& r, std::ostream& out) {
  if (r.material)
    throw UsageError("'" + r.label + "' is a reduction over all materials; drop --material");
  if (r.when == ExtractRequest::When::Step)
    throw UsageError("'" + r.label + "' is saved by time, not by step; use --time");
  const std::vector<ReductionRow> rows = read_reduction_file(reduction_file(r.dir, r.label));
  if (rows.empty()) throw UsageError("'" + r.label + "' has no saved rows yet");
  std::vector<const ReductionRow*> chosen;
  if (r.when == ExtractRequest::When::AllTimes) {
    for (const ReductionRow& row : rows) chosen.push_back(&row);
  } else if (r.when == ExtractRequest::When::Last) {
    chosen.push_back(&rows.back());
  } else {  // nearest saved time; the earlier one on a tie
    const ReductionRow* best = &rows.front();
    for (const ReductionRow& row : rows)
      if (std::abs(row.time - r.time) < std::abs(best->time - r.time)) best = &row;
    chosen.push_back(best);
  }
  const int n = static_cast<int>(rows.front().values.size());
  out << "time," << columns(r.label, n) << '\n';
  for (const ReductionRow* row : chosen) {
    out << num(row->time);
    print_values(out, row->values, 0, n);
    out << '\n';
  }
}

// Every label saved anywhere (frames and reductions), for error messages.
std::set<std::string> saved_labels(const std::vector<SavedFrame>& layouts,
                                   const std::vector<std::string>& reductions) {
  std::set<std::string> all(reductions.begin(), reductions.end());
  for (const SavedFrame& f : layouts) {
    for (const SavedGridField& g : f.grid_fields) all.insert(g.field.data.label);
    for (const SavedParticles& p : f.particles) {
      all.insert(kParticlePosition);
      for (const FieldArray& a : p.block.fields) all.insert(a.label);
    }
  }
  return all;
}

bool frame_has(const SavedFrame& f, const std::string& label, std::optional<int> material,
               std::set<int>* materials) {
  bool found = false;
  auto note = [&](int m) {
    if (materials) materials->insert(m);
    if (!material || *material == m) found = true;
  };
  for (const SavedGridField& g : f.grid_fields)
    if (g.field.data.label == label) note(g.field.data.material);
  for (const SavedParticles& p : f.particles) {
    if (label == kParticlePosition) note(p.block.material);
    for (const FieldArray& a : p.block.fields)
      if (a.label == label) note(p.block.material);
  }
  return found;
}

// Frames (by index into `steps`) that the request selects.
std::vector<size_t> select_frames(const ExtractRequest& r, const std::vector<int>& steps,
                                  const std::vector<SavedFrame>& layouts) {
  std::vector<size_t> holding;
  for (size_t n = 0; n < layouts.size(); ++n)
    if (frame_has(layouts[n], r.label, r.material, nullptr)) holding.push_back(n);
  if (holding.empty()) {
    std::set<int> mats;
    for (const SavedFrame& f : layouts) frame_has(f, r.label, std::nullopt, &mats);
    std::set<std::string> names;
    for (int m : mats) names.insert(std::to_string(m));
    throw UsageError("'" + r.label + "' is not saved for material " + std::to_string(*r.material) +
                     "; saved for material(s): " + join(names));
  }
  switch (r.when) {
    case ExtractRequest::When::AllTimes: return holding;
    case ExtractRequest::When::Last: return {holding.back()};
    case ExtractRequest::When::Step: {
      for (size_t n : holding)
        if (steps[n] == r.step) return {n};
      std::set<std::string> saved;
      for (size_t n : holding) saved.insert(std::to_string(steps[n]));
      throw UsageError("step " + std::to_string(r.step) + " of '" + r.label +
                       "' is not saved; saved steps: " + join(saved));
    }
    case ExtractRequest::When::Time: {
      size_t best = holding.front();
      for (size_t n : holding)
        if (std::abs(layouts[n].time - r.time) < std::abs(layouts[best].time - r.time)) best = n;
      return {best};
    }
  }
  return {};
}

// The (i,j,k) a request selects among the stored extent of a grid field, in
// output order: all of them, the one holding a point, or those a line crosses.
std::vector<IntVec3> selected_indices(const ExtractRequest& r, const Grid& grid, const SavedGridField& g) {
  const IntVec3 stagger = location_stagger(g.field.location);  // 1: values on the cell boundaries
  const IntVec3 lo = g.first_index, hi = g.first_index + g.extent;  // hi exclusive
  auto index_of = [&](const Vec3& x) {
    IntVec3 ijk;
    for (int d = 0; d < 3; ++d) {
      const double s = (x[d] - grid.lower[d]) / grid.dx[d];
      ijk[d] = static_cast<int>(stagger[d] ? std::lround(s) : std::floor(s));
    }
    return ijk;
  };
  auto stored = [&](const IntVec3& ijk) {
    return (ijk.array() >= lo.array()).all() && (ijk.array() < hi.array()).all();
  };
  std::vector<IntVec3> out;
  if (r.point) {
    const IntVec3 ijk = index_of(*r.point);
    if (stored(ijk)) out.push_back(ijk);
  } else if (r.line) {
    // Sample the segment at a quarter of the smallest spacing: every cell
    // (node) it passes through is hit at least once; keep first visits.
    const Vec3 a = r.line->first, b = r.line->second;
    const double h = grid.dx.minCoeff() / 4.0;
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / h)));
    for (int s = 0; s <= n; ++s) {
      const IntVec3 ijk = index_of(a + (b - a) * (double(s) / n));
      if (stored(ijk) && (out.empty() || out.back() != ijk) &&
          std::find(out.begin(), out.end(), ijk) == out.end())
        out.push_back(ijk);
    }
  } else {
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i) out.emplace_back(i, j, k);
  }
  return out;
}

void extract_grid(const ExtractRequest& r, const SavedFrame& f, const SavedGridField& g, bool material_column,
                  std::ostream& out) {
  const FieldArray& d = g.field.data;
  const int nc = d.components;
  for (const IntVec3& ijk : selected_indices(r, f.grid, g)) {
    const IntVec3 o = ijk - g.first_index;
    const size_t at = (size_t(o[2]) * g.extent[1] + o[1]) * g.extent[0] + o[0];
    const Vec3 x = f.grid.cell_center(ijk[0], ijk[1], ijk[2]) -
                   0.5 * f.grid.dx.cwiseProduct(location_stagger(g.field.location).cast<double>());
    out << num(f.time);
    if (material_column) out << ',' << d.material;
    out << ',' << ijk[0] << ',' << ijk[1] << ',' << ijk[2] << ',' << num(x[0]) << ',' << num(x[1]) << ','
        << num(x[2]);
    print_values(out, d.values, at * nc, nc);
    out << '\n';
  }
}

// Particle indices a request selects, in output order.
std::vector<long long> selected_particles(const ExtractRequest& r, const SavedFrame& f, const SavedParticles& p) {
  std::vector<long long> out;
  const auto& x = p.block.position;
  if (r.point) {
    long long best = -1;
    double best_d = 0.0;
    for (long long n = 0; n < p.count; ++n) {
      const double d = (x[n] - *r.point).squaredNorm();
      if (best < 0 || d < best_d) best = n, best_d = d;
    }
    if (best >= 0) out.push_back(best);
  } else if (r.line) {
    const Vec3 a = r.line->first, b = r.line->second;
    const double len2 = (b - a).squaredNorm();
    const double reach = 0.5 * f.grid.dx.maxCoeff();
    std::vector<std::pair<double, long long>> along;
    for (long long n = 0; n < p.count; ++n) {
      const double s = len2 > 0 ? std::clamp((x[n] - a).dot(b - a) / len2, 0.0, 1.0) : 0.0;
      if ((x[n] - (a + s * (b - a))).norm() <= reach) along.push_back({s, n});
    }
    std::stable_sort(along.begin(), along.end());
    for (const auto& [s, n] : along) out.push_back(n);
  } else {
    for (long long n = 0; n < p.count; ++n) out.push_back(n);
  }
  return out;
}

void extract_particles(const ExtractRequest& r, const SavedFrame& f, const SavedParticles& p,
                       const std::string& label, bool material_column, std::ostream& out) {
  const std::vector<double>* values = nullptr;
  std::vector<double> xyz;
  int nc = 3;
  if (label == kParticlePosition) {
    for (const Vec3& x : p.block.position) xyz.insert(xyz.end(), {x[0], x[1], x[2]});
    values = &xyz;
  } else {
    for (const FieldArray& a : p.block.fields)
      if (a.label == label) {
        values = &a.values;
        nc = a.components;
      }
  }
  if (!values) return;
  for (long long n : selected_particles(r, f, p)) {
    const Vec3& x = p.block.position[n];
    out << num(f.time);
    if (material_column) out << ',' << p.block.material;
    out << ',' << p.block.id[n] << ',' << num(x[0]) << ',' << num(x[1]) << ',' << num(x[2]);
    print_values(out, *values, size_t(n) * nc, nc);
    out << '\n';
  }
}

}  // namespace

void extract_csv(const ExtractRequest& r, std::ostream& out) {
  std::error_code ec;
  if (!fs::is_directory(r.dir, ec)) throw UsageError("'" + r.dir + "' is not an output directory");
  const std::vector<std::string> reductions = read_reduction_labels(r.dir);
  if (std::find(reductions.begin(), reductions.end(), r.label) != reductions.end()) {
    if (r.point || r.line) throw UsageError("'" + r.label + "' is a reduction: --point and --line do not apply");
    return extract_reduction(r, out);
  }

  std::vector<int> steps;
  std::vector<std::string> paths;
  std::vector<SavedFrame> layouts;
  for (const auto& [step, path] : list_frame_files(r.dir)) {
    steps.push_back(step);
    paths.push_back(path);
    layouts.push_back(read_frame_file(path, false));
  }
  std::set<int> materials;
  bool known = false;
  for (const SavedFrame& f : layouts) known |= frame_has(f, r.label, std::nullopt, &materials);
  if (!known) {
    const std::set<std::string> all = saved_labels(layouts, reductions);
    throw UsageError("no saved variable '" + r.label + "' in " + r.dir + "; saved: " +
                     (all.empty() ? std::string("(nothing)") : join(all)));
  }
  const std::vector<size_t> chosen = select_frames(r, steps, layouts);
  const bool material_column = !r.material && materials.size() > 1;

  // The header comes from the first selected frame; a label keeps its kind
  // (grid or particle) and component count across a run.
  bool header = false;
  for (size_t n : chosen) {
    const SavedFrame f = read_frame_file(paths[n], true, r.label);
    for (const SavedGridField& g : f.grid_fields) {
      if (g.field.data.label != r.label || (r.material && *r.material != g.field.data.material))
        continue;
      if (!header) {
        out << "time," << (material_column ? "material," : "") << "i,j,k,x,y,z,"
            << columns(r.label, g.field.data.components) << '\n';
        header = true;
      }
      extract_grid(r, f, g, material_column, out);
    }
    for (const SavedParticles& p : f.particles) {
      if (r.material && *r.material != p.block.material) continue;
      int nc = 0;
      if (r.label == kParticlePosition) nc = 3;
      for (const FieldArray& a : p.block.fields)
        if (a.label == r.label) nc = a.components;
      if (nc == 0) continue;
      if (!header) {
        out << "time," << (material_column ? "material," : "") << "particle_id,x,y,z,"
            << columns(r.label, nc) << '\n';
        header = true;
      }
      extract_particles(r, f, p, r.label, material_column, out);
    }
  }
}

}  // namespace tephra
