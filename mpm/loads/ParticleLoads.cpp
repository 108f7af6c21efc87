#include "mpm/loads/ParticleLoads.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/LU>

#include "core/base/Log.h"
#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

// The particle's spacing dxpp_d = |psize column d| h_d (psize = diag(1/res)
// at seeding, in cell units).
Vec3 particle_spacing(const Mat3& psize, const Vec3& h) {
  return Vec3(psize.col(0).norm() * h[0], psize.col(1).norm() * h[1], psize.col(2).norm() * h[2]);
}

// Distance of x from the axis bottom -> top, and its axial coordinate s in [0, L] when inside the length.
struct AxisCoordinates {
  double s, r, length;
  Vec3 radial;  // unit vector from the axis to x (zero on the axis)
};
AxisCoordinates axis_coordinates(const Vec3& bottom, const Vec3& top, const Vec3& x) {
  const Vec3 axis = top - bottom;
  const double L = axis.norm();
  const Vec3 a = axis / L;
  const Vec3 d = x - bottom;
  const double s = d.dot(a);
  const Vec3 perp = d - s * a;
  const double r = perp.norm();
  return {s, r, L, r > 0.0 ? Vec3(perp / r) : Vec3::Zero()};
}

void require_known(const DeckNode& n, std::initializer_list<const char*> known) {
  for (const DeckNode& c : n.children) {
    bool ok = false;
    for (const char* k : known) ok = ok || c.name == k;
    if (!ok) {
      std::string list;
      for (const char* k : known) list += (list.empty() ? "" : ", ") + std::string(k);
      c.fail("unknown element <" + c.name + "> in <" + n.name + "> (known: " + list + ")");
    }
  }
}

// The <geom_object> of a <pressure>: one box, cylinder or sphere, given in
// full (Vaango's PressureBC builds the piece from the element itself).
void parse_surface(const DeckNode& geom_object, PressureSurface& s) {
  if (geom_object.children.size() != 1)
    geom_object.fail("the <geom_object> of a <pressure> load holds exactly one box, cylinder or sphere");
  const DeckNode& g = geom_object.children.front();
  if (g.name == "box") {
    require_known(g, {"min", "max"});
    s.kind = PressureSurface::Kind::Box;
    s.lo = g.get_vec3("min");
    s.hi = g.get_vec3("max");
    const Vec3 side = s.hi - s.lo;
    if ((side.array() < 0.0).any()) g.fail("box min must be <= max in every direction");
    // The loaded plane: the thin direction; A = V / smallest side (Vaango), i.e. the product of the other two.
    side.minCoeff(&s.thickness_dir);
    const int a = (s.thickness_dir + 1) % 3, b = (s.thickness_dir + 2) % 3;
    s.area = side[a] * side[b];
    if (!(s.area > 0.0)) g.fail("the pressure box must span a plane (two sides > 0)");
  } else if (g.name == "cylinder") {
    require_known(g, {"bottom", "top", "radius", "cylinder_end", "axisymmetric_end", "axisymmetric_side"});
    s.bottom = g.get_vec3("bottom");
    s.top = g.get_vec3("top");
    s.radius = g.get_double("radius");
    if (!(s.radius > 0.0)) g.require_child("radius").fail("radius must be > 0");
    const double L = (s.top - s.bottom).norm();
    if (!(L > 0.0)) g.fail("cylinder top and bottom must differ");
    const bool axi_end = g.get_bool("axisymmetric_end", false), axi_side = g.get_bool("axisymmetric_side", false);
    if (axi_end || axi_side) {
      // x = r, y = z (the axis), z = the hoop cell: the axis is the line x = 0.
      if (s.bottom[0] != 0.0 || s.top[0] != 0.0 || s.bottom[2] != s.top[2] || !(s.top[1] != s.bottom[1]))
        g.fail("an axisymmetric cylinder surface lies on the axis x = 0 along y (bottom and top differ in y only)");
      if (axi_end && axi_side) g.fail("a cylinder is either <axisymmetric_end> or <axisymmetric_side>");
      if (g.get_bool("cylinder_end", false)) g.fail("<cylinder_end> and an axisymmetric surface exclude each other");
      s.kind = axi_end ? PressureSurface::Kind::AxiEnd : PressureSurface::Kind::AxiSide;
      s.area = axi_side ? s.radius * L : 0.5 * s.radius * s.radius;  // per radian (Vaango's getSurfaceArea)
    } else if (g.get_bool("cylinder_end", false)) {
      s.kind = PressureSurface::Kind::CylinderEnd;
      s.area = std::numbers::pi * s.radius * s.radius;  // one end cap (Vaango: end caps / 2)
    } else {
      s.kind = PressureSurface::Kind::Cylinder;
      s.area = 2.0 * std::numbers::pi * s.radius * L;  // lateral surface
    }
  } else if (g.name == "sphere") {
    require_known(g, {"origin", "radius"});
    s.kind = PressureSurface::Kind::Sphere;
    s.origin = g.get_vec3("origin");
    s.radius = g.get_double("radius");
    if (!(s.radius > 0.0)) g.require_child("radius").fail("radius must be > 0");
    s.area = 4.0 * std::numbers::pi * s.radius * s.radius;
  } else {
    g.fail("a <pressure> surface is a box, cylinder or sphere (Vaango's PressureBC), not <" + g.name + ">");
  }
}

}  // namespace

