// <contact> -> a ContactModel. Parameters and defaults as Vaango's contact
// classes read them (ContactFactory, FrictionContact, FrictionContactBard,
// ApproachContact, SingleVelContact, SpecifiedBodyContact). A child that the
// chosen type does not read is a DeckError (Vaango would ignore it silently).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/deck/DeckNode.h"
#include "mpm/contact/ContactTypes.h"

namespace tephra {

namespace {

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1);
}

// <materials>[0,1]</materials>; default: every material.
std::vector<int> read_materials(const DeckNode& contact, int material_count) {
  std::vector<int> out;
  const DeckNode* list = contact.child("materials");
  if (!list) {
    for (int m = 0; m < material_count; ++m) out.push_back(m);
    return out;
  }
  for (double v : list->as_doubles()) {
    if (v != std::floor(v) || v < 0 || v >= material_count)
      list->fail("contact material " + std::to_string(v) + " is not an MPM material index (0.." +
                 std::to_string(material_count - 1) + ")");
    const int m = int(v);
    if (std::find(out.begin(), out.end(), m) != out.end()) list->fail("material listed twice");
    out.push_back(m);
  }
  std::sort(out.begin(), out.end());
  return out;
}

double non_negative(const DeckNode& contact, const char* name, double fallback) {
  const double v = contact.get_double(name, fallback);
  if (!(v >= 0.0) || !std::isfinite(v)) contact.require_child(name).fail(std::string(name) + " must be >= 0");
  return v;
}

FrictionParameters read_friction(const DeckNode& contact, int material_count) {
  FrictionParameters p;
  p.materials = read_materials(contact, material_count);
  p.mu = contact.get_double("mu");  // required, as in Vaango
  if (!(p.mu >= 0.0) || !std::isfinite(p.mu)) contact.require_child("mu").fail("mu must be >= 0");
  p.volume_constraint = non_negative(contact, "volume_constraint", 0.0);
  return p;
}

std::vector<std::pair<double, Vec3>> read_profile(const DeckNode& where, const std::string& file) {
  std::ifstream in(file);
  if (!in) where.fail("cannot open the specified-contact velocity file '" + file + "'");
  std::vector<std::pair<double, Vec3>> rows;
  std::string line;
  int lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    std::istringstream s(line);
    double t, vx, vy, vz;
    if (!(s >> t)) continue;  // blank line
    if (!(s >> vx >> vy >> vz))
      where.fail(file + ":" + std::to_string(lineno) + ": expected 't vx vy vz'");
    if (!rows.empty() && !(t > rows.back().first))
      where.fail(file + ":" + std::to_string(lineno) + ": times must increase");
    rows.push_back({t, Vec3(vx, vy, vz)});
  }
  if (rows.size() < 2) where.fail(file + ": a velocity profile needs at least two rows");
  return rows;
}

SpecifiedParameters read_specified(const DeckNode& contact, int material_count) {
  SpecifiedParameters p;
  p.materials = read_materials(contact, material_count);
  p.master = contact.get_int("master_material", 0);
  if (p.master < 0 || p.master >= material_count)
    contact.require_child("master_material").fail("master_material is not an MPM material index");
  if (std::find(p.materials.begin(), p.materials.end(), p.master) == p.materials.end()) {
    p.materials.push_back(p.master);  // Vaango: the master always takes part
    std::sort(p.materials.begin(), p.materials.end());
  }
  if (const DeckNode* d = contact.child("direction")) {
    const Vec3 v = d->as_vec3();
    for (int i = 0; i < 3; ++i) {
      if (v[i] != 0.0 && v[i] != 1.0) d->fail("direction components must be 0 or 1");
      p.direction[i] = int(v[i]);
    }
  }
  p.normal_only = contact.get_bool("normal_only", false);
  // Vaango's direction-based exchange (SpecifiedBodyContact::computeDirectionBasedExchange)
  // loops over every MPM material and never consults <materials>; only the normal_only
  // exchange skips materials not requested. Stock decks rely on this: the Taylor-impact
  // decks (MPM/Impact/cylinderImpact_*.ups) list only the wall, <materials>[0], and the
  // wall must still stop the rod. So the direction-based rigid body acts on all materials.
  if (!p.normal_only) {
    p.materials.clear();
    for (int m = 0; m < material_count; ++m) p.materials.push_back(m);
  }
  p.volume_constraint = non_negative(contact, "volume_constraint", 0.0);
  p.stop_time = contact.get_double("stop_time", p.stop_time);
  p.velocity_after_stop = contact.get_vec3("velocity_after_stop", Vec3::Zero());
  if (const DeckNode* f = contact.child("filename")) {
    // Relative to the deck's directory, like <include href>.
    std::string path = trimmed(f->text);
    if (!path.empty() && path[0] != '/') {
      const auto slash = f->file.find_last_of('/');
      if (slash != std::string::npos) path = f->file.substr(0, slash + 1) + path;
    }
    p.profile = read_profile(*f, path);
  }
  if (const DeckNode* r = contact.child("master_material_is_rigid"))
    if (!r->as_bool()) r->missing_feature("specified contact with master_material_is_rigid = false");
  return p;
}

