// Deck geometry -> pieces: dispatch on the element name, boolean nodes,
// global labels (Vaango's GeometryPieceFactory rules, made strict) and the
// children of <geom_object>.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <map>

#include "core/deck/DeckNode.h"
#include "core/geometry/Boolean.h"
#include "core/geometry/DeckChecks.h"
#include "core/geometry/GeometryPiece.h"
#include "core/geometry/ParticleFile.h"
#include "core/geometry/Primitives.h"
#include "core/geometry/TriMesh.h"

namespace tephra {

namespace {

using Parser = std::function<std::shared_ptr<GeometryPiece>(const DeckNode&)>;

const std::map<std::string, Parser>& primitive_parsers() {
  static const std::map<std::string, Parser> parsers = {
      {"box", parse_box},           {"sphere", parse_sphere},
      {"cylinder", parse_cylinder}, {"cone", parse_cone},
      {"ellipsoid", parse_ellipsoid}, {"parallelepiped", parse_parallelepiped},
      {"torus", parse_torus},       {"tri", parse_tri},
  };
  return parsers;
}

const std::vector<std::string>& boolean_names() {
  static const std::vector<std::string> names = {"union", "difference", "intersection"};
  return names;
}

// Pieces of Vaango's schema that Tephra does not have yet (MissingFeature).
const std::vector<std::string>& unsupported_piece_names() {
  static const std::vector<std::string> names = {
      "sphere_membrane", "sphere_shell", "cylinder_shell", "plane_shell", "smoothcyl",
      "smooth_sphere",   "abaqus_mesh",  "corrugated",     "null"};
  return names;
}

// <geom_object> children that are not geometry: initial state read by MPM,
// ICE and the models (ups_spec.xml geom_object; DataAnalysis adds <extract>).
const std::vector<std::string>& non_geometry_children() {
  static const std::vector<std::string> names = {
      "res", "velocity", "level", "temperature", "color", "density", "pressure", "moment",
      "volumeFraction", "affineTransformation_A0", "affineTransformation_A1",
      "affineTransformation_A2", "affineTransformation_b", "coeff", "cubicInitialize",
      "exponentialInitialize_1D", "freq", "linearInitialize", "scalar", "sinusoidalInitialize",
      "slope", "triangularInitialize", "comment", "extract"};
  return names;
}

// geom_object children that read geometry from files and are not
// implemented yet (<file> is: core/geometry/ParticleFile.h).
const std::vector<std::string>& unsupported_geom_object_children() {
  static const std::vector<std::string> names = {"image"};
  return names;
}

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

std::vector<std::string> all_piece_names() {
  std::vector<std::string> names;
  for (const auto& [n, p] : primitive_parsers()) names.push_back(n);
  for (const auto& n : boolean_names()) names.push_back(n);
  return names;
}

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

// The element's values in a normal form, so that "[0, 0, 0]" and
// "[0.0,0.0,0.0]" compare equal: two definitions of one label are the same
// geometry exactly when their canonical forms are equal.
std::string canonical_form(const DeckNode& node) {
  std::string s = node.name;
  for (const auto& [k, v] : node.attributes) s += " " + k + "=" + v;
  if (!node.text.empty()) {
    s += "(";
    if (auto nums = parse_number_list(node.text)) {
      for (double x : *nums) {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.17g,", x);
        s += buf;
      }
    } else {
      s += node.text;
    }
    s += ")";
  }
  s += "{";
  for (const auto& c : node.children) s += canonical_form(c) + ";";
  return s + "}";
}

std::string piece_label(const DeckNode& node) {
  // Vaango reads "label", and "name" when there is no label.
  if (auto l = node.attribute("label")) return *l;
  if (auto n = node.attribute("name")) return *n;
  return "";
}

}  // namespace

bool GeometryRegistry::is_piece_name(const std::string& n) {
  return primitive_parsers().count(n) || contains(boolean_names(), n) ||
         contains(unsupported_piece_names(), n);
}

GeometryPieceP GeometryRegistry::find(const std::string& label) const {
  for (const auto& p : labelled_)
    if (p->label == label) return p;
  return nullptr;
}

GeometryPieceP GeometryRegistry::parse_piece(const DeckNode& node) {
  if (!is_piece_name(node.name)) {
    std::string msg = "unknown geometry piece <" + node.name + ">; expected one of: " +
                      join(all_piece_names());
    const std::string near = geometry_detail::nearest_name(node.name, all_piece_names());
    if (!near.empty()) msg += " (did you mean <" + near + ">?)";
    node.fail(msg);
  }
  const std::string label = piece_label(node);

  // A labelled element with no values refers to the earlier definition.
  if (node.children.empty() && node.text.empty()) {
    if (label.empty())
      node.fail("<" + node.name + "> has no values and no label (give its children, or a label "
                "that refers to an earlier piece)");
    GeometryPieceP earlier = find(label);
    if (!earlier) {
      std::vector<std::string> known;
      for (const auto& p : labelled_) known.push_back(p->label);
      std::string msg = "geometry label '" + label + "' is used before it is defined (an element "
                        "with a label and no children refers to an earlier definition)";
      const std::string near = geometry_detail::nearest_name(label, known);
      if (!near.empty()) msg += "; did you mean '" + near + "'?";
      node.fail(msg);
    }
    if (earlier->type() != node.name)
      node.fail("geometry label '" + label + "' refers to a <" + earlier->type() + "> (defined at " +
                definitions_.at(label).where + "), not a <" + node.name + ">");
    return earlier;
  }

  if (contains(unsupported_piece_names(), node.name))
    node.missing_feature("geometry piece <" + node.name + ">");

  std::shared_ptr<GeometryPiece> piece;
  if (auto it = primitive_parsers().find(node.name); it != primitive_parsers().end()) {
    piece = it->second(node);
  } else {
    if (!node.text.empty()) node.fail("<" + node.name + "> takes geometry pieces, not a value");
    std::vector<GeometryPieceP> children;
    for (const auto& c : node.children) {
      if (!is_piece_name(c.name)) {
        std::string msg = "unknown element <" + c.name + "> in <" + node.name +
                          ">; expected geometry pieces (" + join(all_piece_names()) + ")";
        const std::string near = geometry_detail::nearest_name(c.name, all_piece_names());
        if (!near.empty()) msg += " (did you mean <" + near + ">?)";
        c.fail(msg);
      }
      children.push_back(parse_piece(c));
    }
    if (node.name == "difference") {
      if (children.size() < 2)
        node.fail("<difference> needs at least two pieces (the first minus the others), got " +
                  std::to_string(children.size()));
      piece = std::make_shared<DifferencePiece>(std::move(children));
    } else if (node.name == "union") {
      piece = std::make_shared<UnionPiece>(std::move(children));
    } else {
      piece = std::make_shared<IntersectionPiece>(std::move(children));
    }
  }

  if (label.empty()) return piece;
  const std::string canonical = canonical_form(node);
  if (auto it = definitions_.find(label); it != definitions_.end()) {
    if (it->second.canonical == canonical) return find(label);  // same geometry again
    node.fail("geometry label '" + label + "' is already defined at " + it->second.where +
              " with different values; to reuse it write <" + node.name + " label=\"" + label +
              "\"/> with no children, or choose another label");
  }
  piece->label = label;
  labelled_.push_back(piece);
  definitions_[label] = {canonical, node.file + ":" + std::to_string(node.line)};
  return piece;
}

GeometryPieceP GeometryRegistry::parse_geom_object(const DeckNode& geom_object) {
  std::vector<GeometryPieceP> pieces;
  for (const auto& c : geom_object.children) {
    if (is_piece_name(c.name)) {
      pieces.push_back(parse_piece(c));
    } else if (c.name == "file") {
      // Particles listed in a file: seeded point by point, so the file must
      // be the geom_object's only piece.
      if (geom_object.children.end() !=
          std::find_if(geom_object.children.begin(), geom_object.children.end(),
                       [&](const DeckNode& o) { return &o != &c && (is_piece_name(o.name) || o.name == "file"); }))
        c.fail("<file> must be the only geometry piece of its <geom_object> (its particles are the listed points)");
      pieces.push_back(std::make_shared<ParticleFilePiece>(read_particle_file(c)));
    } else if (contains(unsupported_geom_object_children(), c.name)) {
      c.missing_feature("geometry from <geom_object><" + c.name + ">");
    } else if (!contains(non_geometry_children(), c.name)) {
      std::vector<std::string> valid = all_piece_names();
      valid.insert(valid.end(), non_geometry_children().begin(), non_geometry_children().end());
      std::string msg = "unknown element <" + c.name + "> in <geom_object>";
      const std::string near = geometry_detail::nearest_name(c.name, valid);
      if (!near.empty()) msg += " (did you mean <" + near + ">?)";
      c.fail(msg + "; expected a geometry piece (" + join(all_piece_names()) +
             ") or one of: " + join(non_geometry_children()));
    }
  }
  if (pieces.empty())
    geom_object.fail("<geom_object> has no geometry piece (" + join(all_piece_names()) + ")");
  if (pieces.size() == 1) return pieces.front();
  return std::make_shared<UnionPiece>(std::move(pieces));
}

}  // namespace tephra
