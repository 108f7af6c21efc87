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
#include "mpm/loads/MomentLoad.h"

namespace tephra {

class DeckNode;

struct PressureSurface {
  // AxiSide, AxiEnd: <axisymmetric_side>, <axisymmetric_end> of a cylinder
  // whose axis is the axisymmetric run's axis (x = r = 0, along y); per-radian
  // loads as Vaango's PressureBC: the side's area R L (2 pi R L / 2 pi) shared
  // by its N particles, the end's force p X_r dr_p per particle (the 1-radian
  // wedge of the annulus of width dr_p = h_x / res_x, <res> of the <pressure>).
  enum class Kind { Box, Cylinder, CylinderEnd, Sphere, AxiSide, AxiEnd };
  Kind kind = Kind::Box;
  double end_dr_fraction = 0.0;               // AxiEnd: 1 / res_x (dr_p = h_x / res_x)
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

// <velocity>: a prescribed velocity v(t) from a vector load curve on the
// particles of a surface (Vaango's VelocityBC; its flags are those of a
// pressure surface: reference position within the particle spacing of the
// box, cylinder or sphere). Tephra imposes it on the grid (Vaango's
// VelocityBC only supplies the value; the application is Tephra's own,
// documented in docs/mpm-loads.md): at the start of step n the flagged
// particles take v_p = v(t_n); every node their stencils reach (S_gp > 0)
// takes v_g = v(t_n) after P2G and v*_g = v(t_{n+1}) with the grid boundary
// conditions (Alg. 8), also in the velocity the gradient is taken from. FLIP
// then gives the flagged particles v_p = v(t_{n+1}) and x_p += dt v(t_{n+1})
// exactly: the surface moves as prescribed and drives the rest of the body
// through the shared nodes, as a Dirichlet face does.
struct VelocitySurface {
  PressureSurface where;   // the surface (its area and pressure curve are unused)
  LoadCurve<Vec3> curve;   // v(t) [m/s]
};

struct ParticleLoads {
  std::vector<PressureSurface> pressure;  // empty unless <use_load_curves>
  std::vector<ForceRegion> force;
  std::vector<VelocitySurface> velocity;  // empty unless <use_load_curves>
  // <heat_flux> (Vaango's HeatFluxBC): a heat flux q(t) [W/m^2] from a load
  // curve into the particles of a surface (flags and area as a pressure
  // surface); each of the N flagged particles (all materials) receives the
  // heat rate Q_p = q(t_n) A / N [W], i.e. dT_p/dt += Q_p / (m_p c_v), so the
  // thermal energy sum m c_v T grows by q A dt per step exactly. Positive q
  // heats. Empty unless <use_load_curves>.
  std::vector<PressureSurface> heat_flux;
  // <moment> (Vaango's MomentBC, mpm/loads/MomentLoad.h): a couple M(t) as
  // particle forces linear in the distance from a neutral plane. Empty
  // unless <use_load_curves>.
  std::vector<MomentSurface> moment;
  bool empty() const {
    return pressure.empty() && force.empty() && velocity.empty() && heat_flux.empty() && moment.empty();
  }
};

// For each particle of `p` (cell size h): the index in loads.velocity of the
// velocity surface it lies on (the last one when several flag it), or -1.
std::vector<int> velocity_surface_of_particles(const ParticleLoads& loads, const Vec3& h, const Particles& p);

// Reads the <load_curve> of `parent` with vector loads ([vx, vy, vz]); as
// parse_scalar_load_curve otherwise.
LoadCurve<Vec3> parse_vector_load_curve(const DeckNode& parent);

// Reads <PhysicalBC> (may be null).
// <arches_heat_flux>, axisymmetric cylinder surfaces and a load-curve scaling
// function other than 1 are MissingFeature; bad values are DeckError.
ParticleLoads parse_particle_loads(const DeckNode* physical_bc, bool use_load_curves);

// Sets p.external_force of every particle of `materials` at time t (cell size h):
// zero, plus the force regions, plus the pressure surfaces, plus the moments.
// On MPI ranks `ranks` sums the surfaces' particle counts and the moments'
// sum d^2 over the ranks (mpm/loads/RankSum.h).
void apply_particle_loads(const ParticleLoads& loads, double t, const Vec3& h,
                          const std::vector<Particles*>& materials, const RankSum& ranks = {});

// Particles on each surface of `surfaces`, summed over `materials` (and over
// the MPI ranks through `ranks`: exact, the counts are integers).
std::vector<long> particles_per_surface(const std::vector<PressureSurface>& surfaces, const Vec3& h,
                                        const std::vector<Particles*>& materials, const RankSum& ranks = {});

// Particles on each pressure surface, summed over `materials` (Vaango's
// materialPointsPerLoadCurve).
std::vector<long> particles_per_pressure_surface(const ParticleLoads& loads, const Vec3& h,
                                                 const std::vector<Particles*>& materials);

}  // namespace tephra
