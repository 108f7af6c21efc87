#pragma once
// The rotating coordinate system of <MPM><rotating_coordinate_system>
// (Vaango MPMFlags d_useCoordRotation; theory manual Alg. 3, with the
// printed branch inverted as the seed inventory's erratum notes: the
// fictitious forces act when the frame rotates, b = g otherwise).
//
// In a frame turning at the constant angular velocity omega = w z_r (w >= 0
// the <rotation_speed_angular> [rad/s], z_r the unit <rotation_axis>) about
// the point x_rc (<rotation_center>), a particle at x with velocity v (both
// measured in the rotating frame) feels, besides gravity g, the accelerations
//   a_centrifugal = omega x (omega x r),   r = x - x_rc,
//   a_coriolis    = 2 omega x v,
// and b_p = g - a_centrifugal - a_coriolis (Alg. 3 line 16). The Euler term
// -(d omega/dt) x r is zero: the deck's speed is constant.
// <body_reference_point> is read (required by Vaango's schema) and not used
// by the body force.
//
// The step evaluates b_p at x_n, v_n (Alg. 2 step 1, before P2G) and adds
// m_p (b_p - g) to the particle's external force (gravity itself enters P2G,
// mpm/Transfers.h), so p.externalforce includes the fictitious forces.
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"

namespace tephra {

class DeckNode;

struct RotatingFrame {
  Vec3 center = Vec3::Zero();       // x_rc [m]
  Vec3 axis = Vec3::UnitX();        // z_r, unit
  double speed = 0.0;               // w [rad/s], >= 0
  Vec3 body_reference_point = Vec3::Zero();  // read, unused

  Vec3 omega() const { return speed * axis; }
  // -a_centrifugal - a_coriolis at position x, velocity v.
  Vec3 fictitious_acceleration(const Vec3& x, const Vec3& v) const;
};

// Reads <rotating_coordinate_system> (the element itself). DeckError for a
// zero axis or a negative speed; the axis is normalised.
RotatingFrame parse_rotating_frame(const DeckNode& node);

// f_ext,p += m_p (-a_centrifugal - a_coriolis)(x_p, v_p) for every particle.
void add_rotating_frame_forces(const RotatingFrame& frame, Particles& p);

}  // namespace tephra
