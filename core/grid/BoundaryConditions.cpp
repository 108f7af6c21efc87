// Parser for <Grid><BoundaryConditions> (schema: shared/ups_spec/ups_spec.xml,
// Grid/BoundaryConditions). Values follow the label: Velocity is a vector,
// Pressure/Temperature/Density/SpecificVol are scalars; other labels (e.g.
// passive scalars) take whatever form the value is written in.
#include "core/grid/BoundaryConditions.h"

#include <cstring>
#include <set>
#include <tuple>

#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

const char* kFaceNames[6] = {"x-", "x+", "y-", "y+", "z-", "z+"};

struct KindName {
  const char* name;
  BCKind kind;
};
const KindName kKinds[] = {
    {"Dirichlet", BCKind::Dirichlet},   {"Neumann", BCKind::Neumann},
    {"symmetry", BCKind::Symmetry},     {"computeFromDensity", BCKind::ComputeFromDensity},
    {"LODI", BCKind::LODI},             {"Sine", BCKind::Sine},
    {"creep", BCKind::Creep},           {"slip", BCKind::Slip},
    {"Custom", BCKind::Custom},
};
// In Vaango's schema, but not representable here (Arches inlets, file input).
const char* kUnsupportedKinds[] = {"VelocityInlet", "PressureBC", "MomentBC",      "WallBC",
                                   "OutletBC",      "VelocityFileInput", "MassFlowInlet", "Swirl",
                                   "FromFile",      "TurbulentInlet",    "Tabulated"};

// Kinds whose <value> Vaango's schema requires and that the components need.
bool needs_value(BCKind k) { return k == BCKind::Dirichlet || k == BCKind::Neumann; }

GridFace parse_face_name(const DeckNode& face, const std::string& attr, const std::string& v) {
  for (int f = 0; f < 6; ++f)
    if (v == kFaceNames[f]) return static_cast<GridFace>(f);
  face.fail(attr + "=\"" + v + "\" is not a face; expected one of x-, x+, y-, y+, z-, z+");
}

double attr_double(const DeckNode& node, const std::string& name) {
  const std::string text = node.require_attribute(name);
  auto v = parse_double(text);
  if (!v) node.fail("attribute " + name + "=\"" + text + "\" is not a number");
  return *v;
}

double attr_positive(const DeckNode& node, const std::string& name) {
  const double v = attr_double(node, name);
  if (!(v > 0)) node.fail("attribute " + name + " must be > 0");
  return v;
}

Vec3 attr_vec3(const DeckNode& node, const std::string& name) {
  const std::string text = node.require_attribute(name);
  auto v = parse_number_list(text);
  if (!v || v->size() != 3) node.fail("attribute " + name + "=\"" + text + "\" is not a vector [x, y, z]");
  return Vec3((*v)[0], (*v)[1], (*v)[2]);
}

// One of side/circle/rectangle/annulus/ellipse names the face; the others'
// geometry attributes come with it.
std::pair<GridFace, FaceRegionGeometry> read_face(const DeckNode& face) {
  static const std::pair<const char*, FaceRegion> kRegions[] = {{"side", FaceRegion::Side},
                                                                 {"circle", FaceRegion::Circle},
                                                                 {"rectangle", FaceRegion::Rectangle},
                                                                 {"annulus", FaceRegion::Annulus},
                                                                 {"ellipse", FaceRegion::Ellipse}};
  FaceRegionGeometry geo;
  std::optional<GridFace> which;
  for (const auto& [attr, kind] : kRegions) {
    if (auto v = face.attribute(attr)) {
      if (which) face.fail("a <Face> takes exactly one of side, circle, rectangle, annulus, ellipse");
      which = parse_face_name(face, attr, *v);
      geo.kind = kind;
    }
  }
  if (!which) face.fail("a <Face> needs one of the attributes side, circle, rectangle, annulus, ellipse");
  switch (geo.kind) {
    case FaceRegion::Side: break;
    case FaceRegion::Circle:
      geo.origin = attr_vec3(face, "origin");
      geo.radius = attr_positive(face, "radius");
      break;
    case FaceRegion::Rectangle:
      geo.lower = attr_vec3(face, "lower");
      geo.upper = attr_vec3(face, "upper");
      break;
    case FaceRegion::Annulus:
      geo.origin = attr_vec3(face, "origin");
      geo.inner_radius = attr_positive(face, "inner_radius");
      geo.outer_radius = attr_positive(face, "outer_radius");
      if (!(geo.outer_radius > geo.inner_radius)) face.fail("annulus: outer_radius must exceed inner_radius");
      break;
    case FaceRegion::Ellipse:
      geo.origin = attr_vec3(face, "origin");
      geo.major_radius = attr_positive(face, "major_radius");
      geo.minor_radius = attr_positive(face, "minor_radius");
      geo.angle_deg = face.attribute("angle") ? attr_double(face, "angle") : 0.0;
      break;
  }
  geo.name = face.attribute("name").value_or("");
  return {*which, geo};
}

int read_material_id(const DeckNode& bc) {
  const std::string id = bc.require_attribute("id");
  if (id == "all") return kAllMaterials;
  auto n = parse_integer(id);
  if (!n || *n < 0 || *n > 1000000)
    bc.fail("id=\"" + id + "\" must be \"all\" or a material index 0, 1, ...");
  return static_cast<int>(*n);
}

