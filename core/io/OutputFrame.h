#pragma once
// What a component hands to the writer at an output time: particle sets and
// grid fields, each a labelled array of scalars (1), vectors (3) or tensors
// (9, row-major xx,xy,xz,yx,...,zz), with Vaango's label names (p.x, p.stress,
// g.mass, press_CC, ...). The writer knows nothing of MPM or ICE.
#include <string>
#include <vector>

#include "core/grid/Grid.h"

namespace tephra {

struct FieldArray {
  std::string label;           // Vaango name, e.g. "p.stress", "press_CC"
  int material = 0;            // material index as in the deck
  int components = 1;          // 1, 3 or 9
  std::vector<double> values;  // size = count * components
};

// One material's particles: positions, ids and any saved fields.
struct ParticleBlock {
  int material = 0;
  std::vector<Vec3> position;        // p.x (always written)
  std::vector<long long> id;         // p.particleID (always written)
  std::vector<FieldArray> fields;    // one entry per particle per field
};

// Cell centres, nodes, or the centres of the faces normal to x, y or z
// (Uintah's SFCX/SFCY/SFCZ variables: uvel_FC, vvel_FC, wvel_FC).
enum class GridLocation { Cell, Node, FaceX, FaceY, FaceZ };

// Per direction 1 where the location sits on the cell boundaries (a field of
// n cells then has n + 1 values along that direction), else 0.
inline IntVec3 location_stagger(GridLocation l) {
  switch (l) {
    case GridLocation::Node: return IntVec3::Ones();
    case GridLocation::FaceX: return IntVec3::Unit(0);
    case GridLocation::FaceY: return IntVec3::Unit(1);
    case GridLocation::FaceZ: return IntVec3::Unit(2);
    default: return IntVec3::Zero();
  }
}
inline const char* location_name(GridLocation l) {
  switch (l) {
    case GridLocation::Node: return "Node";
    case GridLocation::FaceX: return "FaceX";
    case GridLocation::FaceY: return "FaceY";
    case GridLocation::FaceZ: return "FaceZ";
    default: return "Cell";
  }
}

// A box of entries of a grid array: offsets lo (inclusive) .. hi (exclusive)
// from the array's first entry, per direction.
struct ArrayBox {
  IntVec3 lo = IntVec3::Zero();
  IntVec3 hi = IntVec3::Zero();
  bool empty() const { return (hi.array() <= lo.array()).any(); }
  long long count() const { return empty() ? 0 : 1LL * (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]); }
  bool operator==(const ArrayBox& o) const { return lo == o.lo && hi == o.hi; }
};

// A field on the whole interior (+ extra cells for Cell) of the grid, stored
// with i fastest: index = i + ni*(j + nj*k) over the written extent.
// Per-rank output (session 25, core/parallel/OutputGather.h OutputPerRank):
// `partial` is set and only the entries inside `pieces` (disjoint boxes) are
// this rank's to write; the rest of `values` is not used. Every entry of the
// level is in the pieces of exactly one rank, or of none (then it reads as 0,
// as the gathered array holds there).
struct GridFieldArray {
  FieldArray data;
  GridLocation location = GridLocation::Cell;
  bool partial = false;
  std::vector<ArrayBox> pieces = {};
};

struct OutputFrame {
  int step = 0;
  double time = 0.0;
  const Grid* grid = nullptr;
  std::vector<ParticleBlock> particles;
  std::vector<GridFieldArray> grid_fields;
};

}  // namespace tephra
