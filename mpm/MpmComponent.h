#pragma once
// The explicit MPM component (update-stress-last, the interpolator of
// <MPM><interpolator>, one velocity field per material coupled by a contact
// model, mpm/contact/). See advance() in MpmComponent.cpp for the step, one
// named phase per line.
#include <array>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "core/grid/Grid.h"
#include "core/sim/Component.h"
#include "models/solid/ConstitutiveModel.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/MpmFlags.h"
#include "mpm/NodeGrid.h"
#include "mpm/ParticleSeeding.h"
#include "mpm/Particles.h"
#include "mpm/contact/ContactModel.h"
#include "mpm/mms/ManufacturedSolution.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

struct Deck;

struct MpmMaterial {
  int index = 0;                        // material index (order in the deck)
  double density = 0.0;                 // rho0 [kg/m^3]
  double thermal_conductivity = 0.0;    // read, unused (no heat conduction yet)
  double specific_heat = 0.0;           // c_v [J/(kg K)] (artificial-viscosity heating)
  double melt_temperature = 0.0;        // <melt_temp> [K], 0 if absent; read, unused by the implemented models
  double room_temperature = 0.0;        // <room_temp> [K], 0 if absent; read, unused
  ConstitutiveModelP model;
  std::vector<ParticleSource> sources;  // geom_objects, seeded by initialize()
  GridBoundaryConditions bcs;

  Particles particles;
  NodeGrid grid;                        // this step's node fields (and g.* output)
  std::shared_ptr<const ManufacturedSolution> mms;  // <run_MMS_problem>, or null
  Stencils stencils;                    // scratch of the step
  std::vector<Mat3> L;                  // velocity gradients of the step
  std::vector<Mat3> F_old;              // F_n of the step (the model's input)
  std::vector<double> plastic_work;     // model outputs of the step: dissipated work per V0 [J/m^3]
  std::vector<double> heating;          //   and internal heating rate dT/dt [K/s] (no heat equation yet)
};

struct MpmSetup {
  Grid grid;
  MpmFlags flags;
  Vec3 gravity = Vec3::Zero();
  std::vector<MpmMaterial> materials;
  ContactModelP contact;  // nullptr: null contact (materials do not interact)
};

class MpmComponent final : public Component {
 public:
  explicit MpmComponent(MpmSetup setup);

  std::string name() const override { return "MPM"; }
  void initialize() override;
  double stable_timestep() const override;
  void advance(double t, double dt, int step) override;
  void fill_output(const std::set<std::string>& labels, OutputFrame& frame) const override;
  std::map<std::string, std::vector<double>> reductions(const std::set<std::string>& labels) const override;
  std::set<std::string> known_labels() const override;
  void save_state(StateArchive& archive) const override;
  void load_state(const StateArchive& archive) override;

  const Grid& grid() const { return setup_.grid; }
  // L2 displacement error against the manufactured solution of each material
  // (reduction label MMSDisplacementErrorL2); 0 without <run_MMS_problem>.
  double mms_displacement_error() const;

  const std::vector<MpmMaterial>& materials() const { return setup_.materials; }
  std::vector<MpmMaterial>& materials() { return setup_.materials; }

 private:
  double material_stable_timestep(const MpmMaterial& m) const;
  void project_to_grid(MpmMaterial& m, int step, const char* phase);
  void interpolate_to_grid(MpmMaterial& m, int step, const char* phase);
  void exchange_momentum(ContactStage stage, double t, double dt);
  void boundary_forces();
  void update_stress(MpmMaterial& m, int step, double dt);
  void artificial_viscosity(MpmMaterial& m) const;
  [[noreturn]] void fail_particle(const MpmMaterial& m, std::size_t i, int step, const std::string& phase,
                                  const std::string& what) const;
  MpmSetup setup_;
  // Stable step for the next advance(), set by the last stress update from
  // c(F_{n+1}) and v_n (Vaango's order); part of the restart state.
  double stable_dt_ = std::numeric_limits<double>::infinity();
  double time_ = 0.0;  // time of the particle state (for the MMS error)
  // Contact scratch of the step (normals, positions, field pointers).
  ContactNodes contact_nodes_;
  // v_g of each material as P2G (and the grid BCs) left it, before the
  // interpolated contact; the step's a_g is taken against it (see advance()).
  std::vector<std::vector<Vec3>> p2g_velocity_;
  // BndyForce_<face> = -sum f_int over the face's nodes and all materials,
  // BndyContactArea_<face> = sum V_g / h_normal (Vaango's computeInternalForce),
  // for the faces of MpmFlags::boundary_traction_faces; from the last step.
  std::array<Vec3, 6> boundary_force_{};
  std::array<double, 6> boundary_area_{};
  // AccStrainEnergy: the stress work sum over the steps (mpm/StrainWork.h); restart state.
  double acc_strain_energy_ = 0.0;
};

// Reads the MPM parts of the deck (<MPM>, <PhysicalConstants>, <MaterialProperties><MPM>,
// <Grid> and its <BoundaryConditions>). Throws DeckError / MissingFeature.
std::unique_ptr<MpmComponent> make_mpm_component(const Deck& deck);

// Registries for `tephra --list`.
std::vector<std::string> mpm_interpolators();  // {"linear", "gimp", "cpdi", "3rdorderBS"}
std::vector<std::string> mpm_contact_types();  // contact_types() of mpm/contact

}  // namespace tephra
