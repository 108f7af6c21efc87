#pragma once
// The explicit ICE component: multi-material, cell-centred, compressible flow
// (Vaango theory manual ch. 24 and the step list of ch. 26 without the MPM
// parts; Uintah's explicit ICE where the manual is silent). advance() in
// IceComponent.cpp lists the step, one named phase per line; docs/algorithms/ice.md
// gives the equations.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/grid/HaloExchange.h"
#include "core/parallel/PatchLayout.h"
#include "core/sim/Component.h"
#include "ice/IceFields.h"
#include "ice/IceSetup.h"
#include "ice/PressureSolver.h"
#include "ice/RadialWeights.h"
#include "ice/models/IceModel.h"

namespace tephra {

struct Deck;

class IceComponent final : public Component {
 public:
  explicit IceComponent(IceSetup setup);

  std::string name() const override { return "ICE"; }
  void initialize() override;
  double stable_timestep() const override;
  void advance(double t, double dt, int step) override;
  void fill_output(const std::set<std::string>& labels, OutputFrame& frame) const override;
  std::map<std::string, std::vector<double>> reductions(const std::set<std::string>& labels) const override;
  std::set<std::string> known_labels() const override;
  void save_state(StateArchive& archive) const override;
  void load_state(const StateArchive& archive) override;

  const IceSetup& setup() const { return setup_; }
  // The patches this process holds (all of them in one process; under
  // mpirun the rank's own, ids = level indices). fields()[m].rho_CC[n]
  // belongs to grid().patches[n].
  const Grid& grid() const { return setup_.grid; }
  // MPI ranks (IceRanks.cpp): the whole level, the patch owners, the
  // reductions. Under mpirun the patches are cut over the ranks at
  // initialize(); keep_whole_level() before initialize() keeps them all in
  // this process with no messages (the 1-rank reference of the MPI tests).
  const PatchLayout& layout() const { return layout_; }
  void keep_whole_level() { keep_whole_level_ = true; }
  const std::vector<IceMaterialFields>& fields() const { return mats_; }
  const CellScalars& press_CC() const { return press_CC_; }
  const CellScalars& press_equil_CC() const { return press_equil_CC_; }
  const CellScalars& delP_Dilatate() const { return delP_Dilatate_; }
  const std::vector<IceModelP>& models() const { return setup_.models; }
  // Implicit pressure: outer iterations of the last step (0 when explicit),
  // and how many steps were redone with half the time step.
  int last_outer_iterations() const { return last_outer_iterations_; }
  int step_restarts() const { return step_restarts_; }
  // The state a failed step attempt must put back (core/sim/StepRedo.h):
  // what the step reads before it writes it -- p_CC (the equilibration's
  // starting guess), rho, u, T, v of every material and the models' state.
  // The other cell fields (p_eq, delP, rho_micro, theta, c, the L_ME
  // copies) are written before they are read in every step. The buffers are
  // kept by the caller across steps: after the first step a save copies into
  // the same storage (no allocation). with_lagrangian = false leaves out the
  // MPMICE solids, whose rho, u, T, v every coupled step rewrites from the
  // particles first (MpmIceComponent::solid_state_to_cells).
  struct StepStart {
    std::vector<CellScalars> rho, temp, spv;
    std::vector<CellVectors> vel;
    CellScalars press;
    std::vector<CellScalars> model_fields;
    std::vector<double> model_scalars;
    std::vector<PatchSums> model_sums;
  };
  void save_step_start(StepStart& s, bool with_lagrangian) const;
  void restore_step_start(const StepStart& s);
  // Implicit pressure or source models: a step that cannot be completed
  // (StepRedoRequest, core/sim/StepRedo.h) is redone with dt/2 (valid after initialize()).
  bool redoes_failed_steps() const { return setup_.implicit.enabled || model_src_ != nullptr; }
  // Row c of the implicit pressure matrix (kCenter, kWest, ...) against the
  // one-sided finite-difference Jacobian -d(rhs_c)/dp_n of the residual at
  // the current iterate (ImplicitPressureCheck.cpp). Entries outside the
  // domain stay 0.
  struct JacobianRow {
    IntVec3 cell = IntVec3::Zero();
    double matrix[kStencilSize] = {}, fd_plus[kStencilSize] = {}, fd_minus[kStencilSize] = {};
  };
  JacobianRow implicit_jacobian_row(double dt, const IntVec3& c);
  // Called at every outer iteration that solves (after the residual and the
  // matrix of the iterate; tests of the outer iteration), and the cell of the
  // largest |residual| of that iterate.
  using OuterIterationHook = std::function<void(IceComponent&, double dt, int step, int outer)>;
  void set_outer_iteration_hook(OuterIterationHook hook) { outer_hook_ = std::move(hook); }
  // Tests: called at the Lagrangian specific-volume check (the last place a
  // step can ask for a redo, IceStep.cpp) with the step's start time and dt;
  // may throw StepRedoRequest as a bad cell would.
  using RedoCheckHook = std::function<void(double t, double dt)>;
  void set_redo_check_hook(RedoCheckHook hook) { redo_check_hook_ = std::move(hook); }
  const IntVec3& max_residual_cell() const { return max_rhs_cell_; }

