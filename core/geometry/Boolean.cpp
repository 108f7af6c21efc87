#include "core/geometry/Boolean.h"

#include <stdexcept>

namespace tephra {

namespace {

bool in_box(const BoundingBox& b, const Vec3& x) {
  return (x.array() >= b.lo.array()).all() && (x.array() <= b.hi.array()).all();
}

}  // namespace

UnionPiece::UnionPiece(std::vector<GeometryPieceP> children) : children_(std::move(children)) {
  if (children_.empty()) throw std::invalid_argument("union: no children");
  box_ = children_.front()->bounding_box();
  for (const auto& c : children_) {
    const BoundingBox b = c->bounding_box();
    box_ = {box_.lo.cwiseMin(b.lo), box_.hi.cwiseMax(b.hi)};
  }
}

bool UnionPiece::inside(const Vec3& x) const {
  if (!in_box(box_, x)) return false;
  for (const auto& c : children_)
    if (c->inside(x)) return true;
  return false;
}

BoundingBox UnionPiece::bounding_box() const { return box_; }

IntersectionPiece::IntersectionPiece(std::vector<GeometryPieceP> children)
    : children_(std::move(children)) {
  if (children_.empty()) throw std::invalid_argument("intersection: no children");
  box_ = children_.front()->bounding_box();
  for (const auto& c : children_) {
    const BoundingBox b = c->bounding_box();
    box_ = {box_.lo.cwiseMax(b.lo), box_.hi.cwiseMin(b.hi)};
  }
}

bool IntersectionPiece::inside(const Vec3& x) const {
  if (!in_box(box_, x)) return false;
  for (const auto& c : children_)
    if (!c->inside(x)) return false;
  return true;
}

BoundingBox IntersectionPiece::bounding_box() const { return box_; }

DifferencePiece::DifferencePiece(std::vector<GeometryPieceP> children)
    : children_(std::move(children)) {
  if (children_.size() < 2) throw std::invalid_argument("difference: needs at least two children");
}

bool DifferencePiece::inside(const Vec3& x) const {
  if (!children_.front()->inside(x)) return false;
  for (size_t k = 1; k < children_.size(); ++k)
    if (children_[k]->inside(x)) return false;
  return true;
}

}  // namespace tephra
