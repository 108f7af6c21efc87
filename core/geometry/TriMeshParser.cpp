// <tri> deck element -> TriMeshPiece (see TriMesh.h for the transform).
#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include "core/deck/DeckNode.h"
#include "core/geometry/DeckChecks.h"
#include "core/geometry/TriMesh.h"

namespace tephra {

std::shared_ptr<GeometryPiece> parse_tri(const DeckNode& node) {
  geometry_detail::require_known_children(
      node, {"file_name_prefix", "name", "file_type", "scaling_factor", "translation_vector",
             "reflection_vector", "axis_sequence"});
  const DeckNode* prefix_node = node.child("file_name_prefix");
  if (const DeckNode* old = node.child("name")) {
    if (prefix_node) old->fail("tri: both <file_name_prefix> and <name> given; use one");
    prefix_node = old;
  }
  if (!prefix_node || prefix_node->text.empty())
    node.fail("tri: missing required element <file_name_prefix>");
  if (const DeckNode* ft = node.child("file_type"); ft && ft->text != "tri")
    ft->missing_feature("tri <file_type> '" + ft->text + "' (only .pts/.tri files are read)");

  const double scale =
      node.has_child("scaling_factor") ? geometry_detail::positive_double(node, "scaling_factor") : 1.0;
  const Vec3 translation = node.get_vec3("translation_vector", Vec3::Zero());
  const Vec3 reflection = node.get_vec3("reflection_vector", Vec3::Ones());
  if (!(reflection.cwiseAbs().array() == 1.0).all())
    node.require_child("reflection_vector").fail("tri <reflection_vector> components must be 1 or -1");
  const IntVec3 seq = node.get_int_vec3("axis_sequence", IntVec3(1, 2, 3));
  {
    IntVec3 sorted = seq;
    std::sort(sorted.data(), sorted.data() + 3);
    if (sorted != IntVec3(1, 2, 3))
      node.require_child("axis_sequence").fail("tri <axis_sequence> must be a permutation of 1, 2, 3");
  }

  std::filesystem::path prefix(prefix_node->text);
  if (prefix.is_relative()) prefix = std::filesystem::path(node.file).parent_path() / prefix;

  TriMeshData mesh;
  try {
    mesh = read_tri_files(prefix.string());
  } catch (const std::runtime_error& e) {
    node.fail(std::string("tri: ") + e.what());
  }
  for (Vec3& v : mesh.vertices) {
    Vec3 q;
    for (int i = 0; i < 3; ++i) q[seq[i] - 1] = v[i];
    v = scale * reflection.cwiseProduct(q) + translation;
  }
  const std::string problem = closed_surface_problem(mesh);
  if (!problem.empty()) node.fail("tri mesh '" + prefix.string() + ".tri': " + problem);
  return std::make_shared<TriMeshPiece>(std::move(mesh));
}

}  // namespace tephra
