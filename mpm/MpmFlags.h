#pragma once
// The <MPM> flags block. Explicit time integration with the interpolators
// linear, gimp, cpdi and 3rdorderBS, and the manufactured solutions
// AxisAligned and GeneralizedVortex are implemented; every other flag must either leave the physics
// of what is implemented unchanged or hold Vaango's default value. Anything
// else is a MissingFeature naming the flag (never silently ignored).
#include <string>
#include <vector>

#include "mpm/Erosion.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

class DeckNode;

struct MpmFlags {
  bool explicit_integrator = true;
  InterpolatorSpec interpolator;  // <interpolator>, <cpdi_lcrit>
  std::string mms;                // <run_MMS_problem>, empty = none
  // <boundary_traction_faces>[zminus,zplus]</boundary_traction_faces>: faces
  // (0 x-, 1 x+, 2 y-, 3 y+, 4 z-, 5 z+) whose BndyForce_<face> and
  // BndyContactArea_<face> reductions are computed.
  std::vector<int> boundary_traction_faces;
  // <artificial_viscosity>: Vaango's artificial bulk viscosity (MPMFlags
  // d_artificial_viscosity, ConstitutiveModel::artificialBulkViscosity),
  //   q = rho (A1 c_b |tr D| h + A2 (tr D h)^2)   for tr D < 0, else 0,
  // c_b = sqrt(K/rho), h the mean cell size; -q I is added to the stress in
  // the internal force only (SerialMPM computeInternalForce). Defaults
  // A1 = 0.2, A2 = 2.0 (<artificial_viscosity_coeff1/2>).
  bool artificial_viscosity = false;
  double artificial_viscosity_coeff1 = 0.2;
  double artificial_viscosity_coeff2 = 2.0;
  // <artificial_viscosity_heating> (Vaango's default: the value of
  // <artificial_viscosity>): adds -q tr D / (rho c_v) to the particle
  // heating rate dT/dt (Vaango's include_AV_heating).
  bool artificial_viscosity_heating = false;
  // <do_explicit_heat_conduction> (Vaango's default true): materials with
  // k > 0 conduct heat on the grid (mpm/thermal/HeatConduction.h).
  bool explicit_heat_conduction = true;
  // <artificial_damping_coeff> alpha [1/s] (theory manual eq. 1.65 per unit
  // node mass): a_g = (f_int + f_ext)/m_g - alpha v_g. 0 = no damping.
  double artificial_damping_coeff = 0.0;
  // Particle limits applied after G2P (mpm/ParticleDeletion.h), Vaango's defaults.
  double minimum_particle_mass = 3e-15;      // <minimum_particle_mass> [kg]: lighter particles are deleted
  double maximum_particle_velocity = 3e105;  // <maximum_particle_velocity> [m/s]: clamp or delete
  bool delete_rogue_particles = false;       // <delete_rogue_particles>: delete instead of clamping
  // <do_pressure_stabilization>: F_p takes its cell's mean dilatation
  // (theory manual eqs. 1.82-1.84, mpm/PressureStabilization.h).
  bool pressure_stabilization = false;
  // <erosion algorithm="...">: what happens to the stress of particles the
  // model flags as failed (mpm/Erosion.h).
  ErosionAlgorithm erosion = ErosionAlgorithm::None;
  // <use_load_curves>: accepted; loads (<PhysicalBC>) are checked in MpmDeck.
  bool use_load_curves = false;
  // <initialize_stress_using_body_force>: start the opted-in materials in the
  // stress that balances gravity (mpm/loads/BodyForceStress.h).
  bool initialize_stress_using_body_force = false;
  // <deformation_gradient algorithm=...>: how F_{n+1} follows from l and F_n
  // (Vaango DeformationGradientComputer): first_order F = (I + dt l) F_n;
  // subcycling, taylor_series, cayley_hamilton with <num_terms> (Vaango's
  // default 1). See mpm/DeformationGradient.h.
  std::string deformation_gradient = "first_order";
  // <use_prescribed_deformation> (Vaango also spells it UsePrescribedDeformation):
  // F follows <prescribed_deformation_file> (read in MpmDeck; mpm/PrescribedDeformation.h).
  bool use_prescribed_deformation = false;
  // <axisymmetric>: x = r, y = z, one hoop cell (mpm/Axisymmetric.h); linear, gimp or cpdi.
  bool axisymmetric = false;
  // <do_contact_friction_heating> (Vaango's default false): the frictional
  // work of the Coulomb contacts heats the particles (mpm/contact/FrictionHeating.h).
  bool contact_friction_heating = false;
  // <collinear_bimaterial_contact_normals> (Vaango's default false): body
  // averaged contact normals, g_a <- (g_a - sum_{b != a} m_b g_b / sum m_b)/2
  // (mpm/contact/ContactNormals.h collinear_normals).
  bool collinear_contact_normals = false;
  int deformation_gradient_terms = 1;
  // <test_for_neg_temps_mpm> (also spelled <testForNegTemps_mpm>; Vaango's
  // default true): a particle temperature below 0 K after G2P stops the run
  // (NumericalFailure, exit 4, naming particle, material and step). With
  // false, such a particle is deleted instead (mpm/ParticleDeletion.h).
  bool test_for_negative_temperatures = true;
};

// Reads <MPM> (may be null: all defaults).
MpmFlags parse_mpm_flags(const DeckNode* mpm);

}  // namespace tephra
