#pragma once
// MPM grid boundary conditions of <Grid><BoundaryConditions>: per domain face,
// a Dirichlet velocity (the face's nodes get the given velocity) or a symmetry
// plane (the normal velocity component of the face's nodes is zero). Vaango
// applies both to the interpolated velocity (after P2G) and to the integrated
// velocity v* (theory manual Alg. 5 and 8).
#include <array>
#include <optional>
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"

namespace tephra {

class DeckNode;

struct FaceVelocityBC {
  enum class Kind { None, Velocity, Symmetry };
  Kind kind = Kind::None;
  Vec3 value = Vec3::Zero();  // for Velocity
};

struct GridBoundaryConditions {
  // faces: 0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+
  std::array<FaceVelocityBC, 6> face;
  // Dirichlet temperature [K] of each face (var="Dirichlet" label="Temperature"),
  // or none: insulated (zero Neumann). Applied by the heat conduction
  // (mpm/thermal/TemperatureBoundary.h).
  std::array<std::optional<double>, 6> temperature;
  // GIMP, CPDI and B-spline supports reach the extra-cell nodes; Vaango
  // (MPMBoundCond::setBoundaryCondition) then also sets those: a Velocity face
  // gives them the value, a symmetry face mirrors the interior, node
  // face - k = reflection of node face + k (normal component negated).
  bool set_extra_nodes = false;

  // Sets the nodes on each face: Velocity -> v = value, Symmetry -> v_normal = 0.
  // As in Vaango, all Velocity faces are applied first, then all symmetry faces,
  // so an edge node shared by both ends with the symmetry plane's normal
  // component zeroed.
  void apply(const NodeGrid& g, std::vector<Vec3>& velocity) const;
};

// Reads <BoundaryConditions> (may be null: no conditions) for material `material`.
// Dirichlet Temperature faces are read for the heat conduction; a zero
// Neumann Temperature is the natural (insulated) face. Other face kinds, and
// faces with circle/rectangle/annulus patches, are MissingFeature.
GridBoundaryConditions parse_grid_boundary_conditions(const DeckNode* bcs, int material);

}  // namespace tephra