  // ---- MPMICE hooks (mpmice/MpmIceComponent.cpp). Materials with
  // IceMaterialSpec::lagrangian get their cell state from the particles:
  // `fill` is called by initialize() (before the first equilibration) to set
  // it; the coupled step then calls the two halves of the explicit step
  // around the MPM internal force.
  void set_lagrangian_state_fill(std::function<void(IceComponent&)> fill) { lagrangian_fill_ = std::move(fill); }
  std::vector<IceMaterialFields>& mutable_fields() { return mats_; }
  // Fills the ghost cells of material m's state (rho_CC, vel_CC, temp_CC,
  // sp_vol_CC) from the owning patches: MPMICE after writing a solid's cell state.
  void exchange_cell_state(std::size_t m);
  // MPMICE on MPI ranks (mpmice/MpmIceRanks.cpp): before initialize(), take
  // the MPM component's patch owners (cost: cells + particles) so that a
  // rank's particles lie in its own cells; and fill the ghost cells of a
  // cell field over the own patches from their owners (ice/IceRanks.cpp).
  void adopt_layout(const PatchLayout& layout);
  void exchange_halo(CellScalars& f) { halo_->exchange(f); }
  void exchange_halo(CellVectors& f) { halo_->exchange(f); }
  // Steps 2-6 of the coupled order: equilibration pressure, face velocities
  // and their exchange, model sources (mass conversion, step 4), pressure
  // increment, face pressure.
  void coupled_pressure_phases(double dt, int step);
  // The coupled step's start time t, which the source models see as
  // IceModelInput::time (advance() sets it for ICE alone).
  void set_coupled_step_time(double t) { time_ = t; }
  // Steps 8-12: Lagrangian values, exchange, specific volume, advection of
  // the fluids (not of the lagrangian materials), state check.
  void coupled_transport_phases(double dt, int step);
  // The Lagrangian velocity and temperature after exchange of material m (last step).
  const CellVectors& lagrangian_velocity(std::size_t m) const { return vel_L_[m]; }
  const CellScalars& lagrangian_temperature(std::size_t m) const { return temp_L_[m]; }
  // The mass [kg] of lagrangian material m crossing each face during the
  // coming step (signed, + along the axis), from the particles' motion
  // (mpmice/SolidVolumeFlux.cpp), set before coupled_pressure_phases. Once
  // set, delP uses it for m, and the fluids cross the faces through the area
  // the solids leave (IceLagrangianFlux.cpp).
  FaceScalars& lagrangian_mass_flux(std::size_t m);

