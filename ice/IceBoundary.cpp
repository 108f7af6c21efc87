#include "ice/IceBoundary.h"

namespace tephra {

void apply_scalar_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<double>& q) {
  const double dx = g.dx[face_axis(f)];
  for_each_boundary_cell(g, p, f, [&](const IntVec3& e, const IntVec3& in) {
    switch (bc.kind) {
      case BCKind::Dirichlet: q(e) = bc.scalar; break;
      case BCKind::Neumann: q(e) = q(in) + bc.scalar * dx; break;
      default: q(e) = q(in); break;  // symmetry: zero normal gradient
    }
  });
}

void apply_vector_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<Vec3>& v) {
  const int d = face_axis(f);
  const double dx = g.dx[d];
  for_each_boundary_cell(g, p, f, [&](const IntVec3& e, const IntVec3& in) {
    switch (bc.kind) {
      case BCKind::Dirichlet: v(e) = bc.vector; break;
      case BCKind::Neumann: v(e) = v(in) + bc.vector * dx; break;
      default: {
        Vec3 m = v(in);
        m[d] = -m[d];
        v(e) = m;
      }
    }
  });
}

void apply_face_velocity_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc, GridArray<double>& u) {
  if (bc.kind != BCKind::Dirichlet && bc.kind != BCKind::Symmetry) return;
  const int d = face_axis(f);
  const bool up = face_is_upper(f);
  if (up ? p.hi[d] != g.cells[d] : p.lo[d] != 0) return;
  IntVec3 lo = p.lo, hi = p.hi;
  lo[d] = up ? g.cells[d] : 0;
  hi[d] = lo[d] + 1;
  const double value = bc.kind == BCKind::Dirichlet ? bc.vector[d] : 0.0;
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) u(i, j, k) = value;
}

}  // namespace tephra
