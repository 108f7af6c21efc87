#include "mpm/ParticleSeeding.h"

#include <algorithm>
#include <cmath>

namespace tephra {

void seed_particles(const Grid& grid, const std::vector<ParticleSource>& sources, double density,
                    Particles& p, long long& next_id) {
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const ParticleSource& src = sources[s];
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