// Children each type reads (besides <type>); anything else is an error.
const std::set<std::string>& accepted(const std::string& type) {
  static const std::set<std::string> single = {"materials"};
  static const std::set<std::string> friction = {"materials", "mu", "volume_constraint"};
  static const std::set<std::string> bard = {"materials", "mu", "volume_constraint", "separation_factor",
                                             "one_or_two_step"};
  static const std::set<std::string> specified = {"materials", "master_material", "direction", "normal_only",
                                                  "volume_constraint", "stop_time", "velocity_after_stop",
                                                  "filename", "master_material_is_rigid"};
  static const std::set<std::string> svf = {"materials", "myu", "use_svf"};
  static const std::set<std::string> lr = {"materials", "mu", "volume_constraint", "one_or_two_step"};
  if (type == "friction_LR") return lr;
  if (type == "nodal_svf") return svf;
  if (type == "single_velocity" || type == "null") return single;
  if (type == "friction_bard") return bard;
  if (type == "specified" || type == "rigid") return specified;
  return friction;
}

}  // namespace

std::vector<std::string> contact_types() {
  return {"null",      "single_velocity", "friction",  "friction_bard", "approach",
          "specified", "rigid",           "nodal_svf", "friction_LR"};
}

ContactModelP parse_contact(const DeckNode& contact, int material_count) {
  const DeckNode& type_node = contact.require_child("type");
  const std::string type = trimmed(type_node.text);
  const auto& known = contact_types();
  if (std::find(known.begin(), known.end(), type) == known.end())
    type_node.fail("unknown MPM contact type '" + type + "'");
  for (const DeckNode& c : contact.children) {
    if (c.name == "type") continue;
    if (c.name == "use_hardcoded_normals" && !c.as_bool() && type == "friction") continue;
    if (c.name == "use_hardcoded_normals" || c.name == "hardcoded_normal" || c.name == "vel_fields")
      c.missing_feature("contact <" + c.name + ">");
    if (!accepted(type).count(c.name)) c.fail("<" + c.name + "> is not a parameter of contact type '" + type + "'");
  }

  if (type == "null") {
    // Vaango's NullContact never reads <materials>: stock decks carry lists
    // that name absent materials (inputs/MPM/AA.ups: [1,2,3] with one
    // material), so the list is only read as numbers, not checked against
    // the material count.
    if (const DeckNode* list = contact.child("materials")) list->as_doubles();
    return nullptr;
  }
  if (type == "single_velocity")
    return std::make_unique<SingleVelocityContact>(read_materials(contact, material_count));
  if (type == "friction") return std::make_unique<FrictionContact>(read_friction(contact, material_count));
  if (type == "nodal_svf") {
    // Vaango requires <myu> and <use_svf>, and at most two materials.
    const std::vector<int> mats = read_materials(contact, material_count);
    if (mats.size() != 2) {
      const DeckNode* list = contact.child("materials");
      (list ? *list : contact)
          .fail("nodal_svf acts between exactly two materials (<materials>), found " + std::to_string(mats.size()));
    }
    const double myu = contact.get_double("myu");
    if (!(myu >= 0.0) || !std::isfinite(myu)) contact.require_child("myu").fail("myu must be >= 0");
    return std::make_unique<NodalSvfContact>(mats[0], mats[1], myu, contact.require_child("use_svf").as_bool());
  }
  if (type == "approach") return std::make_unique<ApproachContact>(read_friction(contact, material_count));
  if (type == "friction_LR") {
    const int steps = contact.get_int("one_or_two_step", 2);
    if (steps != 1 && steps != 2) contact.require_child("one_or_two_step").fail("one_or_two_step must be 1 or 2");
    return std::make_unique<FrictionLRContact>(read_friction(contact, material_count), steps);
  }
  if (type == "friction_bard") {
    const double sep = contact.get_double("separation_factor", 9.9e99);
    if (!(sep > 0.0)) contact.require_child("separation_factor").fail("separation_factor must be > 0");
    const int steps = contact.get_int("one_or_two_step", 2);
    if (steps != 1 && steps != 2) contact.require_child("one_or_two_step").fail("one_or_two_step must be 1 or 2");
    return std::make_unique<FrictionBardContact>(read_friction(contact, material_count), sep, steps);
  }
  return std::make_unique<SpecifiedContact>(read_specified(contact, material_count));
}

}  // namespace tephra
