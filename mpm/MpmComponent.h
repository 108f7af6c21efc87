#pragma once
// The explicit MPM component (update-stress-last, the interpolator of
// <MPM><interpolator>, one velocity field per material coupled by a contact
// model, mpm/contact/). See advance() in MpmComponent.cpp for the step, one
// named phase per line.
#include <array>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/grid/Grid.h"
#include "core/parallel/PatchLayout.h"
#include "core/sim/Component.h"
#include "models/solid/ConstitutiveModel.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/MpmCoupling.h"
#include "mpm/MpmFlags.h"
#include "mpm/EnergyLedger.h"
#include "mpm/NodeGrid.h"
#include "mpm/PrescribedDeformation.h"
#include "mpm/ParticleSeeding.h"
#include "mpm/PatchBand.h"
#include "mpm/RankNodeSums.h"
#include "mpm/PeriodicGrid.h"
#include "mpm/Particles.h"
#include "mpm/contact/ContactModel.h"
#include "mpm/loads/ParticleLoads.h"
#include "mpm/loads/RotatingFrame.h"
#include "mpm/mms/ManufacturedSolution.h"
#include "mpm/shape/Interpolator.h"
#include "mpm/thermal/HeatConduction.h"

namespace tephra {

struct Deck;

struct MpmMaterial {
  int index = 0;                        // material index (order in the deck)
  double density = 0.0;                 // rho0 [kg/m^3]
  double thermal_conductivity = 0.0;    // k [W/(m K)] (mpm/thermal/HeatConduction.h)
  double specific_heat = 0.0;           // c_v [J/(kg K)] (conduction, contact, AV heating, ThermalEnergy)
  double specific_heat_p = 0.0;         // <C_p> [J/(kg K)], default specific_heat (stored only)
  double melt_temperature = 0.0;        // <melt_temp> [K], 0 if absent; read, unused by the implemented models
  double room_temperature = 0.0;        // <room_temp> [K], 0 if absent; read, unused
  ConstitutiveModelP model;
  std::vector<ParticleSource> sources;  // geom_objects, seeded by initialize()
  GridBoundaryConditions bcs;

  Particles particles;
  NodeGrid grid;                        // this step's node fields (and g.* output)
  std::shared_ptr<const ManufacturedSolution> mms;  // <run_MMS_problem>, or null
  // <constitutive_model><initialize_with_body_force>true: its <surface_reference_point>
  // (used with <MPM><initialize_stress_using_body_force>; mpm/loads/BodyForceStress.h).
  std::optional<Vec3> body_force_surface;
  Stencils stencils;                    // scratch of the step
  std::vector<Mat3> L;                  // velocity gradients of the step (empty unless MpmComponent::keeps_L)
  std::vector<Mat3> F_old;              // F_n of the step (the model's input)
  std::vector<double> plastic_work;     // model outputs of the step: dissipated work per V0 [J/m^3]
  std::vector<double> heating;          //   and internal heating rate dT/dt [K/s], added to T in G2P
  ThermalNodes thermal;                 // T_g and (dT/dt)_g; empty unless the run conducts heat
};

struct MpmSetup {
  Grid grid;
  MpmFlags flags;
  Vec3 gravity = Vec3::Zero();
  std::vector<MpmMaterial> materials;
  ContactModelP contact;  // nullptr: null contact (materials do not interact)
  ParticleLoads loads;    // <PhysicalBC><MPM> pressure and force loads (mpm/loads/)
  std::optional<RotatingFrame> rotating_frame;  // <MPM><rotating_coordinate_system>, or none
  std::optional<PrescribedDeformation> prescribed;  // <use_prescribed_deformation>, or none
  bool accumulate_strain_energy = false;  // the deck saves AccStrainEnergy (mpm/StrainWork.h)
  bool accumulate_plastic_work = false;   // the deck saves PlasticWork (mpm/StrainWork.h)
  bool energy_ledger = false;  // the deck saves a label of the kinetic-energy ledger (mpm/EnergyLedger.h)
  bool node_stress = true;  // P2G sums g.stressFS (NodeGrid::node_stress); false unless the deck saves it
                            // (always summed with a contact model: the friction contacts read it)
  bool thermal_contact = false;
  // Keep the particle columns in the scatter order of the stencils
  // (mpm/ParticleReorder.h); false: seeding order (tests compare the two).
  bool reorder_particles = true;
  // Where and why heat conduction cannot run in this scene yet (periodic or
  // axisymmetric grids): a MissingFeature at the first step that conducts.
  std::optional<std::pair<SourceLocation, std::string>> conduction_unsupported;  // <MaterialProperties><MPM><thermal_contact/> (Vaango STThermalContact)
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
  // The start of a step for a redo (MPMICE, core/sim/StepRedo.h;
  // mpm/MpmStepStart.cpp): every particle column of this process and the
  // run totals. The node arrays are not kept: every step resets them before
  // it reads them (NodeGrid::reset in P2G). Buffers kept by the caller: after
  // the first step a save copies into the same storage.
  struct StepStart {
    std::vector<Particles> particles;
    double time = 0, acc_strain_energy = 0, plastic_work = 0, deleted_mass = 0;
    EnergyLedger ledger;
    std::array<Vec3, 6> boundary_force{};
    std::array<double, 6> boundary_area{};
  };
  void save_step_start(StepStart& s) const;
  void restore_step_start(const StepStart& s);

