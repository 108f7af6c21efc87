#include "mpm/loads/RotatingFrame.h"

#include <Eigen/Geometry>

#include "core/deck/DeckNode.h"

namespace tephra {

Vec3 RotatingFrame::fictitious_acceleration(const Vec3& x, const Vec3& v) const {
  const Vec3 w = omega();
  return -w.cross(w.cross(Vec3(x - center))) - 2.0 * w.cross(v);
}

RotatingFrame parse_rotating_frame(const DeckNode& node) {
  for (const DeckNode& c : node.children)
    if (c.name != "rotation_center" && c.name != "rotation_axis" && c.name != "rotation_speed_angular" &&
        c.name != "body_reference_point")
      c.fail("unknown element <" + c.name + "> in <rotating_coordinate_system> (known: rotation_center, "
             "rotation_axis, rotation_speed_angular, body_reference_point)");
  RotatingFrame f;
  f.center = node.get_vec3("rotation_center");
  const Vec3 axis = node.get_vec3("rotation_axis");
  if (!(axis.squaredNorm() > 0.0)) node.require_child("rotation_axis").fail("rotation_axis has zero length");
  f.axis = axis.normalized();
  f.speed = node.get_double("rotation_speed_angular");
  if (!(f.speed >= 0.0)) node.require_child("rotation_speed_angular").fail("rotation_speed_angular must be >= 0");
  f.body_reference_point = node.get_vec3("body_reference_point");
  return f;
}

void add_rotating_frame_forces(const RotatingFrame& frame, Particles& p) {
  const long n = static_cast<long>(p.size());
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (long i = 0; i < n; ++i) p.external_force[i] += p.mass[i] * frame.fictitious_acceleration(p.x[i], p.v[i]);
}

}  // namespace tephra
