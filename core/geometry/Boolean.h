#pragma once
// Boolean combinations of pieces (closed sets in, closed sets out up to the
// boundary of the subtracted pieces):
//   union:        x in A_1 or ... or A_n
//   intersection: x in A_1 and ... and A_n
//   difference:   x in A_1 and not in (A_2 or ... or A_n)
// The difference follows Vaango: the first child minus the others. Its
// result contains no point of a subtracted piece's boundary (A \ B with B
// closed); this matters only for points exactly on that boundary.
#include <vector>

#include "core/geometry/GeometryPiece.h"

namespace tephra {

class UnionPiece : public GeometryPiece {
 public:
  explicit UnionPiece(std::vector<GeometryPieceP> children);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override;
  std::string type() const override { return "union"; }

 private:
  std::vector<GeometryPieceP> children_;
  BoundingBox box_;
};

class IntersectionPiece : public GeometryPiece {
 public:
  explicit IntersectionPiece(std::vector<GeometryPieceP> children);
  bool inside(const Vec3& x) const override;
  // The intersection of the children's boxes; lo > hi in some direction when
  // those boxes do not overlap (the piece is then empty).
  BoundingBox bounding_box() const override;
  std::string type() const override { return "intersection"; }

 private:
  std::vector<GeometryPieceP> children_;
  BoundingBox box_;
};

class DifferencePiece : public GeometryPiece {
 public:
  // children: the piece, then the pieces removed from it (at least one).
  explicit DifferencePiece(std::vector<GeometryPieceP> children);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override { return children_.front()->bounding_box(); }
  std::string type() const override { return "difference"; }

 private:
  std::vector<GeometryPieceP> children_;
};

}  // namespace tephra
