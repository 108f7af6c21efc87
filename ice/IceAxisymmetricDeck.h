#pragma once
// <MPM><axisymmetric> for ICE (axisymmetric finite volumes, ice/RadialWeights.h):
// reads the flag into IceSetup::axisymmetric and checks the deck can use it.
#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"

namespace tephra {

// Sets s.axisymmetric from <MPM><axisymmetric> (absent: false). With it on:
// DeckError unless the grid has one cell in z, no periodic x, x lower >= 0,
// no radial gravity and, when the domain touches the axis (x lower = 0), a
// Symmetric velocity condition on the x- face for every material;
// MissingFeature (exit 3) for what the axisymmetric step does not have yet:
// viscosity, heat conduction, <ImplicitSolver>, LODI faces.
void read_ice_axisymmetric(const DeckNode& root, IceSetup& s);

}  // namespace tephra
