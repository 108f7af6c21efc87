// The start of a step, kept so that a failed attempt can be put back
// (IceComponent::StepStart, core/sim/StepRedo.h). Copy-assignment into the
// caller's buffers: std::vector keeps its storage when the sizes agree, so
// after the first step a save allocates nothing (session 19: the MPMICE
// snapshot used to build a whole StateArchive, ~20 MB of fresh vectors per
// step, docs/performance.md "MPMICE coupling overhead").
#include "ice/IceComponent.h"

namespace tephra {

void IceComponent::save_step_start(StepStart& s, bool with_lagrangian) const {
  const std::size_t nm = mats_.size();
  s.rho.resize(nm);
  s.temp.resize(nm);
  s.spv.resize(nm);
  s.vel.resize(nm);
  for (std::size_t m = 0; m < nm; ++m) {
    if (!with_lagrangian && setup_.materials[m].lagrangian) continue;  // left empty: not restored
    const IceMaterialFields& f = mats_[m];
    s.rho[m] = f.rho_CC;
    s.temp[m] = f.temp_CC;
    s.spv[m] = f.sp_vol_CC;
    s.vel[m] = f.vel_CC;
  }
  s.press = press_CC_;
  std::size_t nf = 0, ns = 0, nu = 0;
  for (const IceModelP& model : setup_.models) {
    for (auto& [name, f] : model->state_fields()) {
      if (s.model_fields.size() <= nf) s.model_fields.emplace_back();
      s.model_fields[nf++] = *f;
    }
    for (auto& [name, v] : model->state_scalars()) {
      if (s.model_scalars.size() <= ns) s.model_scalars.emplace_back();
      s.model_scalars[ns++] = *v;
    }
    for (auto& [name, sums] : model->state_sums()) {
      if (s.model_sums.size() <= nu) s.model_sums.push_back(*sums);
      else s.model_sums[nu] = *sums;
      ++nu;
    }
  }
  s.model_fields.resize(nf);
  s.model_scalars.resize(ns);
  s.model_sums.erase(s.model_sums.begin() + static_cast<long>(nu), s.model_sums.end());
}

void IceComponent::restore_step_start(const StepStart& s) {
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    if (s.rho[m].size() == 0) continue;  // a solid left out by save_step_start
    IceMaterialFields& f = mats_[m];
    f.rho_CC = s.rho[m];
    f.temp_CC = s.temp[m];
    f.sp_vol_CC = s.spv[m];
    f.vel_CC = s.vel[m];
  }
  press_CC_ = s.press;
  std::size_t nf = 0, ns = 0, nu = 0;
  for (const IceModelP& model : setup_.models) {
    for (auto& [name, f] : model->state_fields()) *f = s.model_fields[nf++];
    for (auto& [name, v] : model->state_scalars()) *v = s.model_scalars[ns++];
    for (auto& [name, sums] : model->state_sums()) *sums = s.model_sums[nu++];
  }
}

}  // namespace tephra
