#pragma once
// The burn models in axisymmetric MPMICE (<MPM><axisymmetric>, x = r, y = z;
// session 23, issue 6; docs/mpmice.md "Session 23: burn models in
// axisymmetric MPMICE"). The particles hold per-radian masses (mpm/Axisymmetric.h),
// ICE keeps Cartesian contents M = rho dx dy dz with rho = M_rad / (r_c dx dy)
// (ice/RadialWeights.h, mpmice/MpmIceTransfers.cpp). A burn model then works
// per radian:
//   * its cell volume is r_c dx dy, so the solid's cell mass is rho_CC r_c dx dy;
//   * its burning area is the per-radian area of the surface: a surface
//     element of the (r, z) plane of length l at radius r_s sweeps r_s l per
//     radian, against the planar l dz of the Cartesian area estimate, so
//       A_rad = A_cart r_s / dz;
//     the surface lies on the cell's face in the direction of the outward
//     normal n (the surface cell is the last cell the solid fills: the
//     Simple_Burn / WSB corner tests, mpmice/SimpleBurn.h), so
//       r_s = r_c + (dx/2) n_r   (n_r = 0: a z-face, the annulus r_c dx);
//   * the mass it burns, dm_rad, leaves per-radian particle masses; ICE takes
//     it as the Cartesian content dm_rad dz / r_c (the density change
//     dm_rad / (r_c dx dy) times dx dy dz), and so the momentum, energy and
//     volume sources.
// Sum_c r_c dx dy rho_c over the gas then gains exactly sum dm_rad: the total
// per-radian mass (particles + r-weighted gas) is conserved.
#include <algorithm>

#include "core/base/Types.h"

namespace tephra {

// The radius of cell i's centre.
inline double axisymmetric_cell_radius(double lower_x, double dx, int i) { return lower_x + (i + 0.5) * dx; }

// The per-radian area of a surface with Cartesian area estimate a_cart and
// outward unit normal n in a cell of centre radius r_c and size dx.
inline double axisymmetric_burn_area(double a_cart, const Vec3& n, double r_c, const Vec3& dx) {
  const double r_s = std::max(0.0, r_c + 0.5 * dx[0] * n[0]);
  return a_cart * r_s / dx[2];
}

// ICE's Cartesian content per unit per-radian mass in a cell of centre radius r_c: dz / r_c.
inline double axisymmetric_content_per_radian_mass(double r_c, double dz) { return dz / r_c; }

}  // namespace tephra