 private:
  // Phases of the step (IceStep.cpp), in order.
  void compute_equilibration_pressure(int step);
  void compute_face_velocities(double dt, const CellScalars& press);
  void add_exchange_to_face_velocities(double dt);
  void compute_delP_and_pressure(double dt);
  void compute_face_pressure();
  void lagrangian_values_and_exchange(double dt);
  void compute_diffusion_sources(std::size_t m, std::size_t pi);
  void advect_and_advance(double dt, int step);
  // out = psi of material m after advection, psi_L advected as the content
  // M_L psi_L, a density-like quantity (IceAdvectContent.cpp); needs mass_new_ of m.
  void advect_content(std::size_t m, const CellScalars& psi_L, CellScalars& out, double dt);
  void keep_contents_nonnegative(std::size_t m, const CellScalars& psi_L, CellScalars& flag);  // IceAdvectContent.cpp
  // Total-energy corrections (IceEnergy.cpp, <conserveTotalEnergy>): the
  // face-pressure work in the Lagrangian phase and DeBar's kinetic energy
  // lost by the advection.
  // Mixture (two or more ICE materials, none lagrangian): the cell's
  // corrections and the kinetic energy the momentum exchange removes, split
  // among the materials by mass.
  enum class EnergyCorrection { None, Single, Mixture };
  EnergyCorrection energy_correction() const;
  void face_pressure_work(double dt);
  void add_face_pressure_work(std::size_t m, std::size_t pi, double dt);
  void add_advected_kinetic_energy_loss(std::size_t m);
  void mixture_face_pressure_work(double dt);
  void add_mixture_face_pressure_work(std::size_t pi, double dt);
  void add_exchange_kinetic_energy_loss(std::size_t pi);
  void add_mixture_advected_kinetic_energy_loss();
  // Source models (IceModelStep.cpp, ice/models/): their sources, the volume
  // fractions they change, the mass-exchange pressure term, and their scalars.
  void allocate_model_storage();
  void compute_model_sources(double dt, int step);
  void advect_model_scalars(std::size_t m, double dt);
  // Implicit pressure (ImplicitPressure.cpp): replaces the face velocities,
  // their exchange and the pressure increment of the explicit step.
  void advance_one(double dt, int step);
  void advance_with_restarts(double t, double dt, int step);  // core/sim/StepRedo.h
  std::function<void()> step_snapshot();  // the state a failed attempt puts back; returns the restore
  StepStart redo_start_;                   // its buffers (one snapshot is live at a time: StepRedo.cpp)
  void implicit_pressure_solve(double dt, int step);
  void assemble_pressure_matrix(double dt);
  double pressure_residual(double dt);  // fills rhs_, returns max |rhs| (its cell: max_rhs_cell_)
  std::string residual_where() const;
  // ImplicitPressureCheck.cpp: rhs_c after p_n += shift (p restored, not the face velocities).
  double residual_after_shift(double dt, const IntVec3& n, double shift, const IntVec3& c);
  static bool implicit_trace_enabled();
  void trace_outer_iteration(double dt, int step, int it, double max_rhs);
  void sum_volume_flux_and_kappa(double dt);

  // MPMICE volume fluxes (IceLagrangianFlux.cpp).
  bool has_lagrangian_flux(std::size_t m) const;
  void lagrangian_volume_flux(std::size_t m, FaceScalars& flux) const;
  // Returns whether it scaled (solids present, m a fluid); the face weights chi L are then in lag_weight_.
  bool scale_fluid_flux(std::size_t m, double dt, FaceScalars& flux);
  // The donor outflow bound of ice/AdvectionBounds.h on material m's mass fluxes flux_ (IceLagrangianFlux.cpp).
  void bound_outflow(std::size_t m, double dt, const FaceScalars* weight, double largest_outflow);
  // theta_s,face of solid s on face R of axis d and the solid's phi = u dt/dx there.
  struct SolidFaceFraction {
    double theta = 0, phi = 0;
  };
  SolidFaceFraction solid_face_fraction(std::size_t s, int d, std::size_t pi, const IntVec3& R, double dt) const;
  // Sum over the solids of theta_s,face (at most 1): the values frozen by
  // freeze_solid_face_fractions during a semi-implicit step, else computed.
  double solids_face_fraction(int d, std::size_t pi, const IntVec3& R, double dt) const;
  void freeze_solid_face_fractions(double dt);
  // The implicit matrix's fluid shares F_m/phi_m per face (ImplicitPressureMatrix.cpp).
  void fluid_face_shares(double dt);
  // a_f of the implicit pressure matrix on face R of axis d (ImplicitPressureMatrix.cpp).
  double pressure_face_coefficient(int d, std::size_t pi, const IntVec3& R, double dt, bool boundary, int face) const;
  void fluids_fill_volume_left_by_solids();  // MPMICE initial state (IceComponent.cpp)
  // rho, vel, temp, sp_vol extra cells of material m, then their ghosts in one
  // message round; with `deferred`, the round is begun into it and the caller
  // finishes it (HaloExchange::finish_exchange), overlapping other work.
  void apply_state_bcs(std::size_t m, CellHaloBatch* deferred = nullptr);
  // LODI faces (IceLodiBcs.cpp, ice/Lodi.h): the pressure, the Lagrangian
  // velocity/temperature and the new state of the LODI material.
  void lodi_pressure_bc(std::size_t pi, CellScalars& press);
  // The Pressure BC of every face of patch pi on press (apply_scalar_bc, then
  // the hydrostatic adjustment when gravity is on; LODI faces are the caller's).
  void apply_pressure_bc(std::size_t pi, CellScalars& press);
  void lodi_lagrangian_bc(std::size_t m, std::size_t pi);
  void lodi_state_bc(std::size_t m, std::size_t pi);
  void check_state(int step, const char* phase) const;  // all ranks throw if one finds a bad cell
  void check_state_here(int step, const char* phase) const;
  void lay_out_patches();  // IceRanks.cpp: layout_, the own-patch grid, the halo exchange
  // IceOutput.cpp: the source models' sums over the patches of all ranks.
  void model_reductions(const std::set<std::string>& labels, std::map<std::string, std::vector<double>>& out) const;