BCKind read_kind(const DeckNode& bc) {
  const std::string var = bc.require_attribute("var");
  for (const KindName& k : kKinds)
    if (var == k.name) return k.kind;
  for (const char* u : kUnsupportedKinds)
    if (var == u) bc.missing_feature("boundary condition var=\"" + var + "\"");
  std::string valid;
  for (const KindName& k : kKinds) valid += std::string(valid.empty() ? "" : ", ") + k.name;
  bc.fail("unknown boundary condition var=\"" + var + "\"; valid: " + valid);
}

void read_value(const DeckNode& bc, BoundaryCondition& out) {
  const DeckNode* value = bc.child("value");
  if (!value) {
    if (needs_value(out.kind))
      bc.fail(std::string(bc_kind_name(out.kind)) + " condition on " + out.label + " needs a <value>");
    return;
  }
  const bool vector_label = out.label == "Velocity";
  const bool scalar_label = out.label == "Pressure" || out.label == "Temperature" || out.label == "Density" ||
                            out.label == "SpecificVol";
  const bool written_as_vector = !value->text.empty() && value->text.front() == '[';
  if (vector_label && !written_as_vector) value->fail("a Velocity value is a vector [vx, vy, vz]");
  if (scalar_label && written_as_vector) value->fail("a " + out.label + " value is a single number");
  out.has_value = true;
  out.is_vector = written_as_vector;
  if (written_as_vector)
    out.vector = value->as_vec3();
  else
    out.scalar = value->as_double();
}

}  // namespace

const char* face_name(GridFace f) { return kFaceNames[static_cast<int>(f)]; }

const char* bc_kind_name(BCKind k) {
  for (const KindName& n : kKinds)
    if (n.kind == k) return n.name;
  return "?";
}

const BoundaryCondition* BoundaryConditions::find(GridFace face, int material, const std::string& label) const {
  const BoundaryCondition* for_all = nullptr;
  for (const BoundaryCondition& bc : list) {
    if (bc.face != face || bc.region.kind != FaceRegion::Side || bc.label != label) continue;
    if (bc.material == material && material != kAllMaterials) return &bc;
    if (bc.material == kAllMaterials && !for_all) for_all = &bc;
  }
  return for_all;
}

std::vector<const BoundaryCondition*> BoundaryConditions::on_face(GridFace face, int material) const {
  std::vector<const BoundaryCondition*> out;
  for (const BoundaryCondition& bc : list)
    if (bc.face == face && (bc.material == material || bc.material == kAllMaterials)) out.push_back(&bc);
  return out;
}

BoundaryConditions parse_boundary_conditions(const DeckNode& grid_section) {
  BoundaryConditions out;
  const DeckNode* block = grid_section.child("BoundaryConditions");
  if (!block) return out;
  if (grid_section.children_named("BoundaryConditions").size() > 1)
    grid_section.children_named("BoundaryConditions")[1]->fail("more than one <BoundaryConditions> block");

  // One whole-face entry per (face, material, label): a second one is a typo
  // (regions such as circles may overlap the face's own condition).
  std::set<std::tuple<int, int, std::string>> seen;
  for (const DeckNode& child : block->children) {
    if (child.name == "LODI") {
      LodiParameters p;
      p.press_infinity = child.get_double("press_infinity");
      p.sigma = child.get_double("sigma", 0.27);  // Uintah LODI2 default
      if (child.has_child("Li_scale")) p.li_scale = child.get_double("Li_scale");
      p.material = child.get_string("material");
      p.where = child.location();
      out.lodi = p;
    } else if (child.name == "SINE_BC") {
      SineParameters p;
      p.omega = child.get_double("omega");
      p.amplitude = child.get_double("A");
      p.reference_pressure = child.get_double("reference_pressure");
      p.reference_velocity = child.get_vec3("reference_velocity");
      p.where = child.location();
      out.sine = p;
    } else if (child.name == "microSlip") {
      MicroSlipParameters p;
      p.alpha_momentum = child.get_double("alpha_momentum");
      p.alpha_temperature = child.get_double("alpha_temperature");
      p.where = child.location();
      out.micro_slip = p;
    } else if (child.name == "Face") {
      const auto [face, region] = read_face(child);
      for (const DeckNode& bcnode : child.children) {
        if (bcnode.name != "BCType") bcnode.fail("a <Face> holds only <BCType> elements");
        BoundaryCondition bc;
        bc.face = face;
        bc.region = region;
        bc.material = read_material_id(bcnode);
        bc.kind = read_kind(bcnode);
        bc.label = bcnode.require_attribute("label");
        if (bc.label.empty()) bcnode.fail("label must not be empty");
        read_value(bcnode, bc);
        bc.where = bcnode.location();
        const auto key = std::make_tuple(static_cast<int>(face), bc.material, bc.label);
        if (region.kind == FaceRegion::Side && !seen.insert(key).second)
          bcnode.fail("a second condition for label " + bc.label + " on face " + face_name(face) +
                      " and the same material id");
        out.list.push_back(bc);
      }
    } else {
      child.fail("unknown element <" + child.name +
                 "> in <BoundaryConditions>; valid: Face, LODI, SINE_BC, microSlip");
    }
  }
  return out;
}

}  // namespace tephra