  const Grid& grid() const { return setup_.grid; }
  // L2 displacement error against the manufactured solution of each material
  // (reduction label MMSDisplacementErrorL2); 0 without <run_MMS_problem>.
  double mms_displacement_error() const;

  // Total mass of the particles deleted so far (mpm/ParticleDeletion.h) [kg].
  double deleted_mass() const { return deleted_mass_; }

  const std::vector<MpmMaterial>& materials() const { return setup_.materials; }
  std::vector<MpmMaterial>& materials() { return setup_.materials; }
  const MpmSetup& setup() const { return setup_; }
  // Particle columns kept in scatter order (MpmSetup::reorder_particles; tests compare on/off).
  void set_particle_reordering(bool on) { setup_.reorder_particles = on; }
  // MPMICE: the coupled component's hooks into advance() (null: plain MPM).
  void set_coupling(MpmCoupling* coupling) { coupling_ = coupling; }
  // MPI ranks (mpm/MpmRanks.cpp): which patches this process holds. Under
  // mpirun the patches are spread over the ranks at initialize() (or
  // load_state()); keep_whole_level() before that keeps them all here (the
  // 1-rank reference inside an MPI test).
  void keep_whole_level() { keep_whole_level_ = true; }
  const PatchLayout& layout() const { return layout_; }
  // Node arrays (NodeGrid index order, full grid) summed over the ranks
  // whose node boxes hold the node (mpm/RankNodeSums.h; no-ops in one
  // process): MPMICE's own node scatters (T_g, burn sums, pressure force).
  void sum_node_vectors(std::vector<Vec3>& v);
  void sum_node_doubles(std::vector<double>& v, int width = 1);  // width doubles per node
  // A whole-grid copy of a node array (width doubles per node) on every rank
  // (RankNodeSums::whole; a collective; `data` itself in one process).
  std::vector<double> whole_node_array(const std::vector<double>& data, int width) const;
  // Per-rank output: marks the nodes of `g` this rank writes (MpmRanks.cpp).
  void mark_node_pieces(GridFieldArray& g) const;
  // MPMICE's particle scatters in patch order (mpm/PatchBand.h; docs/parallel.md
  // "MPMICE on ranks"): this step's band widened by `extra` nodes beyond the
  // reach of MPM's stencils (a burn's cell shares land one node below the
  // stencil, a projection of moved particles as far as they move), the same
  // on every rank; null when MPM does not use the band (one patch, periodic,
  // axisymmetric), whose scatters then keep their per-rank sums. The band
  // only grows: MPM's own band sums stay exact with a wider band.
  PatchBand* coupling_band(int extra);
  // A band-summed node array (PatchBand::reduce written into it) combined
  // over the ranks with one non-zero contribution per node (0 + x = x: the
  // one-process bits); no-op in one process.
  void sum_band_node_doubles(double* data, int width);

