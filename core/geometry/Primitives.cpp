// Inside tests and bounding boxes of the primitive pieces (see Primitives.h
// for the defining sets).
#include "core/geometry/Primitives.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace tephra {

namespace {

// Half-extent, along coordinate direction i, of a disc of radius rho whose
// normal is the unit vector a: rho * sqrt(1 - a_i^2) (the disc's in-plane unit
// vectors span all of e_i except its component along a).
Vec3 disc_half_extent(const Vec3& a, double rho) {
  Vec3 e;
  for (int i = 0; i < 3; ++i) e[i] = rho * std::sqrt(std::max(0.0, 1.0 - a[i] * a[i]));
  return e;
}

BoundingBox hull(const BoundingBox& a, const BoundingBox& b) {
  return {a.lo.cwiseMin(b.lo), a.hi.cwiseMax(b.hi)};
}

}  // namespace

// ---------------------------------------------------------------- box
BoxPiece::BoxPiece(const Vec3& min, const Vec3& max) : min_(min), max_(max) {
  if (!(min.array() < max.array()).all()) throw std::invalid_argument("box: min must be < max");
}

bool BoxPiece::inside(const Vec3& x) const {
  return (x.array() >= min_.array()).all() && (x.array() <= max_.array()).all();
}

// ---------------------------------------------------------------- sphere
SpherePiece::SpherePiece(const Vec3& origin, double radius) : origin_(origin), radius_(radius) {
  if (!(radius > 0)) throw std::invalid_argument("sphere: radius must be > 0");
}

bool SpherePiece::inside(const Vec3& x) const {
  return (x - origin_).squaredNorm() <= radius_ * radius_ * (1.0 + kGeomTol);
}

BoundingBox SpherePiece::bounding_box() const {
  const Vec3 r = Vec3::Constant(radius_);
  return {origin_ - r, origin_ + r};
}

// ---------------------------------------------------------------- cylinder, cone
FrustumPiece::FrustumPiece(const Vec3& bottom, double bottom_radius, const Vec3& top,
                           double top_radius, std::string type_name)
    : bottom_(bottom), top_(top), r_bottom_(bottom_radius), r_top_(top_radius),
      type_name_(std::move(type_name)) {
  length_ = (top - bottom).norm();
  if (!(length_ > 0)) throw std::invalid_argument(type_name_ + ": top must differ from bottom");
  if (r_bottom_ < 0 || r_top_ < 0 || !(r_bottom_ + r_top_ > 0))
    throw std::invalid_argument(type_name_ + ": radii must be >= 0 and not both zero");
  axis_ = (top - bottom) / length_;
}

bool FrustumPiece::inside(const Vec3& x) const {
  const Vec3 d = x - bottom_;
  const double s = d.dot(axis_);
  const double scale = std::max({length_, r_bottom_, r_top_});
  const double tol = kGeomTol * scale;
  if (s < -tol || s > length_ + tol) return false;
  const double sc = std::clamp(s, 0.0, length_);
  const double r = r_bottom_ + (r_top_ - r_bottom_) * sc / length_;
  const double rho = (d - s * axis_).norm();
  return rho <= r + tol;
}

BoundingBox FrustumPiece::bounding_box() const {
  const Vec3 eb = disc_half_extent(axis_, r_bottom_);
  const Vec3 et = disc_half_extent(axis_, r_top_);
  return hull({bottom_ - eb, bottom_ + eb}, {top_ - et, top_ + et});
}

std::shared_ptr<FrustumPiece> make_cylinder(const Vec3& bottom, const Vec3& top, double radius) {
  if (!(radius > 0)) throw std::invalid_argument("cylinder: radius must be > 0");
  return std::make_shared<FrustumPiece>(bottom, radius, top, radius, "cylinder");
}

std::shared_ptr<FrustumPiece> make_cone(const Vec3& bottom, double bottom_radius, const Vec3& top,
                                        double top_radius) {
  return std::make_shared<FrustumPiece>(bottom, bottom_radius, top, top_radius, "cone");
}

