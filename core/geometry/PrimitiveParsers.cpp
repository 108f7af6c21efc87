// Deck parsers of the primitive pieces. Element and child names follow
// Vaango's schema (ups_spec.xml, CommonTags); where Vaango's code reads other
// spellings than its schema (ellipsoid rx/ry/rz, torus axis/theta) both are
// accepted. Every invalid value is a DeckError at the element.
#include <Eigen/Geometry>
#include <cmath>

#include "core/deck/DeckNode.h"
#include "core/geometry/DeckChecks.h"
#include "core/geometry/Primitives.h"

namespace tephra {

using geometry_detail::positive_double;
using geometry_detail::require_known_children;

MutablePieceP parse_box(const DeckNode& node) {
  require_known_children(node, {"min", "max"});
  const Vec3 lo = node.get_vec3("min"), hi = node.get_vec3("max");
  for (int i = 0; i < 3; ++i)
    if (!(lo[i] < hi[i]))
      node.fail("degenerate box: min must be < max in every direction (direction " +
                std::string(1, "xyz"[i]) + ": min " + std::to_string(lo[i]) + ", max " +
                std::to_string(hi[i]) + ")");
  return std::make_shared<BoxPiece>(lo, hi);
}

MutablePieceP parse_sphere(const DeckNode& node) {
  require_known_children(node, {"origin", "radius"});
  return std::make_shared<SpherePiece>(node.get_vec3("origin"), positive_double(node, "radius"));
}

MutablePieceP parse_cylinder(const DeckNode& node) {
  // cylinder_end / axisymmetric_* only select surfaces for pressure BCs.
  require_known_children(node, {"bottom", "top", "radius", "cylinder_end", "axisymmetric_end",
                                "axisymmetric_side"});
  const Vec3 bottom = node.get_vec3("bottom"), top = node.get_vec3("top");
  const double radius = positive_double(node, "radius");
  if (!((top - bottom).norm() > 0)) node.fail("cylinder: <top> equals <bottom> (zero length)");
  return make_cylinder(bottom, top, radius);
}

MutablePieceP parse_cone(const DeckNode& node) {
  require_known_children(node, {"bottom", "bottom_radius", "top", "top_radius"});
  const Vec3 bottom = node.get_vec3("bottom"), top = node.get_vec3("top");
  // One radius may be zero (a pointed cone); negative radii, or both zero, are invalid.
  double r[2];
  const char* names[2] = {"bottom_radius", "top_radius"};
  for (int k = 0; k < 2; ++k) {
    const DeckNode& c = node.require_child(names[k]);
    r[k] = c.as_double();
    if (r[k] < 0) c.fail(std::string("<") + names[k] + "> must be >= 0 (got " + c.text + ")");
  }
  if (!(r[0] + r[1] > 0)) node.fail("cone: bottom_radius and top_radius are both zero");
  if (!((top - bottom).norm() > 0)) node.fail("cone: <top> equals <bottom> (zero length)");
  return make_cone(bottom, r[0], top, r[1]);
}

namespace {

// Unit vector of child `name`, DeckError if zero.
Vec3 direction(const DeckNode& node, const std::string& name) {
  const DeckNode& c = node.require_child(name);
  const Vec3 v = c.as_vec3();
  if (!(v.norm() > 0)) c.fail("<" + name + "> must be a nonzero vector");
  return v;
}

void require_orthogonal(const DeckNode& node, const Vec3& a, const Vec3& b, const char* what) {
  if (std::abs(a.normalized().dot(b.normalized())) > 1e-10)
    node.fail(std::string("ellipsoid: axes ") + what + " are not orthogonal");
}

}  // namespace

// Three spellings of the axes:
//  - schema:  r1, r2, r3 (semi-axes) with directions v1, v2 and optional v3
//             (v3 = v1 x v2 when absent); without v1, v2 the axes are x, y, z;
//  - Vaango code: v1, v2, v3 alone, whose lengths are the semi-axes;
//  - Vaango code: rx, ry, rz, axis-aligned.
MutablePieceP parse_ellipsoid(const DeckNode& node) {
  require_known_children(node,
                         {"origin", "r1", "r2", "r3", "v1", "v2", "v3", "rx", "ry", "rz"});
  const Vec3 origin = node.get_vec3("origin");
  const bool has_r = node.has_child("r1") || node.has_child("r2") || node.has_child("r3");
  const bool has_rxyz = node.has_child("rx") || node.has_child("ry") || node.has_child("rz");
  const bool has_v = node.has_child("v1") || node.has_child("v2") || node.has_child("v3");
  Vec3 radii;
  Mat3 axes = Mat3::Identity();
  if (has_r && has_rxyz) node.fail("ellipsoid: give either r1, r2, r3 or rx, ry, rz, not both");
  if (has_rxyz) {
    if (has_v) node.fail("ellipsoid: rx, ry, rz are axis-aligned radii; they cannot take v1, v2, v3");
    radii = {positive_double(node, "rx"), positive_double(node, "ry"), positive_double(node, "rz")};
  } else if (has_r) {
    radii = {positive_double(node, "r1"), positive_double(node, "r2"), positive_double(node, "r3")};
    if (has_v) {
      const Vec3 v1 = direction(node, "v1"), v2 = direction(node, "v2");
      require_orthogonal(node, v1, v2, "v1 and v2");
      Vec3 v3 = v1.cross(v2);
      if (node.has_child("v3")) {
        v3 = direction(node, "v3");
        require_orthogonal(node, v1, v3, "v1 and v3");
        require_orthogonal(node, v2, v3, "v2 and v3");
      }
      axes << v1.normalized(), v2.normalized(), v3.normalized();
    }
  } else if (has_v) {
    const Vec3 v[3] = {direction(node, "v1"), direction(node, "v2"), direction(node, "v3")};
    require_orthogonal(node, v[0], v[1], "v1 and v2");
    require_orthogonal(node, v[0], v[2], "v1 and v3");
    require_orthogonal(node, v[1], v[2], "v2 and v3");
    for (int k = 0; k < 3; ++k) {
      radii[k] = v[k].norm();
      axes.col(k) = v[k] / radii[k];
    }
  } else {
    node.fail("ellipsoid: missing semi-axes (r1, r2, r3 [+ v1, v2, v3], or v1, v2, v3, or rx, ry, rz)");
  }
  return std::make_shared<EllipsoidPiece>(origin, radii, axes);
}

MutablePieceP parse_parallelepiped(const DeckNode& node) {
  require_known_children(node, {"p1", "p2", "p3", "p4"});
  const Vec3 p1 = node.get_vec3("p1"), p2 = node.get_vec3("p2"), p3 = node.get_vec3("p3"),
             p4 = node.get_vec3("p4");
  Mat3 e;
  e << p2 - p1, p3 - p1, p4 - p1;
  const double scale = e.col(0).norm() * e.col(1).norm() * e.col(2).norm();
  if (!(std::abs(e.determinant()) > 1e-12 * scale))
    node.fail("degenerate parallelepiped: p2-p1, p3-p1, p4-p1 are coplanar (zero volume)");
  return std::make_shared<ParallelepipedPiece>(p1, p2, p3, p4);
}

// Schema: axis_vector (any direction). Vaango's code: axis = x|y|z and an
// optional rotation angle theta (radians): axis z is tilted about y, y about
// x, x about z, i.e. the axis vector becomes (-sin t, 0, cos t), (0, cos t,
// sin t), (cos t, sin t, 0) respectively.
MutablePieceP parse_torus(const DeckNode& node) {
  require_known_children(node,
                         {"center", "axis_vector", "axis", "theta", "major_radius", "minor_radius"});
  const Vec3 center = node.get_vec3("center");
  Vec3 axis;
  if (node.has_child("axis_vector")) {
    if (node.has_child("axis") || node.has_child("theta"))
      node.fail("torus: give either <axis_vector> or <axis> (+ <theta>), not both");
    axis = direction(node, "axis_vector");
  } else if (node.has_child("axis")) {
    const DeckNode& a = node.require_child("axis");
    const double t = node.get_double("theta", 0.0);
    if (a.text == "x") axis = {std::cos(t), std::sin(t), 0.0};
    else if (a.text == "y") axis = {0.0, std::cos(t), std::sin(t)};
    else if (a.text == "z") axis = {-std::sin(t), 0.0, std::cos(t)};
    else a.fail("torus <axis> must be x, y or z (got '" + a.text + "')");
  } else {
    node.fail("torus: missing required element <axis_vector>");
  }
  return std::make_shared<TorusPiece>(center, axis, positive_double(node, "major_radius"),
                                      positive_double(node, "minor_radius"));
}

}  // namespace tephra
