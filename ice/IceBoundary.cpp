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

void apply_hydrostatic_pressure_bc(const Grid& g, const Patch& p, GridFace f, const IceFaceBc& bc,
                                   const Vec3& gravity, const std::vector<const GridArray<double>*>& rho_parts,
                                   GridArray<double>& press) {
  if (gravity == Vec3::Zero()) return;
  auto rho = [&](const IntVec3& c) {
    double s = 0;
    for (const GridArray<double>* r : rho_parts) s += (*r)(c);
    return s;
  };
  const int d = face_axis(f);
  if (bc.kind == BCKind::Neumann || bc.kind == BCKind::Symmetry) {
    const double g_n = face_is_upper(f) ? gravity[d] : -gravity[d];
    if (g_n == 0.0) return;
    const double dx = g.dx[d];
    for_each_boundary_cell(g, p, f, [&](const IntVec3& e, const IntVec3& in) {
      press(e) += g_n * dx * 0.5 * (rho(in) + rho(e));
    });
  } else if (bc.kind == BCKind::Dirichlet) {
    const Vec3 x0 = g.cell_center(0, 0, 0);
    for_each_boundary_cell(g, p, f, [&](const IntVec3& e, const IntVec3&) {
      press(e) += rho(e) * gravity.dot(g.cell_center(e[0], e[1], e[2]) - x0);
    });
  }
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
