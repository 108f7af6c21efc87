#include "mpm/ParticleSeeding.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/Errors.h"
#include "core/geometry/ParticleFile.h"

namespace tephra {

namespace {

// One particle per listed point (<geom_object><file>, core/geometry/ParticleFile.h).
// V0 = p.volume when the file has it, else the uniform seeding's cell volume /
// (res0 res1 res2) (an assumption; the reference size of the particle domain
// is that of the uniform seeding, diag(1/res)); m = rho0 V0; temperature,
// color and velocity from the file when listed, else the geom_object's.
// A point outside the grid's domain is a DeckError naming its file and line.
void seed_from_file(const Grid& grid, const ParticleFilePiece& file, const std::vector<ParticleSource>& sources,
                    std::size_t s, double density, Particles& p, long long& next_id) {
  const ParticleSource& src = sources[s];
  const ParticleFileData& d = file.data();
  const IntVec3 res = src.res;
  const double v_default = grid.cell_volume() / (double(res[0]) * res[1] * res[2]);
  const Mat3 size = Vec3(1.0 / res[0], 1.0 / res[1], 1.0 / res[2]).asDiagonal();
  for (std::size_t i = 0; i < d.x.size(); ++i) {
    const Vec3& x = d.x[i];
    if (!((x.array() >= grid.lower.array()).all() && (x.array() <= grid.upper.array()).all())) {
      throw DeckError(SourceLocation{d.files[d.file_index[i]], d.line[i], "geom_object/file"},
                      "particle at (" + std::to_string(x[0]) + ", " + std::to_string(x[1]) + ", " +
                          std::to_string(x[2]) + ") lies outside the grid's domain");
    }
    bool earlier = false;
    for (std::size_t e = 0; e < s && !earlier; ++e) earlier = sources[e].piece->inside(x);
    if (earlier) continue;
    const double v0 = d.volume.empty() ? v_default : d.volume[i];
    p.add(x, d.velocity.empty() ? src.velocity : d.velocity[i], density * v0, v0,
          d.temperature.empty() ? src.temperature : d.temperature[i], d.color.empty() ? src.color : d.color[i],
          next_id++, size);
  }
}

}  // namespace

void seed_particles(const Grid& grid, const std::vector<ParticleSource>& sources, double density,
                    Particles& p, long long& next_id) {
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const ParticleSource& src = sources[s];
    if (const auto* file = dynamic_cast<const ParticleFilePiece*>(src.piece.get())) {
      seed_from_file(grid, *file, sources, s, density, p, next_id);
      continue;
    }
    const IntVec3 res = src.res;
    const double v0 = grid.cell_volume() / (double(res[0]) * res[1] * res[2]);
    const double m = density * v0;
    const Mat3 size = Vec3(1.0 / res[0], 1.0 / res[1], 1.0 / res[2]).asDiagonal();
    // Cells that can hold points of the piece: those meeting its bounding box.
    const BoundingBox bb = src.piece->bounding_box();
    IntVec3 lo, hi;
    for (int d = 0; d < 3; ++d) {
      const double a = std::floor((bb.lo[d] - grid.lower[d]) / grid.dx[d]);
      const double b = std::floor((bb.hi[d] - grid.lower[d]) / grid.dx[d]);
      lo[d] = static_cast<int>(std::clamp(a, 0.0, double(grid.cells[d])));
      hi[d] = static_cast<int>(std::clamp(b + 1.0, 0.0, double(grid.cells[d])));  // exclusive
    }
    for (int k = lo[2]; k < hi[2]; ++k)
      for (int j = lo[1]; j < hi[1]; ++j)
        for (int i = lo[0]; i < hi[0]; ++i) {
          const Vec3 corner = grid.node_position(i, j, k);
          for (int c = 0; c < res[2]; ++c)
            for (int b = 0; b < res[1]; ++b)
              for (int a = 0; a < res[0]; ++a) {
                const Vec3 x = corner + Vec3((a + 0.5) / res[0] * grid.dx[0], (b + 0.5) / res[1] * grid.dx[1],
                                             (c + 0.5) / res[2] * grid.dx[2]);
                if (!src.piece->inside(x)) continue;
                bool earlier = false;
                for (std::size_t e = 0; e < s && !earlier; ++e) earlier = sources[e].piece->inside(x);
                if (earlier) continue;
                p.add(x, src.velocity, m, v0, src.temperature, src.color, next_id++, size);
              }
        }
  }
}

}  // namespace tephra
