#pragma once
// Helpers for the geometry tests: volume by counting lattice points, and
// an orthonormal frame around an axis.
#include <cmath>

#include "core/geometry/GeometryPiece.h"

namespace tephra::test {

// V_h = h^3 * #{ lattice points x = lo + (i + s) h inside }, over the piece's
// bounding box widened by h, with a generic sub-cell shift s so that the
// lattice is not aligned with the piece. Each lattice point stands for the
// cube of side h around it, so |V_h - V| is at most the volume of the points
// within h*sqrt(3)/2 of the surface: by Steiner's formula 2 (h sqrt(3)/2) A
// + O(h^2) for a surface of area A, i.e.
//     |V_h - V| / V <= sqrt(3) A h / V   (to leading order).
inline double counted_volume(const GeometryPiece& piece, double h,
                             const Vec3& shift = Vec3(0.3141592, 0.2718281, 0.1618033)) {
  const BoundingBox b = piece.bounding_box();
  const Vec3 lo = b.lo - Vec3::Constant(h);
  const Vec3 n = ((b.hi - lo) / h).array().ceil() + 1.0;
  long count = 0;
  for (int i = 0; i < n.x(); ++i)
    for (int j = 0; j < n.y(); ++j)
      for (int k = 0; k < n.z(); ++k)
        if (piece.inside(lo + h * (Vec3(i, j, k) + shift))) ++count;
  return count * h * h * h;
}

// Unit vectors n1, n2 with (a, n1, n2) orthonormal.
inline void frame(const Vec3& a, Vec3& n1, Vec3& n2) {
  const Vec3 t = std::abs(a.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  n1 = a.cross(t).normalized();
  n2 = a.cross(n1);
}

}  // namespace tephra::test
