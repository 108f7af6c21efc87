#pragma once
// Particle loads of <PhysicalBC><MPM> (Vaango's MPMPhysicalBC family):
//
//  <pressure>  a pressure p(t) from a load curve on the particles of a loaded
//              surface (Vaango's PressureBC). The surface is a box (one thin
//              side: the loaded plane, normal along its thickness direction),
//              a cylinder (its lateral surface, radial normal; or with
//              <cylinder_end> a thin disc, normal along the axis) or a sphere
//              (radial normal). A particle is on the surface when its
//              reference position X = x - u lies within its own spacing
//              dxpp = h / res of it (box grown by dxpp; cylinder annulus
//              r +- 0.9 min dxpp; disc grown by 0.9 min dxpp along the axis;
//              spherical shell r +- |dxpp|). The total force p A (A the
//              surface's area times <volume_fraction_inside_domain>) is shared
//              equally by the N particles on the surface (all materials):
//                f_p = (p(t) A / N) J F^{-T} N_ref        (Nanson's relation),
//              N_ref the reference normal. Sign (Vaango's): a positive load
//              pulls along the normal: +e_thickness for a box, outward for a
//              cylinder or sphere, (top - bottom)/|top - bottom| for a disc.
//  <force>     a constant force per unit mass on the particles whose
//              reference position is in [lower, upper] (Vaango's ForceBC):
//                f_p = m_p force_density.
//
// Pressure loads act only with <MPM><use_load_curves>true (as in Vaango;
// without it the deck's pressure is ignored with a warning). Vaango also
// drops the <force> loads when load curves are on (applyExternalLoads resets
// the external force); Tephra keeps both, summed.
//
// The loads are stateless: each step recomputes the flags from the
// reference positions (which never change), so a restart needs nothing
// saved. Loads are applied at the start of a step, at t_n with F_n (Vaango's
// applyExternalLoads).
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "mpm/Particles.h"
#include "mpm/loads/LoadCurve.h"

namespace tephra {

class DeckNode;

struct PressureSurface {
  enum class Kind { Box, Cylinder, CylinderEnd, Sphere };
  Kind kind = Kind::Box;
  Vec3 lo = Vec3::Zero(), hi = Vec3::Zero();  // box
  int thickness_dir = 0;                      // box: the direction of its smallest side
  Vec3 bottom = Vec3::Zero(), top = Vec3::Zero();  // cylinder
  Vec3 origin = Vec3::Zero();                 // sphere
  double radius = 0.0;                        // cylinder, sphere
  double area = 0.0;                          // loaded area A [m^2], times volume_fraction_inside_domain
  LoadCurve<double> curve;                    // p(t) [Pa]

  // True when reference position X lies on the loaded surface (particle spacing dxpp).
  bool on_surface(const Vec3& X, const Vec3& dxpp) const;
  // The unit reference normal N_ref for a particle at current position x.
  Vec3 normal(const Vec3& x) const;
};

struct ForceRegion {
  Vec3 lower = Vec3::Zero(), upper = Vec3::Zero();
  Vec3 force_density = Vec3::Zero();  // [N/kg]
};

struct ParticleLoads {
  std::vector<PressureSurface> pressure;  // empty unless <use_load_curves>
  std::vector<ForceRegion> force;
  bool empty() const { return pressure.empty() && force.empty(); }
};

// Reads <PhysicalBC> (may be null). <velocity>, <moment>, <heat_flux>,
// <arches_heat_flux>, axisymmetric cylinder surfaces and a load-curve scaling
// function other than 1 are MissingFeature; bad values are DeckError.
ParticleLoads parse_particle_loads(const DeckNode* physical_bc, bool use_load_curves);

// Sets p.external_force of every particle of `materials` at time t (cell size h):
// zero, plus the force regions, plus the pressure surfaces.
void apply_particle_loads(const ParticleLoads& loads, double t, const Vec3& h,
                          const std::vector<Particles*>& materials);

// Particles on each pressure surface, summed over `materials` (Vaango's
// materialPointsPerLoadCurve).
std::vector<long> particles_per_pressure_surface(const ParticleLoads& loads, const Vec3& h,
                                                 const std::vector<Particles*>& materials);

}  // namespace tephra