namespace {

// <load_curve> id and strictly increasing <time_point> (time, load) rows;
// read_load gives one load value (a double or a [x, y, z] vector).
template <class T, class ReadLoad>
LoadCurve<T> parse_load_curve(const DeckNode& parent, ReadLoad read_load) {
  const DeckNode& lc = parent.require_child("load_curve");
  require_known(lc, {"id", "time_point"});
  LoadCurve<T> c;
  c.id = lc.get_int("id");
  for (const DeckNode* tp : lc.children_named("time_point")) {
    require_known(*tp, {"time", "load"});
    const double t = tp->get_double("time");
    if (!c.time.empty() && !(t > c.time.back()))
      tp->require_child("time").fail("load curve times must increase strictly");
    c.time.push_back(t);
    c.load.push_back(read_load(*tp));
  }
  if (c.time.empty()) lc.fail("a <load_curve> needs at least one <time_point>");
  return c;
}

}  // namespace

LoadCurve<double> parse_scalar_load_curve(const DeckNode& parent) {
  return parse_load_curve<double>(parent, [](const DeckNode& tp) { return tp.get_double("load"); });
}

LoadCurve<Vec3> parse_vector_load_curve(const DeckNode& parent) {
  return parse_load_curve<Vec3>(parent, [](const DeckNode& tp) { return tp.get_vec3("load"); });
}

std::vector<int> velocity_surface_of_particles(const ParticleLoads& loads, const Vec3& h, const Particles& p) {
  std::vector<int> surface(p.size(), -1);
  for (std::size_t k = 0; k < loads.velocity.size(); ++k)
    for (std::size_t i = 0; i < p.size(); ++i)
      if (loads.velocity[k].where.on_surface(p.x[i] - p.displacement[i], particle_spacing(p.psize[i], h)))
        surface[i] = int(k);
  return surface;
}

bool PressureSurface::on_surface(const Vec3& X, const Vec3& dxpp) const {
  switch (kind) {
    case Kind::Box:
      return ((X - (lo - dxpp)).array() >= 0.0).all() && (((hi + dxpp) - X).array() >= 0.0).all();
    case Kind::Cylinder: {
      const double tol = 0.9 * dxpp.minCoeff();
      const AxisCoordinates c = axis_coordinates(bottom, top, X);
      return c.s >= 0.0 && c.s <= c.length && c.r >= radius - tol && c.r <= radius + tol;
    }
    case Kind::CylinderEnd: {
      const double tol = 0.9 * dxpp.minCoeff();
      const AxisCoordinates c = axis_coordinates(bottom, top, X);
      return c.s >= -tol && c.s <= c.length + tol && c.r <= radius;
    }
    case Kind::Sphere: {
      const double tol = dxpp.norm(), r = (X - origin).norm();
      return r >= radius - tol && r <= radius + tol;
    }
    case Kind::AxiSide:
    case Kind::AxiEnd: {
      // In the r-z plane: r = X_x, s = the axial distance from bottom (the
      // hoop coordinate X_z plays no part).
      const double tol = 0.9 * std::min(dxpp[0], dxpp[1]);
      const double L = std::abs(top[1] - bottom[1]);
      const double s = (X[1] - bottom[1]) * (top[1] > bottom[1] ? 1.0 : -1.0), r = X[0];
      if (kind == Kind::AxiSide) return s >= 0.0 && s <= L && r >= radius - tol && r <= radius + tol;
      return s >= -tol && s <= L + tol && r <= radius;
    }
  }
  return false;
}

