#pragma once
// Axisymmetric MPMICE (x = r): the share of a particle's node weight that the
// projection gives to the cell above the node in r (mpmice/CellProjection.h).
//
// Cell i = [r_g, r_g + h] of node g. The projection gives cell i, from a
// particle p, the x weight
//   W_i(x_p) = sum over i's two nodes n of a_np S_n(x_p),
// a_np the share of the particle's S_gp at node n going to the cell above n
// (1 - a_np to the cell below). Session 21 took the side of the particle,
// a = 1 if r_p >= r_g else 0. With it W_i jumps when a particle crosses a
// node: by S_g(r_g) = 1 - l/2 = 7/8 of the particle (GIMP, half-length l = 1/4
// in cells, 2 ppc). The solids' face fluxes, differences of two projections
// (mpmice/SolidVolumeFlux.cpp), then move 7/8 of the particle's x weight
// through the face in the step it crosses, with no motion behind it; the
// cookoff deck (inputs/validation/cookoff_axisym.ups) got a PBX volume
// inflow of 0.11 cell volumes in one step in cell (32,6): delP 6.4e8 Pa,
// then 2.6 GPa and a negative specific volume of the trace product gas
// (docs/mpmice.md "Session 24"). The Cartesian projection (weight 1/8 per
// node, no side) is continuous in x_p.
//
// The share used now makes W_i the fraction of the particle's domain
// [x_p - l h, x_p + l h] that lies in the cell (the overlap), which is
// continuous in x_p, equals the side rule whenever the domain lies in one
// cell (so the initial, midpoint-placed lattice projects as before: the
// exact-density property of CellProjection.h holds), and moves exactly the
// domain fraction that crosses the face (tiled domains translated by d:
// the flux is rho d per unit face, as the Cartesian GIMP projection's).
// With t = (r_p - r_g)/h in [-l, l] (the domain straddles node g, and only
// node g for l <= 1/2), o = (t + l)/(2l) the overlap with the cell above,
// the cell above gets S_{g+1} (all of it: the particle is below node g+1)
// plus a S_g, so
//   a = (o - S_{g+1}) / S_g,
// with the 1-D weights of the interpolator at the particle:
//   GIMP (ShapeGimp.h eqs. 1.91-1.92): S_g = 1 - (t^2 + l^2)/(2l),
//        S_{g+1} = (l + t)^2/(4l) = l o^2;
//   linear hat: S_g = 1 - |t|, S_{g+1} = max(t, 0).
// The cell below then gets S_{g-1} + (1 - a) S_g = 1 - o by the partition of
// unity. t = +-l gives a = 1, 0 (the side rule), t = 0 gives 1/2. Used for
// GIMP only; the linear hat and the others (B-splines, CPDI) keep the side
// rule (not continuous; see the note in the function).
#include <algorithm>
#include <cmath>

#include "mpm/shape/Interpolator.h"

namespace tephra {

// t: (r_p - r_g)/h; l: the particle's half-length along r in cells (0.5 psize_xx).
inline double axisymmetric_share_above(InterpolatorKind kind, double t, double l) {
  // GIMP only (session 24): with the linear hat the overlap share makes the radially expanding
  // cylinder of test_mpmice_axisymmetric.cpp (v_r = 25 r) stop at step 9 (air on the axis,
  // sp_vol < 0), not investigated; the linear hat keeps the side rule.
  const bool overlap = kind == InterpolatorKind::Gimp && l > 0.0 && l <= 0.5;
  if (!overlap || t >= l) return t >= 0.0 ? 1.0 : 0.0;
  if (t <= -l) return 0.0;
  const double o = (t + l) / (2.0 * l);
  double S_g, S_up;
  if (kind == InterpolatorKind::Gimp) {
    S_g = 1.0 - (t * t + l * l) / (2.0 * l);
    S_up = l * o * o;
  } else {
    S_g = 1.0 - std::abs(t);
    S_up = std::max(t, 0.0);
  }
  return std::clamp((o - S_up) / S_g, 0.0, 1.0);
}

}  // namespace tephra