  // Axisymmetric ICE: the radial weights of the divergences (null when Cartesian).
  const RadialWeights* radial() const { return setup_.axisymmetric ? &radial_ : nullptr; }

  IceSetup setup_;
  RadialWeights radial_;  // filled by the constructor when setup_.axisymmetric
  PatchLayout layout_;
  bool keep_whole_level_ = false, laid_out_ = false;
  std::unique_ptr<HaloExchange> halo_;
  std::vector<IceMaterialFields> mats_;
  CellScalars press_CC_, press_equil_CC_, delP_Dilatate_, sum_rho_CC_;
  FaceScalars press_FC_;
  // Lagrangian quantities of the step, per material (scratch): mass, and the
  // specific quantities advected with it (velocity, temperature, specific volume).
  std::vector<CellScalars> mass_L_, temp_L_, spv_L_, cv_CC_;  // cv_CC_: c_v per cell for the step
  // Per material: the model that makes it a per-cell ideal gas (SimpleRxn), or null.
  std::vector<IceModel*> cell_gas_;
  void set_up_cell_ideal_gas();
  void fill_cell_gas_cv(std::size_t m, std::size_t pi);  // cv_CC_ = the model's cv, if any
  std::vector<CellScalars> work_corr_;  // face-pressure minus cell-pressure work (IceEnergy.cpp)
  std::vector<CellVectors> vel_L_;
  FaceScalars flux_, flux2_;
  FaceData<Vec3> flux_v_;
  CellScalars dq_, sum_kappa_, mass_new_;
  CellScalars content_;  // M_L psi_L of advect_content (scratch)
  CellVectors dqv_;
  // Viscous force and conduction of the current material (Diffusion.h), and
  // the velocity/temperature with the wall-mirrored extra cells they use.
  CellVectors visc_force_, vel_bc_;
  CellScalars heat_, temp_bc_;
  std::vector<std::vector<double>> beta_;  // thermal expansivity per material (scratch of step 7-9, whole patch storage)
  std::vector<char> diffusion_zero_;  // per patch: visc_force_ and heat_ hold zeros
  // Implicit pressure: the solver, the matrix, the residual and the correction.
  std::unique_ptr<PressureSolver> pressure_solver_;
  StencilCoefficients stencil_;
  CellScalars rhs_, delta_p_;
  int last_outer_iterations_ = 0, step_restarts_ = 0;
  IntVec3 max_rhs_cell_ = IntVec3::Zero();
  OuterIterationHook outer_hook_;
  RedoCheckHook redo_check_hook_;
  // Source models: per-step sources (null without models), delP_MassX, the
  // Lagrangian value of a model scalar, and the time at the start of the step.
  std::unique_ptr<IceModelSources> model_src_;
  CellScalars delP_MassX_, scalar_L_;
  double time_ = 0;
  std::function<void(IceComponent&)> lagrangian_fill_;  // MPMICE: solid cell state from the particles
  std::vector<FaceScalars> lag_mass_flux_;  // MPMICE: per material (empty for fluids), lagrangian_mass_flux()
  FaceScalars lag_chi_;                     // MPMICE: scratch of scale_fluid_flux
  CellScalars lag_limit_;
  FaceScalars lag_weight_;   // chi L of the last scale_fluid_flux, per face
  CellScalars outflow_limit_;  // scratch of bound_outflow
  FaceScalars lag_theta_face_;     // MPMICE implicit: theta_face held over the outer iterations
  bool lag_theta_frozen_ = false;  // set by freeze_solid_face_fractions, cleared at the next step
  std::vector<FaceScalars> imp_share_;  // MPMICE implicit: per fluid, F_m/phi_m on each face
};

// The ICE part of a deck (make_ice_component), with `solids` (an MPMICE run's
// MPM materials, lagrangian) numbered first, as Uintah numbers MPM materials
// before ICE materials: exchange coefficients and boundary-condition ids
// count over all of them. `models`: <Model> types the caller supplies (MPMICE burn models).
IceSetup read_ice_setup(const Deck& deck, std::vector<IceMaterialSpec> solids, const IceModelFactories& models = {});

// Reads <CFD><ICE>, <MaterialProperties><ICE>, <exchange_properties>,
// <PhysicalConstants>, <Grid> and its <BoundaryConditions>.
std::unique_ptr<IceComponent> make_ice_component(const Deck& deck);

std::vector<std::string> ice_advection_types();  // {"FirstOrder", "SecondOrder"}

}  // namespace tephra
