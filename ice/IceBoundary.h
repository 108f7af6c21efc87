#pragma once
// ICE boundary conditions on the extra (boundary) cells of the domain, one
// layer (Uintah's BoundaryCond.cc meaning of each kind):
//   Dirichlet          q_extra = value
//   Neumann            q_extra = q_inner + value * dx   (value = gradient along the outward normal)
//   symmetry           scalars: q_extra = q_inner; vectors: mirror, normal component negated
//   computeFromDensity (SpecificVol) sp_vol_extra = vol_frac_extra / rho_CC_extra
// and on the boundary faces for the normal face velocity:
//   Dirichlet velocity u_face = value . n;  symmetry u_face = 0;  Neumann: the
//   face velocity computed from the extra-cell state is kept.
#include "core/grid/Fields.h"
#include "ice/IceSetup.h"

#include <vector>

namespace tephra {

// Calls fn(extra_cell, inner_cell) for each extra cell of patch p on domain
// face f (none if p does not touch f). The tangential range covers the
// patch's extra cells, so edges and corners get a value too, and, in periodic
// tangential directions, `periodic_ghosts` ghost layers (for a field whose
// ghosts already hold the periodic images of the inner cells and that is not
// exchanged again after this BC: the corner ghosts then get the same value as
// the extra cells they are images of).
template <class Fn>
void for_each_boundary_cell(const Grid& g, const Patch& p, GridFace f, Fn&& fn, int periodic_ghosts = 0) {
  const int d = face_axis(f);
  const bool up = face_is_upper(f);
  if (up ? p.extra_hi[d] <= p.hi[d] : p.extra_lo[d] >= p.lo[d]) return;
  IntVec3 lo = p.extra_lo, hi = p.extra_hi;
  for (int t = 0; t < 3; ++t)
    if (t != d && g.periodic[t]) {
      lo[t] -= periodic_ghosts;
      hi[t] += periodic_ghosts;
    }
  lo[d] = up ? g.cells[d] : -1;
  hi[d] = lo[d] + 1;
  const IntVec3 in = up ? IntVec3(-IntVec3::Unit(d)) : IntVec3(IntVec3::Unit(d));
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        const IntVec3 c(i, j, k);
        fn(c, IntVec3(c + in));
      }
}

// Scalar kinds (Dirichlet, Neumann, symmetry). ComputeFromDensity is the
// caller's (it needs two other fields).
void apply_scalar_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<double>& q);
void apply_vector_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<Vec3>& v);
// Hydrostatic adjustment of the pressure in the extra cells of face f, after
// apply_scalar_bc, when gravity g is not zero (Uintah's BoundaryCond.cc
// HydrostaticPressureAdjustment; Kashiwa's ICE: the face pressure on a
// wall must carry the weight of the fluid). rho is the mixture density
// sum_m rho_CC,m, the sum over `rho` (Uintah takes the micro density of the surrounding
// material; the two agree for one material).
//   Neumann and symmetry (a wall normal to g):
//     p_e += g_n dx (rho_i + rho_e)/2,   g_n = g . n_outward,
//   the discrete balance (p_R - p_L)/dx = g (rho_L + rho_R)/2 of the face
//   velocity eq. 26.1 across the boundary face (Uintah adjusts Neumann
//   faces only; a symmetry plane normal to g is no mirror plane, since g
//   breaks the mirror symmetry, so Tephra treats it as the wall it is).
//   Dirichlet (value = p at the centre x_0 of cell (0,0,0)):
//     p_e += rho_e g . (x_e - x_0).
// Other kinds (LODI) are left as they are.
void apply_hydrostatic_pressure_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc,
                                   const Vec3& gravity, const std::vector<const GridArray<double>*>& rho,
                                   GridArray<double>& press);
// The normal face velocity on the boundary face f (face array of axis(f)).
void apply_face_velocity_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<double>& u);

}  // namespace tephra
