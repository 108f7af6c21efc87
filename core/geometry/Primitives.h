#pragma once
// The primitive geometry pieces. Each is a closed set; inside() tests the
// defining inequality. Constructors take already-validated values (the deck
// parsers in PrimitiveParsers.cpp check them and report errors at the node);
// a constructor given invalid values throws std::invalid_argument.
//
// Curved and rotated pieces accept points within a relative round-off
// tolerance kGeomTol of their boundary (in the piece's normalised
// coordinates), so a point computed to lie on the surface counts as inside.
// The axis-aligned box compares exactly, as Vaango's box does.
#include "core/geometry/GeometryPiece.h"

namespace tephra {

inline constexpr double kGeomTol = 1e-12;

// { x : min <= x <= max } componentwise. Requires min < max in every direction.
class BoxPiece : public GeometryPiece {
 public:
  BoxPiece(const Vec3& min, const Vec3& max);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override { return {min_, max_}; }
  std::string type() const override { return "box"; }
  double volume() const { return (max_ - min_).prod(); }

 private:
  Vec3 min_, max_;
};

// { x : |x - origin| <= radius }.
class SpherePiece : public GeometryPiece {
 public:
  SpherePiece(const Vec3& origin, double radius);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return "sphere"; }

 private:
  Vec3 origin_;
  double radius_;
};

// A truncated cone (frustum) with circular ends of radius r_b at `bottom` and
// r_t at `top`: with a = (top-bottom)/L, s = (x-bottom).a,
//   { x : 0 <= s <= L, |x - bottom - s a| <= r_b + (r_t - r_b) s / L }.
// The cylinder is the case r_b = r_t. One radius may be zero (a true cone).
class FrustumPiece : public GeometryPiece {
 public:
  FrustumPiece(const Vec3& bottom, double bottom_radius, const Vec3& top, double top_radius,
               std::string type_name);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return type_name_; }

 private:
  Vec3 bottom_, top_, axis_;  // axis_: unit vector bottom -> top
  double length_, r_bottom_, r_top_;
  std::string type_name_;
};

std::shared_ptr<FrustumPiece> make_cylinder(const Vec3& bottom, const Vec3& top, double radius);
std::shared_ptr<FrustumPiece> make_cone(const Vec3& bottom, double bottom_radius, const Vec3& top,
                                        double top_radius);

// { x : sum_k ((x-origin).u_k / r_k)^2 <= 1 } with orthonormal axes u_k and
// semi-axis lengths r_k (Vaango: E = { x | (x-c)^T U S U^T (x-c) <= 1 },
// S = diag(1/r_k^2)).
class EllipsoidPiece : public GeometryPiece {
 public:
  // axes: columns are unit vectors, mutually orthogonal.
  EllipsoidPiece(const Vec3& origin, const Vec3& radii, const Mat3& axes);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return "ellipsoid"; }

 private:
  Vec3 origin_, radii_;
  Mat3 axes_;
};

// p1 a corner, p2, p3, p4 the three corners adjacent to it (their order does
// not matter):  { p1 + E c : c in [0,1]^3 },  E = [p2-p1, p3-p1, p4-p1].
// Requires det E != 0.
class ParallelepipedPiece : public GeometryPiece {
 public:
  ParallelepipedPiece(const Vec3& p1, const Vec3& p2, const Vec3& p3, const Vec3& p4);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return "parallelepiped"; }

 private:
  Vec3 p1_;
  Mat3 edges_, inverse_;
};

// Solid torus around the axis through `center` along unit vector a, with
// major radius R (centre of the tube) and minor radius r (tube):
//   { x : (rho - R)^2 + z^2 <= r^2 },  z = (x-center).a,  rho = |x-center - z a|.
class TorusPiece : public GeometryPiece {
 public:
  TorusPiece(const Vec3& center, const Vec3& axis, double major_radius, double minor_radius);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return "torus"; }

 private:
  Vec3 center_, axis_;
  double major_, minor_;
};

// Parsers from deck elements (children as in Vaango's schema). They report
// every invalid value with a DeckError located at the element.
// They return a mutable piece so that the registry can set its label.
using MutablePieceP = std::shared_ptr<GeometryPiece>;
MutablePieceP parse_box(const DeckNode& node);
MutablePieceP parse_sphere(const DeckNode& node);
MutablePieceP parse_cylinder(const DeckNode& node);
MutablePieceP parse_cone(const DeckNode& node);
MutablePieceP parse_ellipsoid(const DeckNode& node);
MutablePieceP parse_parallelepiped(const DeckNode& node);
MutablePieceP parse_torus(const DeckNode& node);

}  // namespace tephra
