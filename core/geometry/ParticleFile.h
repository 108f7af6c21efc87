#pragma once
// <geom_object><file>: particles listed in a file (Vaango's FileGeometryPiece,
// checked in its FileGeometryPiece.cc; schema ups_spec geom_object/file:
// <name>, <var> (repeated), <format>, <usePFS>).
//
// Text format, one particle per line: x y z, then the columns of the <var>
// elements in their deck order:
//   p.volume (1 value, m^3), p.temperature (1, K), p.color (1),
//   p.velocity (3, m/s).
// Vaango also reads p.externalforce, p.fiberdir and p.rvec1..3 (CPDI/CPTI
// domain vectors) and binary formats (bin, lsb, msb): these are a
// MissingFeature here. Blank lines and lines starting with '#' are skipped;
// a row with the wrong count of numbers, a non-number, a non-finite value
// or a volume <= 0 is a DeckError naming the data file and its line.
//
// <usePFS> (Vaango's default true): the points were split per patch by
// Uintah's pfs tool into <name>.0, <name>.1, ..., each starting with a
// bounding-box line "xmin ymin zmin xmax ymax zmax". Tephra reads every
// <name>.k present from k = 0 up (its patches need not match the split).
// <usePFS>false</usePFS>: one file <name> with no header.
// A relative <name> is resolved against the directory of the deck file
// that holds the element (Vaango opens it relative to the working
// directory, which is normally the deck's).
//
// As a geometry piece (for inside(), e.g. ICE initial states) the file is
// its points' bounding box widened by 1e-5 (Vaango's FileGeometryPiece);
// MPM seeds one particle per point (mpm/ParticleSeeding.cpp).
#include <memory>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "core/geometry/GeometryPiece.h"

namespace tephra {

class DeckNode;

struct ParticleFileData {
  std::vector<std::string> files;  // the data files read, in order
  std::vector<Vec3> x;             // positions [m]
  std::vector<int> file_index;     // files[file_index[i]] holds particle i ...
  std::vector<int> line;           // ... on this 1-based line
  std::string where(std::size_t i) const { return files[file_index[i]] + ":" + std::to_string(line[i]); }
  std::vector<double> volume;      // p.volume, empty when absent
  std::vector<double> temperature; // p.temperature, empty when absent
  std::vector<double> color;       // p.color, empty when absent
  std::vector<Vec3> velocity;      // p.velocity, empty when absent
};

class ParticleFilePiece final : public GeometryPiece {
 public:
  explicit ParticleFilePiece(std::shared_ptr<const ParticleFileData> data);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override { return box_; }
  std::string type() const override { return "file"; }
  const ParticleFileData& data() const { return *data_; }

 private:
  std::shared_ptr<const ParticleFileData> data_;
  BoundingBox box_;
};

// Reads the <file> element and its data file(s). Throws DeckError /
// MissingFeature.
std::shared_ptr<const ParticleFileData> read_particle_file(const DeckNode& file_node);

}  // namespace tephra
