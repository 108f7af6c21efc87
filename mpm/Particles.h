#pragma once
// The particles of one MPM material, structure of arrays (DESIGN.md §2.4).
// A new column must also be added to permute_particles (mpm/ParticleReorder.cpp),
// remove_particles (mpm/ParticleDeletion.cpp) and the restart state (MpmComponentOutput.cpp).
// Every column has one entry per particle; all columns have the same length.
#include <cstddef>
#include <vector>

#include "core/base/Types.h"

namespace tephra {

struct Particles {
  std::vector<Vec3> x;             // position [m]                      (p.x)
  std::vector<Vec3> v;             // velocity [m/s]                    (p.velocity)
  std::vector<Vec3> displacement;  // x - x0 [m]                        (p.displacement)
  std::vector<Vec3> external_force;// applied force [N]                 (p.externalforce)
  std::vector<Mat3> F;             // deformation gradient              (p.deformationMeasure)
  std::vector<Mat3> stress;        // Cauchy stress, tension positive   (p.stress)
  std::vector<Mat3> psize;         // reference particle domain in cell units, columns = edge vectors
                                   // (Vaango's pSize: diag(1/res) at seeding); GIMP half-length
                                   // l_d = size(d,d) h_d / 2; CPDI domain F size   (p.size)
  std::vector<double> mass;        // [kg], constant                    (p.mass)
  std::vector<double> volume;      // current volume J*V0 [m^3]         (p.volume)
  std::vector<double> volume0;     // reference volume m/rho0 [m^3]
  std::vector<double> temperature; // [K], carried (no heat conduction) (p.temperature)
  std::vector<double> color;       // geom_object <color>, 0 if absent  (p.color)
  std::vector<double> wave_speed;  // dilatational wave speed [m/s] of the last stress update
  std::vector<double> energy_density; // stored energy per reference volume W(F) [J/m^3]
  std::vector<double> q;           // artificial bulk viscosity [Pa] of the last stress update
                                   // (0 without <artificial_viscosity>; mpm/ArtificialViscosity.h) (p.q)
  std::vector<long long> id;       // unique, stable                    (p.particleID)
  // The internal variables the material's model declares
  // (ConstitutiveModel::history(), same order): history[k] holds
  // components_k values per particle (saved as p.<name>). Sized by
  // init_history() after seeding; add() leaves them alone.
  std::vector<std::vector<double>> history;

  std::size_t size() const { return x.size(); }

  // Appends one particle at rest in the reference state (F = I, zero stress).
  void add(const Vec3& position, const Vec3& velocity, double m, double v0, double temp,
           double col, long long pid, const Mat3& sz = Mat3::Identity()) {
    x.push_back(position);
    v.push_back(velocity);
    displacement.push_back(Vec3::Zero());
    external_force.push_back(Vec3::Zero());
    F.push_back(Mat3::Identity());
    stress.push_back(Mat3::Zero());
    psize.push_back(sz);
    mass.push_back(m);
    volume.push_back(v0);
    volume0.push_back(v0);
    temperature.push_back(temp);
    color.push_back(col);
    wave_speed.push_back(0.0);
    energy_density.push_back(0.0);
    q.push_back(0.0);
    id.push_back(pid);
  }
};

}  // namespace tephra
