#pragma once
// Geometry pieces of a deck (<geom_object> children): primitives (box, sphere,
// cylinder, cone, ellipsoid, parallelepiped, torus, tri), the boolean
// combinations (union, difference, intersection) and labels reused by name
// across the deck. MPM seeds particles with them; ICE sets initial cell states
// with them.
//
// The concrete pieces live in Primitives.h, Boolean.h and TriMesh.h; most code
// only needs this header.
#include <map>
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
//
// Rules (Vaango's GeometryPieceFactory, made strict):
//  - a piece element with a `label` (or `name`) attribute and no children
//    refers to the earlier piece of that label; it must exist and have the
//    same element name;
//  - a piece element with children and a label defines it; defining it again
//    is allowed only with the same geometry (same values), else a DeckError;
//  - pieces Vaango has but Tephra does not yet (sphere_membrane, ...) are a
//    MissingFeature naming the piece.
class GeometryRegistry {
 public:
  // Parses the geometry children of a <geom_object> (or of a union/...) node.
  // Returns one piece (a union when there are several). Throws DeckError.
  GeometryPieceP parse_geom_object(const DeckNode& geom_object);
  GeometryPieceP parse_piece(const DeckNode& piece);
  GeometryPieceP find(const std::string& label) const;  // nullptr if unknown

  // True for element names that are geometry pieces of Vaango's schema
  // (supported or not): box, sphere, ..., union, difference, intersection.
  static bool is_piece_name(const std::string& element_name);

 private:
  struct Definition {
    std::string canonical;  // the defining element's values, normalised
    std::string where;      // "file:line" of the definition
  };
  std::vector<GeometryPieceP> labelled_;
  std::map<std::string, Definition> definitions_;  // by label
};

}  // namespace tephra
