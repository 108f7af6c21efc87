#include "core/geometry/ParticleFile.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

// Columns of one <var>: how many numbers and where they go.
enum class Column { Volume, Temperature, Color, Velocity };

struct VarSpec {
  Column column;
  int width;
};

VarSpec parse_var(const DeckNode& var) {
  const std::string& v = var.text;
  if (v == "p.volume") return {Column::Volume, 1};
  if (v == "p.temperature") return {Column::Temperature, 1};
  if (v == "p.color") return {Column::Color, 1};
  if (v == "p.velocity") return {Column::Velocity, 3};
  if (v == "p.externalforce" || v == "p.fiberdir" || v == "p.rvec1" || v == "p.rvec2" || v == "p.rvec3")
    var.missing_feature("particle file column '" + v + "' (implemented: p.volume, p.temperature, p.color, p.velocity)");
  var.fail("unknown particle file column '" + v +
           "' (Vaango's: p.volume, p.temperature, p.color, p.velocity, p.externalforce, p.fiberdir, p.rvec1, "
           "p.rvec2, p.rvec3)");
}

[[noreturn]] void row_error(const std::string& file, int line, const std::string& message) {
  throw DeckError(SourceLocation{file, line, "geom_object/file"}, message);
}

// Parses the numbers of one line; false for a blank or comment line.
bool read_numbers(const std::string& text, const std::string& file, int line, std::vector<double>& out) {
  out.clear();
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    if (out.empty() && tok[0] == '#') return false;
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(tok, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != tok.size()) row_error(file, line, "'" + tok + "' is not a number");
    if (!std::isfinite(v)) row_error(file, line, "non-finite value '" + tok + "'");
    out.push_back(v);
  }
  return !out.empty();
}

void read_one_file(const std::string& path, bool header, const std::vector<VarSpec>& vars, int row_width,
                   ParticleFileData& d) {
  std::ifstream in(path);
  std::string text;
  std::vector<double> nums;
  int line = 0;
  bool header_seen = !header;
  while (std::getline(in, text)) {
    ++line;
    if (!read_numbers(text, path, line, nums)) continue;
    if (!header_seen) {  // pfs bounding box: xmin ymin zmin xmax ymax zmax
      if (nums.size() != 6)
        row_error(path, line, "the first line of a pfs file (usePFS) holds the bounding box, 6 numbers; found " +
                                  std::to_string(nums.size()));
      header_seen = true;
      continue;
    }
    if (int(nums.size()) != row_width)
      row_error(path, line, "row has " + std::to_string(nums.size()) + " numbers, expected " +
                                std::to_string(row_width) + " (x y z and the <var> columns)");
    d.x.emplace_back(nums[0], nums[1], nums[2]);
    d.file_index.push_back(int(d.files.size()));
    d.line.push_back(line);
    std::size_t k = 3;
    for (const VarSpec& v : vars) {
      switch (v.column) {
        case Column::Volume:
          if (!(nums[k] > 0.0)) row_error(path, line, "p.volume must be > 0");
          d.volume.push_back(nums[k]);
          break;
        case Column::Temperature: d.temperature.push_back(nums[k]); break;
        case Column::Color: d.color.push_back(nums[k]); break;
        case Column::Velocity: d.velocity.emplace_back(nums[k], nums[k + 1], nums[k + 2]); break;
      }
      k += std::size_t(v.width);
    }
  }
  d.files.push_back(path);
}

}  // namespace

std::shared_ptr<const ParticleFileData> read_particle_file(const DeckNode& node) {
  const DeckNode& name = node.require_child("name");
  std::vector<VarSpec> vars;
  int row_width = 3;
  for (const DeckNode& c : node.children) {
    if (c.name == "var") {
      vars.push_back(parse_var(c));
      for (std::size_t i = 0; i + 1 < vars.size(); ++i)
        if (vars[i].column == vars.back().column) c.fail("particle file column '" + c.text + "' listed twice");
      row_width += vars.back().width;
    } else if (c.name == "format") {
      if (c.text == "bin" || c.text == "lsb" || c.text == "msb")
        c.missing_feature("binary particle files (<format>" + c.text + "); text is implemented");
      if (c.text != "text") c.fail("particle file <format> must be text, bin, lsb or msb, not '" + c.text + "'");
    } else if (c.name != "name" && c.name != "usePFS") {
      c.fail("unknown element <" + c.name + "> in <file> (expected name, var, format, usePFS)");
    }
  }
  const bool pfs = node.child("usePFS") ? node.child("usePFS")->as_bool() : true;  // Vaango's default
  std::filesystem::path path(name.text);
  if (path.is_relative() && !node.file.empty()) path = std::filesystem::path(node.file).parent_path() / path;

  auto d = std::make_shared<ParticleFileData>();
  if (pfs) {
    for (int k = 0;; ++k) {
      const std::string part = path.string() + "." + std::to_string(k);
      if (!std::filesystem::exists(part)) {
        if (k == 0)
          name.fail("cannot open particle file '" + part + "' (<usePFS> is true, Vaango's default: the points are " +
                    "split per patch into <name>.0, <name>.1, ...; write <usePFS>false</usePFS> for one file)");
        break;
      }
      read_one_file(part, true, vars, row_width, *d);
    }
  } else {
    if (!std::filesystem::exists(path)) name.fail("cannot open particle file '" + path.string() + "'");
    read_one_file(path.string(), false, vars, row_width, *d);
  }
  if (d->x.empty()) name.fail("particle file '" + path.string() + "' lists no particles");
  return d;
}

ParticleFilePiece::ParticleFilePiece(std::shared_ptr<const ParticleFileData> data) : data_(std::move(data)) {
  box_.lo = Vec3::Constant(1e300);
  box_.hi = Vec3::Constant(-1e300);
  for (const Vec3& x : data_->x) {
    box_.lo = box_.lo.cwiseMin(x);
    box_.hi = box_.hi.cwiseMax(x);
  }
  const Vec3 fudge = Vec3::Constant(1e-5);  // Vaango's FileGeometryPiece widening
  box_.lo -= fudge;
  box_.hi += fudge;
}

bool ParticleFilePiece::inside(const Vec3& x) const {
  return (x.array() >= box_.lo.array()).all() && (x.array() <= box_.hi.array()).all();
}

}  // namespace tephra