// ---------------------------------------------------------------- ellipsoid
EllipsoidPiece::EllipsoidPiece(const Vec3& origin, const Vec3& radii, const Mat3& axes)
    : origin_(origin), radii_(radii), axes_(axes) {
  if (!(radii.array() > 0).all()) throw std::invalid_argument("ellipsoid: radii must be > 0");
  if (!(axes.transpose() * axes).isIdentity(1e-10))
    throw std::invalid_argument("ellipsoid: axes must be orthonormal");
}

bool EllipsoidPiece::inside(const Vec3& x) const {
  // Coordinates along the principal axes, scaled by the semi-axes.
  const Vec3 c = (axes_.transpose() * (x - origin_)).cwiseQuotient(radii_);
  return c.squaredNorm() <= 1.0 + kGeomTol;
}

BoundingBox EllipsoidPiece::bounding_box() const {
  // max over the ellipsoid of e_i.(x - origin) = sqrt(sum_k r_k^2 (u_k)_i^2)
  // (support function of the ellipsoid, = sqrt of (U S^-1 U^T)_ii).
  Vec3 e;
  for (int i = 0; i < 3; ++i)
    e[i] = std::sqrt((axes_.row(i).transpose().cwiseProduct(radii_)).squaredNorm());
  return {origin_ - e, origin_ + e};
}

// ---------------------------------------------------------------- parallelepiped
ParallelepipedPiece::ParallelepipedPiece(const Vec3& p1, const Vec3& p2, const Vec3& p3,
                                         const Vec3& p4)
    : p1_(p1) {
  edges_.col(0) = p2 - p1;
  edges_.col(1) = p3 - p1;
  edges_.col(2) = p4 - p1;
  const double scale = edges_.col(0).norm() * edges_.col(1).norm() * edges_.col(2).norm();
  if (!(std::abs(edges_.determinant()) > 1e-12 * scale))
    throw std::invalid_argument("parallelepiped: p2-p1, p3-p1, p4-p1 are coplanar");
  inverse_ = edges_.inverse();
}

bool ParallelepipedPiece::inside(const Vec3& x) const {
  const Vec3 c = inverse_ * (x - p1_);  // x = p1 + E c
  return (c.array() >= -kGeomTol).all() && (c.array() <= 1.0 + kGeomTol).all();
}

BoundingBox ParallelepipedPiece::bounding_box() const {
  BoundingBox b{p1_, p1_};
  for (int corner = 1; corner < 8; ++corner) {
    Vec3 p = p1_;
    for (int k = 0; k < 3; ++k)
      if (corner & (1 << k)) p += edges_.col(k);
    b = hull(b, {p, p});
  }
  return b;
}

// ---------------------------------------------------------------- torus
TorusPiece::TorusPiece(const Vec3& center, const Vec3& axis, double major_radius,
                       double minor_radius)
    : center_(center), major_(major_radius), minor_(minor_radius) {
  if (!(axis.norm() > 0)) throw std::invalid_argument("torus: axis must be nonzero");
  if (!(major_radius > 0) || !(minor_radius > 0))
    throw std::invalid_argument("torus: radii must be > 0");
  axis_ = axis.normalized();
}

bool TorusPiece::inside(const Vec3& x) const {
  const Vec3 d = x - center_;
  const double z = d.dot(axis_);
  const double rho = (d - z * axis_).norm();
  return (rho - major_) * (rho - major_) + z * z <= minor_ * minor_ * (1.0 + kGeomTol);
}

BoundingBox TorusPiece::bounding_box() const {
  // The tube's centre circle (radius R, normal a) swept by a ball of radius r.
  const Vec3 e = disc_half_extent(axis_, major_) + Vec3::Constant(minor_);
  return {center_ - e, center_ + e};
}

}  // namespace tephra
