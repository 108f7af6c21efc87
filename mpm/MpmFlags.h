#pragma once
// The <MPM> flags block. Explicit time integration with the interpolators
// linear, gimp, cpdi and 3rdorderBS, and the manufactured solutions
// AxisAligned and GeneralizedVortex are implemented; every other flag must either leave the physics
// of what is implemented unchanged or hold Vaango's default value. Anything
// else is a MissingFeature naming the flag (never silently ignored).
#include <string>
#include <vector>

#include "mpm/shape/Interpolator.h"

namespace tephra {

class DeckNode;

struct MpmFlags {
  bool explicit_integrator = true;
  InterpolatorSpec interpolator;  // <interpolator>, <cpdi_lcrit>
  std::string mms;                // <run_MMS_problem>, empty = none
  // <boundary_traction_faces>[zminus,zplus]</boundary_traction_faces>: faces
  // (0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+) whose BndyForce_<face> and
  // BndyContactArea_<face> reductions are computed.
  std::vector<int> boundary_traction_faces;
};

// Reads <MPM> (may be null: all defaults).
MpmFlags parse_mpm_flags(const DeckNode* mpm);

}  // namespace tephra
