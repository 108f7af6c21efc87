#pragma once
// Node -> cell weights of the coupled step's projection of a solid to the
// cells (Vaango theory manual sec. 26.1.3 step 1; MpmIceTransfers.cpp): a
// cell's value is the weighted sum of its 8 corner nodes with weight 1/8,
// doubled per symmetry plane the node lies on (the plane's mirror particles
// give the node as much again).
#include <array>
#include <cmath>

#include "core/grid/Grid.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"

namespace tephra {

// The node index offset of cell c's lower corner: node = c + offset.
inline IntVec3 node_offset(const Grid& g, const NodeGrid& ng) {
  IntVec3 o;
  for (int d = 0; d < 3; ++d) o[d] = int(std::lround((g.lower[d] - ng.origin[d]) / ng.h[d]));
  return o;
}

// Which of the six faces (x-, x+, y-, ...) are symmetry planes for the solid.
inline std::array<bool, 6> symmetry_faces(const GridBoundaryConditions& bcs) {
  std::array<bool, 6> s{};
  for (int fc = 0; fc < 6; ++fc) s[fc] = bcs.face[fc].kind == FaceVelocityBC::Kind::Symmetry;
  return s;
}

// The weight of node `node` in the value of a cell it bounds: 1/8 x 2 per
// symmetry plane through the node. `on_plane[d]` (if given) is set when the
// node lies on a symmetry plane normal to d.
inline double node_cell_weight(const NodeGrid& ng, const std::array<bool, 6>& symmetric, const IntVec3& node,
                               bool* on_plane = nullptr) {
  double w = 0.125;
  for (int d = 0; d < 3; ++d) {
    const bool on = (symmetric[2 * d] && node[d] == ng.extra[d]) ||
                    (symmetric[2 * d + 1] && node[d] == ng.n[d] - 1 - ng.extra[d]);
    if (on) w *= 2;
    if (on_plane) on_plane[d] = on;
  }
  return w;
}

}  // namespace tephra
