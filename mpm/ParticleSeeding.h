#pragma once
// Particle seeding from <geom_object>s (Vaango's ParticleCreator, uniform
// placement): each grid cell is cut into res[0] x res[1] x res[2] sub-cells; a
// particle sits at each sub-cell centre that lies inside the piece, with
// volume V0 = cell volume / (res0 res1 res2) and mass m = rho0 V0. A point
// already covered by an earlier geom_object of the same material is skipped,
// so overlapping objects do not double the mass (an assumption: Vaango's
// behaviour for overlaps is not specified in the seeds). A <file> piece
// (core/geometry/ParticleFile.h) gives one particle per listed point instead.
#include <vector>

#include "core/base/Types.h"
#include "core/geometry/GeometryPiece.h"
#include "core/grid/Grid.h"
#include "mpm/Particles.h"

namespace tephra {

struct ParticleSource {
  GeometryPieceP piece;
  IntVec3 res = IntVec3::Constant(2);  // particles per cell per direction (<res>)
  Vec3 velocity = Vec3::Zero();        // <velocity>
  double temperature = 0.0;            // <temperature>
  double color = 0.0;                  // <color>, 0 when absent
};

// Appends the particles of `sources` (in order) to `p`, with ids next_id, next_id+1, ...
// Cells are visited k, j, i (i fastest), sub-points likewise, so the order is
// deterministic.
void seed_particles(const Grid& grid, const std::vector<ParticleSource>& sources, double density,
                    Particles& p, long long& next_id);

}  // namespace tephra