 private:
  double material_stable_timestep(const MpmMaterial& m) const;
  double courant_number(const MpmMaterial& m, double dt) const;
  void project_to_grid(MpmMaterial& m, int step, const char* phase);
  // with_internal_force: P2G also sums f_int,g (one pass, the same bits); internal_force() then skips its scatter.
  void internal_force(MpmMaterial& m, bool scattered = false);
  void interpolate_to_grid(MpmMaterial& m, int step, const char* phase, bool may_reorder = false,
                           bool with_internal_force = false);
  // Permutes every per-particle column of m (particles, step columns, the
  // velocity-surface flags) into the scatter order of m.stencils (mpm/ParticleReorder.h).
  void reorder_particles(MpmMaterial& m);
  // record_work: add the frictional work to contact_nodes_.friction_work
  // (<do_contact_friction_heating>); false for the re-contact of the MUSL velocity.
  void exchange_momentum(ContactStage stage, double t, double dt, bool record_work = true);
  void boundary_forces();
  void apply_loads(double t);
  void apply_rotating_frame();  // mpm/loads/BodyForcePhase.cpp
  // <PhysicalBC><MPM><velocity> (mpm/loads/VelocityBcPhase.cpp).
  void prescribe_surface_velocities(double t);
  void find_surface_velocity_nodes(double t);
  void impose_surface_velocities(std::size_t material, double t, std::vector<Vec3>& velocity) const;
  // <PhysicalBC><MPM><heat_flux>: q A / N per flagged particle into its heating rate (same file).
  void add_heat_flux_heating(double t, int step);
  void update_stress(MpmMaterial& m, int step, double dt);
  void artificial_viscosity(MpmMaterial& m) const;
  // Thermal phases (mpm/thermal/ThermalPhase.cpp).
  bool thermal_grid_needed() const;
  double thermal_stable_timestep() const;
  void compute_heat_rates(double dt);
  void update_temperatures(MpmMaterial& m, double dt);
  void erode(MpmMaterial& m);  // mpm/ErosionPhase.cpp
  void delete_particles(MpmMaterial& m, const std::vector<Vec3>& v_old, int step);  // mpm/ParticleDeletionPhase.cpp
  void check_temperatures(const MpmMaterial& m, int step) const;  // <test_for_neg_temps_mpm> (same file)
  [[noreturn]] void fail_particle(const MpmMaterial& m, std::size_t i, int step, const std::string& phase,
                                  const std::string& what) const;
  // MPI ranks (mpm/MpmRanks.cpp; all no-ops unless layout_.distributed).
  void lay_out_patches();                  // layout_ from the seeded particles, keep the own ones
  void check_rank_support() const;         // MissingFeature for what does not run on ranks yet
  int patch_of(const Vec3& x) const;       // level patch holding x (nearest interior cell)
  void keep_own_particles(MpmMaterial& m);
  void size_step_columns(MpmMaterial& m);  // L, F_old, plastic_work, heating to the particle count
  // Whether the step keeps the per-particle L column: the model reads it, or
  // artificial viscosity (tr D), or a step that forms F from a stored L
  // (axisymmetric, a deformation-gradient series). Otherwise the fused pass
  // forms F without storing L (72 B per particle less; first_order_F).
  bool keeps_L(const MpmMaterial& m) const;
  void set_node_boxes();                   // this step's node boxes of all ranks (a collective)
  void sum_particles_to_grid(NodeGrid& g); // P2G arrays over the ranks (mpm/RankNodeSums.h)
  double sum_over_ranks(double local) const;  // in rank order, the same bits on every rank
  // Per node of the grid: 1 where this rank is the lowest whose node box holds
  // the node (each node any box holds is counted by exactly one rank), else 0.
  std::vector<char> first_holder_nodes() const;
  RankSum load_totals() const;             // the loads' surface totals over the ranks (mpm/loads/RankSum.h)
  void migrate_particles();                // particles to the ranks owning their new patches
  PatchLayout layout_;
  RankNodeSums node_sums_;
  // Node sums in ascending patch order (mpm/PatchBand.h) with several patches
  // (not periodic, not axisymmetric): the same bits in one process and on ranks.
  PatchBand band_;
  bool band_used_ = false;                 // the last prepare_band set it up (P2G, f_int, MUSL use it)
  PatchBand* prepare_band(MpmMaterial& m); // this step's band for m's stencils; null when not used
  int band_request_ = 0;                   // the reach the last prepare_band asked for (coupling_band adds to it)
  PatchBand* band() { return band_used_ ? &band_ : nullptr; }
  // On ranks, before combining a band-summed array: every band node kept only
  // on the lowest rank whose box holds it, 0 elsewhere, so the combine adds
  // that one value to zeros (mpm/MpmRanks.cpp).
  void keep_band_on_one_rank(double* data, int width);
  bool keep_whole_level_ = false, laid_out_ = false;
  MpmSetup setup_;
  // Stable step for the next advance(), set by the last stress update from
  // c(F_{n+1}) and v_n (Vaango's order); part of the restart state.
  double stable_dt_ = std::numeric_limits<double>::infinity();
  double time_ = 0.0;  // time of the particle state (for the MMS error)
  double deleted_mass_ = 0.0;  // sum of the deleted particles' masses (not part of the restart state)
  bool conducting_ = false;  // this step computed node temperature rates (compute_heat_rates)
  // Contact scratch of the step (normals, positions, field pointers).
  ContactNodes contact_nodes_;
  // v_g of each material as P2G (and the grid BCs) left it, before the
  // interpolated contact; the step's a_g is taken against it (see advance()).
  std::vector<std::vector<Vec3>> p2g_velocity_;
  std::vector<unsigned char> musl_needed_;  // scratch: nodes where step 9 keeps v_g^{n+1} (usl_needed_nodes)
  // Axisymmetric: the full-node volume per node index along r, the fill reference of the
  // MUSL/USL choice (axisymmetric_full_node_volumes, mpm/Axisymmetric.h); empty otherwise.
  std::vector<double> usl_full_volume_x_;
  std::vector<std::vector<Vec3>> musl_velocity_;  // per material: v_g^{n+1} of the updated particle velocities (step 9)
  // BndyForce_<face> = -sum f_int over the face's nodes and all materials,
  // BndyContactArea_<face> = sum V_g / h_normal (Vaango's computeInternalForce),
  // for the faces of MpmFlags::boundary_traction_faces; from the last step.
  std::array<Vec3, 6> boundary_force_{};
  std::array<double, 6> boundary_area_{};
  // AccStrainEnergy: the work of the stresses summed over the steps (mpm/StrainWork.h).
  double acc_strain_energy_ = 0.0;
  // PlasticWork: the models' plastic work summed over the steps (mpm/StrainWork.h).
  double plastic_work_ = 0.0;
  // The kinetic-energy ledger summed over the steps (mpm/EnergyLedger.h; setup_.energy_ledger).
  EnergyLedger ledger_;
  // Per material, the node velocities the ledger compares: v_g (P2G), v*_g, v*_g after the integrated contact.
  std::vector<std::array<std::vector<Vec3>, 3>> ledger_velocity_;
  // Node aliases of the periodic directions (inactive without <periodic>).
  PeriodicNodes periodic_;
  MpmCoupling* coupling_ = nullptr;  // not owned
  // Velocity surfaces of the step, per material: the surface index of each
  // particle (-1: none) and the (node, surface) pairs the flagged particles reach.
  std::vector<std::vector<int>> surface_of_particle_;
  std::vector<std::vector<std::pair<std::size_t, int>>> surface_nodes_;
};

// Reads the MPM parts of the deck (<MPM>, <PhysicalConstants>, <MaterialProperties><MPM>,
// <Grid> and its <BoundaryConditions>). Throws DeckError / MissingFeature.
std::unique_ptr<MpmComponent> make_mpm_component(const Deck& deck);

// Registries for `tephra --list`.
std::vector<std::string> mpm_interpolators();  // {"linear", "gimp", "cpdi", "3rdorderBS"}
std::vector<std::string> mpm_contact_types();  // contact_types() of mpm/contact

}  // namespace tephra
