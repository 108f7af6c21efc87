// <MPM><axisymmetric> for ICE: the flag and its deck checks (IceAxisymmetricDeck.h).
#include "ice/IceAxisymmetricDeck.h"

#include <string>

namespace tephra {

void read_ice_axisymmetric(const DeckNode& root, IceSetup& s) {
  const DeckNode* mpm = root.child("MPM");
  const DeckNode* flag = mpm ? mpm->child("axisymmetric") : nullptr;
  if (!flag || !flag->as_bool()) return;
  s.axisymmetric = true;
  const DeckNode& grid = root.require_child("Grid");
  const Grid& g = s.grid;
  if (g.cells[2] != 1)
    grid.fail("axisymmetric ICE (x = r, y = z) needs exactly one cell in z; the grid has " + std::to_string(g.cells[2]));
  if (g.periodic[0]) grid.fail("axisymmetric ICE: the radial direction x cannot be periodic");
  if (g.lower[0] < 0)
    grid.fail("axisymmetric ICE: the domain starts at r = x = " + std::to_string(g.lower[0]) + " < 0");
  if (s.gravity[0] != 0.0)
    root.require_child("PhysicalConstants").require_child("gravity").fail(
        "axisymmetric ICE: gravity must lie along the axis y (its x = r component is " + std::to_string(s.gravity[0]) + ")");
  if (s.implicit.enabled) flag->missing_feature("<axisymmetric> with the ICE <ImplicitSolver>");
  if (s.lodi.enabled) flag->missing_feature("<axisymmetric> with LODI boundary conditions");
  for (const IceMaterialSpec& m : s.materials) {
    if (m.lagrangian) continue;
    if (m.dynamic_viscosity != 0.0)
      flag->missing_feature("<axisymmetric> with viscosity (ICE material '" + m.name + "' has dynamic_viscosity " +
                            std::to_string(m.dynamic_viscosity) + ")");
    if (m.thermal_conductivity != 0.0)
      flag->missing_feature("<axisymmetric> with heat conduction (ICE material '" + m.name +
                            "' has thermal_conductivity " + std::to_string(m.thermal_conductivity) + ")");
  }
  // The axis r = 0 is a symmetry face: no flow through it.
  if (g.lower[0] == 0.0)
    for (std::size_t m = 0; m < s.bcs.size(); ++m)
      if (s.bcs[m][static_cast<int>(GridFace::XMinus)][kBcVelocity].kind != BCKind::Symmetry)
        grid.require_child("BoundaryConditions")
            .fail("axisymmetric ICE: the x- face (the axis r = 0) needs a Symmetric boundary condition for material " +
                  std::to_string(m) + (s.materials[m].name.empty() ? "" : " ('" + s.materials[m].name + "')"));
}

}  // namespace tephra
