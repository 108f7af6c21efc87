#pragma once
// MPMICE: MPM solids and ICE fluids on one grid (Vaango theory manual ch. 26;
// the 14-step order of sec. 26.1.3, docs/mpmice.md). The component owns an
// MpmComponent and an IceComponent; the MPM materials also appear in the ICE
// material list (first, as in Uintah's numbering) as "lagrangian" materials
// whose cell state comes from the particles every step and whose equation of
// state is the constitutive model's pressure hook (mpmice/SolidEos.h). The
// coupled step is advance() -> MpmComponent::advance, which calls the hooks
// of mpm/MpmCoupling.h at the three places the order needs the grid.
#include <memory>
#include <vector>

#include "core/sim/Component.h"
#include "ice/IceComponent.h"
#include "mpm/MpmComponent.h"
#include "mpm/MpmCoupling.h"
#include "mpmice/SolidBurn.h"

namespace tephra {

struct Deck;
struct MpmIceNodeWeights;  // MpmIceTransfers.cpp

class MpmIceComponent final : public Component, private MpmCoupling, private SolidBurnSupport {
 public:
  MpmIceComponent(std::unique_ptr<MpmComponent> mpm, std::unique_ptr<IceComponent> ice, double p_ref);

  std::string name() const override { return "MPMICE"; }
  void initialize() override;
  double stable_timestep() const override;
  void advance(double t, double dt, int step) override;
  void fill_output(const std::set<std::string>& labels, OutputFrame& frame) const override;
  std::map<std::string, std::vector<double>> reductions(const std::set<std::string>& labels) const override;
  std::set<std::string> known_labels() const override;
  void save_state(StateArchive& archive) const override;
  void load_state(const StateArchive& archive) override;

  // MPI ranks: keep every patch in this process (the 1-rank reference of the
  // MPI tests), before initialize(); MPM's layout is then ICE's too.
  void keep_whole_level() { mpm_->keep_whole_level(); }
  const MpmComponent& mpm() const { return *mpm_; }
  MpmComponent& mpm() { return *mpm_; }
  // The particle queries the burn models make (DDT1's crack-history lookup; tests).
  const SolidBurnSupport& burn_support() const { return *this; }
  const IceComponent& ice() const { return *ice_; }
  IceComponent& mutable_ice() { return *ice_; }  // tests: hooks of the implicit pressure
  // Coupled steps redone with dt/2 so far (each redo counts once; core/sim/StepRedo.h).
  int step_redos() const { return step_redos_; }
  // Particle pressure p_p - p_ref of MPM material m from the last step (step 7).
  const std::vector<double>& particle_pressure(std::size_t m) const { return particle_pressure_[m]; }

 private:
  // The step-redo snapshot (advance()): save into / restore from the buffers below.
  void save_step_start();
  void restore_step_start();

  // MpmCoupling (called from MpmComponent::advance).
  void after_interpolate_to_grid(double t, double dt, int step) override;
  void add_internal_forces() override;
  void after_integrate_grid(double dt, int step) override;

  // The phases of the coupled step (MpmIceTransfers.cpp).
  void solid_state_to_cells();                 // step 1: nodes -> cells, rho_micro from the solid EOS
  void solid_mass_fluxes(double dt);           // step 1: the solids' face mass fluxes of the step (SolidVolumeFlux.cpp)
  void pressure_to_particles();                // step 7: p_CC -> nodes -> particles
  void cell_changes_to_nodes_and_particles();  // step 13: dv_CC -> v*_g, dT_CC -> T_p

  // SolidBurnSupport (step 4, burn models; ParticleBurn.cpp).
  void corner_masses(std::size_t s, const IntVec3& c, double wm[8]) const override;
  void burn_particles(std::size_t s, const CellScalars& dm, BurnedCells& out) override;
  void particles_per_cell(std::size_t s, CellScalars& out) const override;
  bool particle_history_max(std::size_t s, const std::string& name, CellScalars& out) const override;
  void reactant_particles(std::size_t s, std::vector<BurnParticle>& out) const override;
  void exchange_cell_halo(CellScalars& f) override { ice_->exchange_halo(f); }
  bool axisymmetric() const override { return ice_->setup().axisymmetric; }
  // MPI ranks: burned cell shares of other ranks' cells to their owners (ParticleBurn.cpp).
  // in_band: cells whose sums every rank holds whole already (mpmice/BandScatter.h): not sent.
  void send_burned_shares(const std::vector<int>& patch_of, const std::vector<char>& in_band, std::vector<double>& mass,
                          std::vector<Vec3>& momentum, std::vector<double>& energy) const;

  std::unique_ptr<MpmComponent> mpm_;
  std::unique_ptr<IceComponent> ice_;
  double p_ref_;
  bool initialized_ = false;
  int step_redos_ = 0;
  std::vector<std::vector<double>> particle_pressure_;  // per MPM material: p_p - p_ref
  Particles flux_particles_;  // scratch of solid_mass_fluxes
  NodeGrid flux_grid_;
  NodeGrid burn_grid_;
  // Scratch of the transfers kept across steps (MpmIceTransfers.cpp): the
  // node weights of each solid (fixed grid and symmetry faces), sum m T at
  // the nodes, the solid's cell changes du, dT.
  std::vector<std::shared_ptr<const MpmIceNodeWeights>> node_weights_;
  std::vector<double> node_mT_;
  // Axisymmetric: per MPM material, per node, the share m_g^+/m_g of its mass
  // projected to the cell above it in r (solid_state_to_cells; used by
  // cell_changes_to_nodes_and_particles, mpmice/NodeAverages.h).
  std::vector<std::vector<double>> node_share_above_;
  // Axisymmetric with burn models: per MPM material, per node, the
  // planar-equivalent node mass sum_p m_p (dz/r_p) S_gp of this step
  // (solid_state_to_cells; corner_masses, mpmice/AxisymmetricBurn.h).
  std::vector<std::vector<double>> node_planar_mass_;
  CellVectors change_du_;
  CellScalars change_dT_;
  // The step-redo snapshot's buffers, kept across steps (advance(); one
  // snapshot is live at a time, core/sim/StepRedo.cpp).
  MpmComponent::StepStart mpm_start_;
  IceComponent::StepStart ice_start_;
  StateArchive burn_start_;
  std::vector<std::vector<double>> node_temperature_;  // per MPM material: T_g of step 1 (g.temperature)  // scratch of burn_particles: the node sums of the removed particle mass
};

// Reads an <SimulationComponent type="mpmice"> deck: the MPM parts
// (make_mpm_component) and the ICE parts with the MPM materials numbered first
// (read_ice_setup). Unsupported pieces are MissingFeature naming them.
std::unique_ptr<MpmIceComponent> make_mpmice_component(const Deck& deck);

}  // namespace tephra