Vec3 PressureSurface::normal(const Vec3& x) const {
  switch (kind) {
    case Kind::Box:
      return Vec3::Unit(thickness_dir);
    case Kind::Cylinder:
      return axis_coordinates(bottom, top, x).radial;
    case Kind::CylinderEnd:
      return (top - bottom).normalized();
    case Kind::Sphere: {
      const Vec3 d = x - origin;
      return d.norm() > 0.0 ? Vec3(d.normalized()) : Vec3::Zero();
    }
    case Kind::AxiSide:
      return Vec3::UnitX();  // e_r, away from the axis (Vaango's radialDirection)
    case Kind::AxiEnd:
      return (top - bottom).normalized();
  }
  return Vec3::Zero();
}

ParticleLoads parse_particle_loads(const DeckNode* physical_bc, bool use_load_curves) {
  ParticleLoads loads;
  if (!physical_bc) return loads;
  for (const DeckNode& mpm : physical_bc->children) {
    if (mpm.name != "MPM") mpm.fail("unknown element <" + mpm.name + "> in <PhysicalBC> (known: MPM)");
    for (const DeckNode& bc : mpm.children) {
      if (bc.name == "pressure") {
        require_known(bc, {"geom_object", "outward_normal", "load_curve", "res", "volume_fraction_inside_domain",
                           "load_curve_scaling_function"});
        PressureSurface s;
        parse_surface(bc.require_child("geom_object"), s);
        s.curve = parse_scalar_load_curve(bc);
        const double fraction = bc.get_double("volume_fraction_inside_domain", 1.0);
        if (!(fraction > 0.0 && fraction <= 1.0))
          bc.require_child("volume_fraction_inside_domain").fail("volume_fraction_inside_domain must be in (0, 1]");
        s.area *= fraction;
        if (s.kind == PressureSurface::Kind::AxiEnd) {
          // Vaango requires <res> with an axisymmetric end: dr_p = h_x / res_x.
          const Vec3 res = bc.get_vec3("res");
          if (!(res[0] >= 1.0)) bc.require_child("res").fail("<res> must be >= 1 in x");
          s.end_dr_fraction = 1.0 / res[0];
        }
        if (const DeckNode* f = bc.child("load_curve_scaling_function")) {
          const auto v = parse_double(f->text);
          if (!v || *v != 1.0)
            f->missing_feature("load_curve_scaling_function '" + f->text + "' (only the constant 1 is implemented)");
        }
        // <outward_normal> acts only with CBDI (use_CBDI_boundary_condition; unimplemented,
        // rejected where it is switched on); <res> only with axisymmetric ends.
        if (const DeckNode* o = bc.child("outward_normal")) o->as_bool();
        if (use_load_curves) loads.pressure.push_back(std::move(s));
        else
          log::warning(bc.file + ":" + std::to_string(bc.line) +
                       ": <pressure> load ignored: Vaango applies pressure loads only with <MPM><use_load_curves>true");
      } else if (bc.name == "force") {
        require_known(bc, {"lower", "upper", "force_density"});
        ForceRegion r;
        r.lower = bc.get_vec3("lower");
        r.upper = bc.get_vec3("upper");
        r.force_density = bc.get_vec3("force_density");
        if (((r.upper - r.lower).array() < 0.0).any()) bc.fail("force region: lower must be <= upper");
        loads.force.push_back(r);
      } else if (bc.name == "velocity") {
        require_known(bc, {"geom_object", "load_curve", "res", "load_curve_scaling_function"});
        VelocitySurface v;
        parse_surface(bc.require_child("geom_object"), v.where);
        v.curve = parse_vector_load_curve(bc);
        if (const DeckNode* f = bc.child("load_curve_scaling_function")) {
          const auto x = parse_double(f->text);
          if (!x || *x != 1.0)
            f->missing_feature("load_curve_scaling_function '" + f->text + "' (only the constant 1 is implemented)");
        }
        if (use_load_curves) loads.velocity.push_back(std::move(v));
        else
          log::warning(bc.file + ":" + std::to_string(bc.line) +
                       ": <velocity> load ignored: Vaango applies load curves only with <MPM><use_load_curves>true");
      } else if (bc.name == "heat_flux") {
        require_known(bc, {"geom_object", "load_curve"});
        PressureSurface s;
        parse_surface(bc.require_child("geom_object"), s);
        s.curve = parse_scalar_load_curve(bc);
        if (use_load_curves) loads.heat_flux.push_back(std::move(s));
        else
          log::warning(bc.file + ":" + std::to_string(bc.line) +
                       ": <heat_flux> load ignored: Vaango applies load curves only with <MPM><use_load_curves>true");
      } else if (bc.name == "moment") {
        MomentSurface m = parse_moment_surface(bc);
        if (use_load_curves) loads.moment.push_back(std::move(m));
        else
          log::warning(bc.file + ":" + std::to_string(bc.line) +
                       ": <moment> load ignored: Vaango applies load curves only with <MPM><use_load_curves>true");
      } else if (bc.name == "arches_heat_flux") {
        bc.missing_feature("MPM physical boundary condition <" + bc.name + ">");
      } else {
        bc.fail("unknown element <" + bc.name + "> in <PhysicalBC><MPM> (known: pressure, force, velocity, "
                "moment, heat_flux, arches_heat_flux)");
      }
    }
  }
  return loads;
}

