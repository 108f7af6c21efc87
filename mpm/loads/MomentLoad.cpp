#include "mpm/loads/MomentLoad.h"

#include <cmath>
#include <string>

#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

// The particle's spacing dxpp_d = |psize column d| h_d (as the pressure flags).
Vec3 spacing_of(const Mat3& psize, const Vec3& h) {
  return Vec3(psize.col(0).norm() * h[0], psize.col(1).norm() * h[1], psize.col(2).norm() * h[2]);
}

void require_known_children(const DeckNode& n, std::initializer_list<const char*> known) {
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

}  // namespace

bool MomentSurface::on_surface(const Vec3& X, const Vec3& dxpp) const {
  return ((X - (lo - dxpp)).array() >= 0.0).all() && (((hi + dxpp) - X).array() >= 0.0).all();
}

MomentSurface parse_moment_surface(const DeckNode& bc) {
  require_known_children(bc, {"geom_object", "normal_plane", "load_curve", "res", "outward_normal"});
  MomentSurface s;
  const DeckNode& geom = bc.require_child("geom_object");
  if (geom.children.size() != 1 || geom.children.front().name != "box")
    geom.fail("the <geom_object> of a <moment> load holds exactly one <box> (Vaango's MomentBC: box surfaces only)");
  const DeckNode& box = geom.children.front();
  require_known_children(box, {"min", "max"});
  s.lo = box.get_vec3("min");
  s.hi = box.get_vec3("max");
  const Vec3 side = s.hi - s.lo;
  if ((side.array() < 0.0).any()) box.fail("box min must be <= max in every direction");
  side.minCoeff(&s.thickness_dir);
  const int a = (s.thickness_dir + 1) % 3, b = (s.thickness_dir + 2) % 3;
  if (!(side[a] > 0.0 && side[b] > 0.0)) box.fail("the moment box must span a plane (two sides > 0)");

  const DeckNode& plane = bc.require_child("normal_plane");
  require_known_children(plane, {"normal", "point"});
  const Vec3 n = plane.get_vec3("normal");
  if (!(n.norm() > 0.0)) plane.require_child("normal").fail("the normal_plane normal must be non-zero");
  s.plane_normal = n.normalized();
  s.plane_point = plane.get_vec3("point");
  // The lever arm d must lie in the loaded face: n perpendicular to the force direction e.
  if (std::abs(s.plane_normal[s.thickness_dir]) > 1e-12)
    plane.require_child("normal").fail(
        "the normal_plane normal must lie in the loaded face (perpendicular to the box's thin direction " +
        std::string(1, "xyz"[s.thickness_dir]) + ")");
  s.curve = parse_scalar_load_curve(bc);
  if (const DeckNode* o = bc.child("outward_normal")) o->as_bool();  // acts only with CBDI, as for <pressure>
  return s;
}

void add_moment_forces(const std::vector<MomentSurface>& moments, double t, const Vec3& h,
                       const std::vector<Particles*>& materials, const RankSum& ranks) {
  // sum_q d_q^2 over the flagged particles of all materials (eq. 1's normalisation), over the ranks.
  std::vector<double> sum_d2(moments.size(), 0.0);
  for (std::size_t k = 0; k < moments.size(); ++k)
    for (const Particles* p : materials)
      for (std::size_t i = 0; i < p->size(); ++i) {
        const Vec3 X = p->x[i] - p->displacement[i];
        const MomentSurface& s = moments[k];
        if (s.on_surface(X, spacing_of(p->psize[i], h))) sum_d2[k] += s.distance(X) * s.distance(X);
      }
  if (!moments.empty()) sum_d2 = total_over_ranks(ranks, std::move(sum_d2));
  for (std::size_t k = 0; k < moments.size(); ++k) {
    const MomentSurface& s = moments[k];
    if (!(sum_d2[k] > 0.0)) continue;  // no flagged particle off the neutral plane: no couple can be applied
    const double scale = s.curve.at(t) / sum_d2[k];
    const Vec3 e = Vec3::Unit(s.thickness_dir);
    for (Particles* pp : materials) {
      Particles& p = *pp;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3 X = p.x[i] - p.displacement[i];
        if (s.on_surface(X, spacing_of(p.psize[i], h))) p.external_force[i] += scale * s.distance(X) * e;
      }
    }
  }
}

}  // namespace tephra
