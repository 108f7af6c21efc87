#pragma once
// Mass conversion from an MPM solid to an ICE product gas (Vaango theory
// manual sec. 26.1.3 step 4; the burn models of <Models>, Uintah's HEChem
// Simple_Burn / Steady_Burn for the facts). A burn model (SolidBurnModel, an
// IceModel) decides how much solid mass dm_c each surface cell burns in the
// step; the MPMICE component (SolidBurnSupport, mpmice/ParticleBurn.cpp)
// takes that mass from the particles and returns what was actually removed,
// cell by cell, which the model hands to ICE as sources:
//   reactant:  -dm, -P, -E, -dm v_s        product: +dm, +P, +E + dm Enthalpy, +dm v_s
// (mass, momentum, internal energy, specific volume; v_s the solid's
// specific volume in the cell). P and E are the momentum sum_p dm_p v_p and
// energy sum_p dm_p c_v T_p of the removed particle mass, so the particles
// lose exactly what the product gains (mass and momentum to round-off).
#include <cstddef>
#include <string>
#include <vector>

#include "ice/models/IceModel.h"
#include "ice/models/PatchSums.h"

namespace tephra {

class StateArchive;

// One particle of a reactant as a burn model sees it at step 4 (start-of-step
// mass and temperature; MesoBurn's per-particle induction clock).
struct BurnParticle {
  long long id = 0;         // p.particleID (stable)
  std::size_t patch = 0;    // this process's patch index holding the particle's cell
  IntVec3 cell = IntVec3::Zero();
  double mass = 0;          // [kg]
  double temperature = 0;   // [K]
};

// What the particles gave up in each interior cell during one step.
struct BurnedCells {
  CellScalars mass;      // [kg]
  CellVectors momentum;  // [kg m/s]
  CellScalars energy;    // [J]: c_v T of the removed mass
};

class SolidBurnSupport {
 public:
  virtual ~SolidBurnSupport() = default;
  // Corner values wm[n] = w_n m_n of interior cell c for solid s: its 8 nodes'
  // masses (step-1 P2G) times their node -> cell weights (CellProjection.h),
  // node n at corner (n & 1, (n >> 1) & 1, (n >> 2) & 1).
  virtual void corner_masses(std::size_t s, const IntVec3& c, double wm[8]) const = 0;
  // Takes dm[c] (kg, interior cells) from solid s's particles (at most the
  // cell's particle mass) and fills `out` with what was removed.
  virtual void burn_particles(std::size_t s, const CellScalars& dm, BurnedCells& out) = 0;
  // The number of solid s's particles in each interior cell (Uintah's numPPC).
  virtual void particles_per_cell(std::size_t s, CellScalars& out) const = 0;
  // The largest value of solid s's scalar particle history column `name`
  // (ConstitutiveModel::history(), e.g. visco_scram's crackRad) over the
  // particles of each interior cell, 0 where the cell has none. False (out
  // untouched) when the solid's model has no such scalar column.
  virtual bool particle_history_max(std::size_t s, const std::string& name, CellScalars& out) const = 0;
  // Solid s's particles in this process's interior cells (the cell rule of
  // particles_per_cell), in storage order.
  virtual void reactant_particles(std::size_t s, std::vector<BurnParticle>& out) const = 0;
  // Fills the ghost cells of a model's cell field from the patches (and
  // ranks) that own them, for a rule that reads a neighbour's value.
  virtual void exchange_cell_halo(CellScalars& f) = 0;
  // Axisymmetric MPMICE (x = r, per-radian particle masses): the models
  // work per radian (mpmice/AxisymmetricBurn.h), and corner_masses gives
  // the planar-equivalent node masses sum_p m_p (dz/r_p) S_np.
  virtual bool axisymmetric() const = 0;
};

// The cell a burn law sees.
struct BurnCell {
  const IceModelInput* in = nullptr;
  std::size_t patch = 0;
  IntVec3 c = IntVec3::Zero();
  double area = 0;         // burning surface area in the cell [m^2] (SimpleBurn.h)
  double temperature = 0;  // the law's temperature (Simple_Burn: the hottest material above the threshold)
  double pressure = 0;     // the law's pressure (Simple_Burn: press_equil_CC)
  double volume = 0;       // the cell's volume in the model's mass units: V, or r_c dx dy per radian (axisymmetric)
  double solid_mass = 0;   // the solid's cell mass rho_CC volume
  double particles = 0;    // the solid's particles in the cell
  bool surface = true;     // select_cell may clear it: the law needs no burning area (DDT1's detonation), area = 0
};

// The common part of the burn models: surface cells, the particle side,
// sources, totalMassBurned / totalHeatReleased (sums over the step, as
// Uintah's sum_vartype), and the fields <type>.onSurface (area) and
// <type>.BurningCell (1 where mass burned).
class SolidBurnModel : public IceModel {
 public:
  // label_prefix: the prefix of the field labels (Vaango: "SimpleBurn", "SteadyBurn").
  SolidBurnModel(std::string type, std::string label_prefix, std::size_t reactant, std::size_t product,
                 double enthalpy, double threshold_temperature);
  std::string type() const override { return type_; }
  std::size_t reactant() const { return reactant_; }
  void attach(SolidBurnSupport* support) { support_ = support; }
  void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) override;
  void compute_sources(const IceModelInput& in, IceModelSources& out) override;
  std::set<std::string> labels() const override;
  std::vector<ModelField> fields() const override;
  // totalMassBurned, totalHeatReleased of the last step per patch (added in
  // patch order over the MPI ranks by ICE: the same bits on any rank count).
  std::vector<ModelSum> patch_sums() const override {
    return {{"totalMassBurned", &sums_, 0, 1}, {"totalHeatReleased", &sums_, 1, 1}};
  }
  // Simple_Burn's cell rule (the default): a surface cell (SimpleBurn.h) with
  // temperature = the hottest start-of-step temperature among the materials
  // with theta > 0.2 above ThresholdTemp (0 if none), pressure = press_equil_CC.
  // Returns false where the cell cannot burn.
  virtual bool select_cell(const double wm[8], BurnCell& cell) const;
  // The solid's particle count in cell c of patch pi (extra cells: 0).
  double particles_in(std::size_t pi, const IntVec3& c) const { return ppc_[pi](c); }
  std::size_t product() const { return product_; }
  // A scalar particle history column the model reads from its reactant
  // (DDT1's crack model: "crackRad"), "" if none; checked when the MPMICE
  // deck is read (mpmice/MpmIceDeck.cpp).
  virtual std::string required_particle_history() const { return ""; }
  // Restart state that is neither a cell field nor a sum (MesoBurn's
  // per-particle induction clocks), put into / read back from the checkpoint
  // by MpmIceComponent::save_state / load_state (the MPMICE step-redo
  // snapshot is the same archive), under names starting with `prefix`.
  virtual void save_arrays(StateArchive& /*a*/, const std::string& /*prefix*/) const {}
  virtual void load_arrays(const StateArchive& /*a*/, const std::string& /*prefix*/) {}
  const CellScalars& on_surface() const { return on_surface_; }       // burning area per cell of the last step
  const CellScalars& particles_per_cell_field() const { return ppc_; }  // reactant particles per cell of the last step
  double mass_burned_last_step() const { return total_burned_; }        // sum_c dm_c of the last step
  const Vec3& momentum_burned_last_step() const { return total_momentum_; }  // sum_c P_c (to the product)

 protected:
  // The mass the law burns in cell `cell` over dt (before the particle cap).
  virtual double burn_mass(const BurnCell& cell) = 0;
  // The heat released per unit burned mass in interior cell c of patch pi
  // (default: the model's enthalpy; DDT1 differs between its branches).
  virtual double heat_of_reaction(std::size_t /*pi*/, const IntVec3& /*c*/) const { return enthalpy_; }
  SolidBurnSupport& support() const { return *support_; }
  // Per own patch: burned mass, heat released, and the c_v T energy the
  // burned mass carried (columns 0, 1, 2; Test reports 0 and 2).
  const PatchSums& burn_sums() const { return sums_; }

 private:
  std::string type_, prefix_;
  std::size_t reactant_, product_;
  double enthalpy_, threshold_temperature_;
  SolidBurnSupport* support_ = nullptr;
  CellScalars dm_, on_surface_, burning_, ppc_;
  BurnedCells burned_;
  double total_burned_ = 0, total_heat_ = 0;  // this process's, for mass_burned_last_step()
  PatchSums sums_;                              // per own patch: burned mass, heat released, c_v T energy moved
  Vec3 total_momentum_ = Vec3::Zero();
};

}  // namespace tephra
