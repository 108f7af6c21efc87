#pragma once
// The structured grid of one Level: the union of its Boxes must be a single
// rectangular region (multi-box levels are a MissingFeature for now), cut into
// the deck's patches. Indices: cell (i,j,k) spans [lower + (i,j,k)*dx, +dx);
// interior cells are 0..cells-1, extra (boundary) cells lie outside that range
// (-extraCells .. cells-1+extraCells). Node (i,j,k) sits at lower + (i,j,k)*dx.
#include <vector>

#include "core/base/Types.h"

namespace tephra {

class DeckNode;

struct Patch {
  int id = 0;
  IntVec3 lo = IntVec3::Zero();  // first interior cell (inclusive)
  IntVec3 hi = IntVec3::Zero();  // last interior cell + 1 (exclusive)
  IntVec3 num_cells() const { return hi - lo; }
};

struct Grid {
  Vec3 lower = Vec3::Zero();            // lower corner of the interior domain
  Vec3 upper = Vec3::Zero();            // upper corner of the interior domain
  Vec3 dx = Vec3::Ones();               // cell size
  IntVec3 cells = IntVec3::Ones();      // interior cells per direction
  IntVec3 extra_cells = IntVec3::Zero();// extra (boundary) cells per side
  IntVec3 periodic = IntVec3::Zero();   // 1 where the direction is periodic
  std::vector<Patch> patches;           // cover the interior cells exactly once

  Vec3 cell_center(int i, int j, int k) const {
    return lower + Vec3((i + 0.5) * dx[0], (j + 0.5) * dx[1], (k + 0.5) * dx[2]);
  }
  Vec3 node_position(int i, int j, int k) const {
    return lower + Vec3(i * dx[0], j * dx[1], k * dx[2]);
  }
  double cell_volume() const { return dx[0] * dx[1] * dx[2]; }
  long long num_interior_cells() const { return 1LL * cells[0] * cells[1] * cells[2]; }
};

// Builds the grid from <Grid> (Level/Box with lower, upper, resolution or
// <spacing>, extraCells, patches, periodic). Throws DeckError on bad input.
Grid make_grid(const DeckNode& grid_section);

}  // namespace tephra
