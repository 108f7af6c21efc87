#pragma once
#include <limits>
// Models of <Models><Model type=...> (and <CFD><ICE><ADD_HEAT>) that add
// per-cell sources of mass, momentum, energy and specific volume to the ICE
// step, between named materials (Uintah's modelMass_src, modelMom_src,
// modelEng_src, modelVol_src). The ICE step calls compute_sources once per
// model per step (the loops are inside the model) at the place Uintah's ICE
// calls computeModelSources: after the equilibration pressure and the face
// velocities, before updateVolumeFraction and the pressure increment
// (ICE.cc scheduleTimeAdvance). ice/IceModelStep.cpp applies the sources.
//
// Source units (per cell, per step, as Uintah): mass [kg], momentum [kg m/s],
// energy [J], specific volume [m^3] (mass x specific volume). A conversion of
// reactant into product moves equal and opposite amounts, so reactant +
// product conserve mass, momentum and energy to round-off (energy up to the
// released heat E0 dm).
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "ice/IceFields.h"
#include "ice/models/PatchSums.h"

namespace tephra {

class DeckNode;
class StateArchive;
struct IceSetup;
struct IceMaterialSpec;

// What a model reads, at its place in the step. rho_CC, sp_vol_CC and
// vol_frac_CC are the equilibration results of this step; vel_CC and temp_CC
// are the state at the start of the step (Uintah: old_dw); cv_CC the specific
// heat per cell at the start of the step.
struct IceModelInput {
  const Grid& grid;
  const std::vector<IceMaterialSpec>& specs;
  const std::vector<IceMaterialFields>& mats;
  const std::vector<CellScalars>& cv_CC;
  const CellScalars& press_equil_CC;
  double time = 0;  // time at the start of the step
  double dt = 0;
  int step = 0;
};

// The per-material sources the models add to (zeroed by the step).
struct IceModelSources {
  std::vector<CellScalars> mass, energy, sp_vol;
  std::vector<CellVectors> momentum;
};

// A scalar carried with a material's mass (PassiveScalar): the step advects
// q with the material's mass fluxes, q_new = (M_L (q + src) + div F)/M_new,
// src the model's per-step source (Uintah's TransportedVariable).
struct TransportedScalar {
  std::size_t material = 0;
  CellScalars* q = nullptr;
  const CellScalars* src = nullptr;  // may be null
};

// A cell field a model saves under a Vaango label (F, delF, ...).
struct ModelField {
  std::string label;
  int material = 0;
  const CellScalars* field = nullptr;
};

// A per-cell ideal-gas mixture a model imposes on one ideal_gas material
// (SimpleRxn): c_v and gamma per cell replace the material's <specific_heat>
// and <gamma> in the EOS p = (gamma - 1) rho cv T, in the speed of sound and
// in the energy M cv T (every stored cell, extra cells too).
struct CellIdealGas {
  std::size_t material = 0;
  const CellScalars* cv = nullptr;
  const CellScalars* gamma = nullptr;
};

// A reduction a model keeps per patch (PatchSums): the label's values are
// columns [first, first + width) of `sums`, added over the patches of all
// ranks in ascending patch id by the component (the same bits on any rank
// count, issue 7).
struct ModelSum {
  std::string label;
  const PatchSums* sums = nullptr;
  int first = 0;
  int width = 1;
};

class IceModel {
 public:
  virtual ~IceModel() = default;
  virtual std::string type() const = 0;
  // Allocates the model's own fields (after the ICE state exists).
  virtual void initialize(const Grid& grid, const std::vector<IceMaterialFields>& mats) = 0;
  virtual void compute_sources(const IceModelInput& in, IceModelSources& out) = 0;
  virtual std::vector<TransportedScalar> transported() { return {}; }
  // Mixture properties (null when the model has none). The step calls
  // update_cell_properties() after the model's scalars are advected, and
  // initialize_state() once after initialize(), before the first
  // equilibration (to set the initial mixture density).
  virtual const CellIdealGas* cell_ideal_gas() const { return nullptr; }
  virtual void update_cell_properties() {}
  virtual void initialize_state(std::vector<IceMaterialFields>&) {}
  // The largest stable time step of the model's own explicit terms (e.g. the
  // forward-Euler limit of a scalar's diffusion); infinity when it has none.
  virtual double stable_timestep() const { return std::numeric_limits<double>::infinity(); }
  // Output: labels it can save, the cell fields and the reduction sums.
  virtual std::set<std::string> labels() const { return {}; }
  virtual std::vector<ModelField> fields() const { return {}; }
  // Sums kept per patch (preferred: exact across ranks, see ModelSum). The
  // plain `reductions` are per process; on several ranks the component adds
  // the processes' values (correct to round-off, not bit for bit).
  virtual std::vector<ModelSum> patch_sums() const { return {}; }
  // By default the patch sums of this process added in patch order (the
  // whole answer in one process; the component asks for the labels of
  // patch_sums() through them, not through this).
  virtual void reductions(const std::set<std::string>& labels, std::map<std::string, std::vector<double>>& out) const {
    for (const ModelSum& s : patch_sums()) {
      if (!labels.count(s.label)) continue;
      std::vector<double> v(std::size_t(s.width), 0.0);
      for (const PatchPartial& row : s.sums->partials())
        for (int c = 0; c < s.width; ++c) v[std::size_t(c)] += row.values[std::size_t(s.first + c)];
      out[s.label] = v;
    }
  }
  // Restart: fields whose value carries over between steps, and sums.
  virtual std::vector<std::pair<std::string, CellScalars*>> state_fields() { return {}; }
  virtual std::vector<std::pair<std::string, double*>> state_scalars() { return {}; }
  // Per-patch sums that carry over (the totals are saved; a restart puts them
  // in level patch 0's row, PatchSums::restore_totals).
  virtual std::vector<std::pair<std::string, PatchSums*>> state_sums() { return {}; }
};

using IceModelP = std::shared_ptr<IceModel>;

// Models a coupled component supplies (MPMICE's burn models, mpmice/): type
// -> factory, tried before the ICE ones.
using IceModelFactory = std::function<IceModelP(const DeckNode& model, const IceSetup& setup)>;
using IceModelFactories = std::map<std::string, IceModelFactory>;

// <Models><Model type=...> and <CFD><ICE><ADD_HEAT> of the deck, checked
// against the ICE materials of `setup` (names or indices). Unknown type:
// DeckError listing the registered ones; a Vaango type Tephra lacks: exit 3.
std::vector<IceModelP> parse_ice_models(const DeckNode& root, const IceSetup& setup,
                                        const IceModelFactories& extra = {});

// Registered <Model type> keys (tephra --list Model).
std::vector<std::string> ice_model_types();

}  // namespace tephra
