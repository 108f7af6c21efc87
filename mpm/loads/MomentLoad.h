#pragma once
// <PhysicalBC><MPM><moment> (Vaango's MomentBC): a moment M(t) from a load
// curve applied to the particles of a loaded box face.
//
// Deck (Vaango's input, ups_spec PhysicalBC/MPM/moment):
//   <moment>
//     <geom_object> <box> <min>..</min> <max>..</max> </box> </geom_object>
//     <normal_plane> <normal>[nx,ny,nz]</normal> <point>[px,py,pz]</point> </normal_plane>
//     <load_curve> ... M(t) [N m] ... </load_curve>
//   </moment>
// The box is thin in one direction e (its thickness direction, as for a
// pressure box); the particles whose reference position X lies in the box
// grown by their spacing dxpp are flagged (Vaango's flagMaterialPoint). The
// "normal plane" n . (x - P) = 0 is the neutral plane of the moment: a
// particle at signed distance d_p = n . (X_p - P) from it (n normalised)
// receives a force along e, linear in d_p (the bending stress profile
// sigma = M d / I of beam theory, Vaango's getForceVector):
//     f_p = M(t) d_p / (sum_q d_q^2) e,                                    (1)
// summed over the N flagged particles q of all materials. Then
//     sum_p d_p f_p = M(t) e        (the couple about the neutral plane),
// i.e. the moment vector M(t) (n x e) about P, and the net force
//     sum_p f_p = M(t) (sum_p d_p) / (sum_q d_q^2) e,
// zero when the plane passes through the centroid of the flagged particles
// (the usual neutral axis of a symmetric face).
//
// Difference from Vaango: Vaango scales by the continuum second moment of
// the face's extent, f_p = 3 M d_p / (L1^3 + L2^3) e with L1, L2 the
// distances of the box's two edges from the plane, which gives a total
// moment of M times (number of flagged particles per unit length across
// the face) — M only for one particle per metre. Tephra's discrete
// normalisation (1) makes the applied couple M(t) exactly for any
// particle density. Like Vaango the force direction is the fixed reference
// direction e and the distance is measured on the reference position (the
// flags are stateless; no checkpoint data).
//
// Bad input (DeckError): a surface that is not a box, a box not thin in one
// direction, a zero plane normal, a plane normal not perpendicular to e.
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"
#include "mpm/loads/LoadCurve.h"
#include "mpm/loads/RankSum.h"

namespace tephra {

class DeckNode;

struct MomentSurface {
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // the loaded box
  int thickness_dir = 0;                      // e = unit vector of this direction
  Vec3 plane_normal = Vec3::UnitX();          // n (unit)
  Vec3 plane_point = Vec3::Zero();            // P
  LoadCurve<double> curve;                    // M(t) [N m]

  // True when reference position X lies in the box grown by dxpp.
  bool on_surface(const Vec3& X, const Vec3& dxpp) const;
  // Signed distance d = n . (X - P) from the neutral plane.
  double distance(const Vec3& X) const { return plane_normal.dot(X - plane_point); }
};

// Reads one <moment> element (its children listed above).
MomentSurface parse_moment_surface(const DeckNode& moment);

// Adds the moment forces (1) at time t to p.external_force of the flagged
// particles of `materials` (cell size h); the sums run over all materials
// (and, through `ranks`, over the particles of every MPI rank: mpm/loads/RankSum.h).
void add_moment_forces(const std::vector<MomentSurface>& moments, double t, const Vec3& h,
                       const std::vector<Particles*>& materials, const RankSum& ranks = {});

}  // namespace tephra