std::vector<long> particles_per_surface(const std::vector<PressureSurface>& surfaces, const Vec3& h,
                                        const std::vector<Particles*>& materials, const RankSum& ranks) {
  std::vector<long> n(surfaces.size(), 0);
  for (const Particles* p : materials)
    for (std::size_t i = 0; i < p->size(); ++i) {
      const Vec3 X = p->x[i] - p->displacement[i];
      const Vec3 dxpp = particle_spacing(p->psize[i], h);
      for (std::size_t k = 0; k < surfaces.size(); ++k)
        if (surfaces[k].on_surface(X, dxpp)) ++n[k];
    }
  if (!ranks || surfaces.empty()) return n;
  // Over the MPI ranks: the counts as doubles (exact below 2^53).
  const std::vector<double> total = total_over_ranks(ranks, std::vector<double>(n.begin(), n.end()));
  for (std::size_t k = 0; k < n.size(); ++k) n[k] = std::lround(total[k]);
  return n;
}

std::vector<long> particles_per_pressure_surface(const ParticleLoads& loads, const Vec3& h,
                                                 const std::vector<Particles*>& materials) {
  return particles_per_surface(loads.pressure, h, materials);
}

void apply_particle_loads(const ParticleLoads& loads, double t, const Vec3& h,
                          const std::vector<Particles*>& materials, const RankSum& ranks) {
  // Force per particle of each surface: p(t) A / N (Vaango's forcePerParticle), N over all ranks.
  const std::vector<long> count = particles_per_surface(loads.pressure, h, materials, ranks);
  std::vector<double> per_particle(loads.pressure.size(), 0.0);
  for (std::size_t k = 0; k < loads.pressure.size(); ++k)
    if (count[k] > 0) per_particle[k] = loads.pressure[k].curve.at(t) * loads.pressure[k].area / double(count[k]);

  for (Particles* pp : materials) {
    Particles& p = *pp;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 X = p.x[i] - p.displacement[i];
      Vec3 f = Vec3::Zero();
      for (const ForceRegion& r : loads.force)
        if (((X - r.lower).array() >= 0.0).all() && ((r.upper - X).array() >= 0.0).all())
          f += p.mass[i] * r.force_density;
      if (!loads.pressure.empty()) {
        const Vec3 dxpp = particle_spacing(p.psize[i], h);
        for (std::size_t k = 0; k < loads.pressure.size(); ++k) {
          const PressureSurface& s = loads.pressure[k];
          if (!s.on_surface(X, dxpp)) continue;
          // Nanson: n da = J F^{-T} N dA, so the reference normal times J F^{-T}
          // (axisymmetric: J includes the hoop stretch F_thth = r / R).
          const Mat3& F = p.F[i];
          const Vec3 scaled_normal = F.determinant() * (F.inverse().transpose() * s.normal(p.x[i]));
          // Axisymmetric end: the wedge p X_r dr_p of this particle's annulus
          // (Vaango: p x_r dr_p with the current x_r, without Nanson; Tephra
          // takes the reference area and maps it with J F^{-T}).
          const double force = s.kind == PressureSurface::Kind::AxiEnd
                                   ? s.curve.at(t) * X[0] * s.end_dr_fraction * h[0]
                                   : per_particle[k];
          f += force * scaled_normal;
        }
      }
      p.external_force[i] = f;
    }
  }
  add_moment_forces(loads.moment, t, h, materials, ranks);
}

}  // namespace tephra
