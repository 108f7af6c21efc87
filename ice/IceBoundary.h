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
// The normal face velocity on the boundary face f (face array of axis(f)).
void apply_face_velocity_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<double>& u);

}  // namespace tephra
