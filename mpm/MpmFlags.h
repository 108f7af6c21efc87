#pragma once
// The <MPM> flags block. Only explicit time integration with linear shape
// functions is implemented; every other flag must either leave the physics
// of what is implemented unchanged or hold Vaango's default value. Anything
// else is a MissingFeature naming the flag (never silently ignored).
#include <vector>

namespace tephra {

class DeckNode;

struct MpmFlags {
  // Nothing to store yet: explicit + linear are the only accepted values.
  // Kept as a struct so later slices (GIMP, damping, ...) add fields here.
  bool explicit_integrator = true;
  bool linear_interpolator = true;
  // <boundary_traction_faces>[zminus,zplus]</boundary_traction_faces>: faces
  // (0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+) whose BndyForce_<face> and
  // BndyContactArea_<face> reductions are computed.
  std::vector<int> boundary_traction_faces;
};

// Reads <MPM> (may be null: all defaults).
MpmFlags parse_mpm_flags(const DeckNode* mpm);

}  // namespace tephra
