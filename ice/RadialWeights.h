#pragma once
// Axisymmetric ICE (x = r, y = z, one cell in the third direction): the
// radial face-area weights of the finite volumes in (r, z).
//
// Per radian, cell i has the volume V_i = r_i dr dz (r_i its centre radius),
// its r-faces the areas r_{i-1/2} dz and r_{i+1/2} dz and its z-faces r_i dr.
// The ICE step keeps its Cartesian form (contents M = rho V with the
// Cartesian V = dx dy dz, face fluxes F = q phi with phi = u dt/dx) and
// takes the geometry in the divergence only: the net inflow of cell i is
//   dq_i = (r_{i-1/2}/r_i) F_{i-1/2} - (r_{i+1/2}/r_i) F_{i+1/2}
//          + (F_{j-1/2} - F_{j+1/2}) + (F_{k-1/2} - F_{k+1/2}),
// i.e. (1/V_i) sum_f A_f (q u)_f dt in units of q times the Cartesian V:
// the r-faces scale by A_f/V_i = r_f/(r_i dr), the z-faces by r_i dr/(r_i dr dz) = 1/dz
// as in Cartesian coordinates. Sum_i r_i dq_i telescopes: the contents
// weighted by r (2 pi r) are conserved. The r = 0 face has r_f = 0 (no flux).
// The pressure force needs no weight: with the hoop source p_h dr dz, p_h the
// mean of the two r-face pressures (well-balanced: r_{i+1/2} - r_{i-1/2} = dr
// exactly), -(r_{i+1/2} p_{i+1/2} - r_{i-1/2} p_{i-1/2}) dz + p_h dr dz
// = -r_i (p_{i+1/2} - p_{i-1/2}) dz, the Cartesian gradient times V_i.
// docs/algorithms/ice.md "Axisymmetric ICE".
#include <vector>

#include "core/grid/Grid.h"

namespace tephra {

struct RadialWeights {
  int i_first = 0;         // cell index of entry 0 (the lowest extra cell)
  std::vector<double> lo;  // r_{i-1/2} / r_i
  std::vector<double> hi;  // r_{i+1/2} / r_i
  std::vector<double> r;   // r_i, the cell-centre radius
  // Row pointers for a row starting at cell index i (row[c] is cell i + c).
  const double* lo_row(int i) const { return lo.data() + (i - i_first); }
  const double* hi_row(int i) const { return hi.data() + (i - i_first); }
  const double* r_row(int i) const { return r.data() + (i - i_first); }
};

// The weights of every cell along x, extra cells included (cells with
// r_i <= 0, outside the axis, get 1: no divergence is taken there).
RadialWeights make_radial_weights(const Grid& g);

}  // namespace tephra
