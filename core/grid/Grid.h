#pragma once
// The structured grid of one Level: the union of its Boxes must be a single
// rectangular region (boxes that tile a rectangle with one spacing are merged;
// anything else is a MissingFeature for now), cut into the deck's patches.
// Indices: cell (i,j,k) spans [lower + (i,j,k)*dx, +dx); interior cells are
// 0..cells-1, extra (boundary) cells lie outside that range
// (-extraCells .. cells-1+extraCells). Node (i,j,k) sits at lower + (i,j,k)*dx.
// Face (i,j,k) in direction d is the low face of cell (i,j,k) in d.
#include <array>
#include <vector>

#include "core/base/Types.h"
#include "core/grid/IndexRange.h"

namespace tephra {

class DeckNode;

struct Patch {
  int id = 0;
  IntVec3 lo = IntVec3::Zero();  // first interior cell (inclusive)
  IntVec3 hi = IntVec3::Zero();  // last interior cell + 1 (exclusive)
  // The patch's cells including the extra (boundary) cells it owns: on a side
  // where the patch touches the domain boundary the range reaches
  // extraCells beyond lo/hi; elsewhere it equals lo/hi (Uintah's
  // "extra cell" low/high index). make_grid sets these.
  IntVec3 extra_lo = IntVec3::Zero();
  IntVec3 extra_hi = IntVec3::Zero();

  IntVec3 num_cells() const { return hi - lo; }
  IndexRange cells() const { return {lo, hi}; }
  IndexRange cells_with_extra() const { return {extra_lo, extra_hi}; }
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

  IndexRange interior_cells() const { return {IntVec3::Zero(), cells}; }
  IndexRange cells_with_extra() const { return {-extra_cells, cells + extra_cells}; }

  // The patch that owns interior cell c (0 <= c < cells), or -1 outside.
  // Requires index_patches() to have run (make_grid does it).
  int patch_owning_cell(const IntVec3& c) const;
  // Builds the lookup behind patch_owning_cell from `patches`; call after
  // changing the patches by hand (tests). Throws std::logic_error if the
  // patches do not cover the interior exactly once.
  void index_patches();
  // Sets every patch's extra_lo/extra_hi from extra_cells.
  void set_patch_extra_cells();

 private:
  // Patch owner lookup: the sorted distinct patch boundaries per direction cut
  // the domain into blocks that each lie inside one patch.
  std::array<std::vector<int>, 3> cuts_;
  std::vector<int> block_owner_;
};

// Builds the grid from <Grid> (Level/Box with lower, upper, resolution or
// <spacing>, extraCells, patches, periodic). Throws DeckError on bad input and
// MissingFeature for AMR, autoPatch, stretched grids and non-rectangular
// multi-box levels.
Grid make_grid(const DeckNode& grid_section);

// Splits n cells into `parts` contiguous pieces as evenly as possible, the
// first (n % parts) pieces one cell longer. Returns parts+1 boundaries
// 0 = b0 < b1 < ... < b_parts = n. Requires 1 <= parts <= n.
std::vector<int> split_evenly(int n, int parts);

}  // namespace tephra
