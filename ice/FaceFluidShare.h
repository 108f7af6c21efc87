#pragma once
// MPMICE: the fluids' share of a face between two cells (ice/IceLagrangianFlux.cpp,
// scale_fluid_flux; docs/mpmice.md "Volume fluxes").
#include <algorithm>

namespace tephra {

// The fluids' share of a face, a = 1 - theta_s,face, bounded by the larger
// fluid fraction of the two cells that share the face: a = min(1 -
// theta_s,face, max(f_L, f_R)). A face lies between its two cells, so the
// part of it the fluids cover cannot exceed the larger of their fluid
// fractions (for any monotone fraction profile across the face). Where a
// fluid-rich cell is one of the two (the surface of a solid, a solid moving
// through a gas: MPMICE/advect.ups) the bound is max(f_L, f_R) ~ 1 and a =
// 1 - theta_s,face as before. Where both cells are solid with a trace of
// fluid (f ~ 1e-6) the solid's face fraction F_s/phi_s carries the
// discretisation error of the particles' projected flux against the face
// velocity (1 - theta_s,face ~ 5e-3 at the compression ramp of
// BurnRate.ups); without the bound chi = (1 - theta_s,face)/f_D reached
// 1500-3000 there and carried the trace product with the compression wave
// at ~1.7 km/s (its own velocity 0.8 m/s), so it took the compression work
// of every cell of the ramp (V theta kappa p delP, the Eulerian delP) while
// the pressure drop of the cell ahead reached it only through the
// equilibration at constant T: +0.12 % of T per step, 3169 K at 27 us and
// 15,411 K at 55 us (docs/mpmice.md, "BurnRate.ups (C10), session 18").
// With the bound chi <= max(f_L, f_R)/f_D ~ 1 there: Uintah's donor-cell
// flux of the fluid's own fraction (Uintah has no chi). The volume the
// fluids do not fill is left to the next equilibration, as in Uintah.
inline double face_fluid_share(double theta_face, double fluid_L, double fluid_R) {
  return std::min(1.0 - theta_face, std::max(fluid_L, fluid_R));
}

}  // namespace tephra
