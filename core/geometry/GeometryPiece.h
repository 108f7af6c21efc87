#pragma once
// Geometry pieces of a deck (<geom_object> children): primitives (box, sphere,
// cylinder, cone, ellipsoid, parallelepiped, tri), the boolean combinations
// (union, difference, intersection) and labels reused by name across the deck.
// MPM seeds particles with them; ICE sets initial cell states with them.
#include <memory>
#include <string>
#include <vector>

#include "core/base/Types.h"

namespace tephra {

class DeckNode;

struct BoundingBox {
  Vec3 lo, hi;
};

class GeometryPiece {
 public:
  virtual ~GeometryPiece() = default;
  virtual bool inside(const Vec3& x) const = 0;  // closed set: boundary points are inside
  virtual BoundingBox bounding_box() const = 0;
  virtual std::string type() const = 0;          // deck element name ("box", "sphere", ...)
  std::string label;                             // the deck's label attribute, if any
};

using GeometryPieceP = std::shared_ptr<const GeometryPiece>;

// Holds every labelled piece of a deck so that a later <box label="x"/> with no
// children refers to the earlier definition (labels are global in Vaango decks).
class GeometryRegistry {
 public:
  // Parses the geometry children of a <geom_object> (or of a union/...) node.
  // Returns one piece (a union when there are several). Throws DeckError.
  GeometryPieceP parse_geom_object(const DeckNode& geom_object);
  GeometryPieceP parse_piece(const DeckNode& piece);
  GeometryPieceP find(const std::string& label) const;

 private:
  std::vector<GeometryPieceP> labelled_;
};

}  // namespace tephra
