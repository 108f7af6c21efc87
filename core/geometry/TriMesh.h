#pragma once
// A closed triangulated surface as a solid: `tri` pieces (Vaango reads
// <prefix>.pts, one "x y z" vertex per line, and <prefix>.tri, three 0-based
// vertex indices per line).
//
// inside(x) is the parity of the number of crossings of a ray from x with the
// surface (Jordan-Brouwer: odd = inside a closed surface). The ray is cast
// along +x first, using a 2-D bin grid over (y, z) to find the triangles it
// can meet; when it grazes an edge, a vertex or lies in a triangle's plane, it
// is re-cast in fixed generic directions until no hit is degenerate. Points
// on the surface (within 1e-12 of the mesh size) are inside (closed set).
#include <array>
#include <string>
#include <vector>

#include "core/geometry/GeometryPiece.h"

namespace tephra {

struct TriMeshData {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
};

// Reads <prefix>.pts and <prefix>.tri. Throws std::runtime_error whose
// message names the file and line of the first problem.
TriMeshData read_tri_files(const std::string& prefix);

// Why a mesh is not a closed surface ("" when it is): an index out of range,
// or an edge used by an odd number of triangles (a hole or a dangling face).
std::string closed_surface_problem(const TriMeshData& mesh);

class TriMeshPiece : public GeometryPiece {
 public:
  // The mesh must be closed (closed_surface_problem(mesh) == ""), else
  // std::invalid_argument.
  explicit TriMeshPiece(TriMeshData mesh);
  bool inside(const Vec3& x) const override;
  BoundingBox bounding_box() const override { return box_; }
  std::string type() const override { return "tri"; }

  // |sum over triangles of (a . (b x c)) / 6| (divergence theorem): the
  // enclosed volume of a consistently oriented closed mesh.
  double enclosed_volume() const;
  size_t triangle_count() const { return tris_.size(); }

 private:
  struct Tri {
    Vec3 a, b, c;
  };
  enum class Cast { Outside, Inside, Degenerate };
  Cast cast_along_x(const Vec3& p) const;
  Cast cast_generic(const Vec3& p, const Vec3& dir) const;
  int bin_index(double y, double z) const;

  std::vector<Tri> tris_;
  BoundingBox box_;
  double eps_ = 0;  // distance tolerance: 1e-12 of the bounding-box diagonal
  // Bins over (y, z): bin (j, k) lists the triangles whose (y, z) extent meets it.
  int ny_ = 1, nz_ = 1;
  double y0_ = 0, z0_ = 0, dy_ = 1, dz_ = 1;
  std::vector<std::vector<int>> bins_;
};

class DeckNode;
// <tri>: file_name_prefix (or Vaango's older `name`), optional
// scaling_factor s, reflection_vector r, translation_vector t and
// axis_sequence; a vertex read as (p_1, p_2, p_3) becomes, with
// q[axis_sequence_i - 1] = p_i, x = s (r .* q) + t (Vaango's order). The
// prefix is relative to the folder of the file that holds the element.
std::shared_ptr<GeometryPiece> parse_tri(const DeckNode& node);

}  // namespace tephra
