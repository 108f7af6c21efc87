// IceComponent: saved labels (Uintah's names), reduction variables and the
// restart state.
#include <string>

#include "ice/IceComponent.h"

namespace tephra {

namespace {

const char* const kCellLabels[] = {"press_CC",      "press_equil_CC", "delP_Dilatate", "rho_CC",      "temp_CC",
                                   "vel_CC",        "vol_frac_CC",    "sp_vol_CC",     "speedSound_CC", "rho_micro_CC",
                                   "mom_L_ME_CC",   "eng_L_ME_CC",    "mom_source_CC", "delP_MassX",
                                   "mass_L_CC",     "mom_L_CC",       "int_eng_L_CC"};
// Face-centred normal velocities (Uintah's SFCX/SFCY/SFCZ labels), before and
// after the face momentum exchange; written on the faces of the interior cells.
const char* const kFaceLabels[] = {"uvel_FC", "vvel_FC", "wvel_FC", "uvel_FCME", "vvel_FCME", "wvel_FCME"};
const char* const kReductionLabels[] = {"KineticEnergy", "TotalMass", "TotalIntEng", "TotalMomentum"};

// The cells of the whole grid with the extra cells, i fastest (OutputFrame.h).
template <class T>
FieldArray gather(const Grid& g, const PatchFields<CellField<T>>& f, const std::string& label, int material) {
  FieldArray out;
  out.label = label;
  out.material = material;
  out.components = std::is_same_v<T, double> ? 1 : 3;
  const IndexRange all = g.cells_with_extra();
  const IntVec3 n = all.extent();
  out.values.assign(static_cast<std::size_t>(all.size()) * out.components, 0.0);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const IndexRange r = g.patches[pi].cells_with_extra();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          const std::size_t idx = static_cast<std::size_t>((i - all.lo[0]) + n[0] * ((j - all.lo[1]) + n[1] * (k - all.lo[2])));
          if constexpr (std::is_same_v<T, double>) {
            out.values[idx] = f[pi](i, j, k);
          } else {
            for (int c = 0; c < 3; ++c) out.values[3 * idx + c] = f[pi](i, j, k)[c];
          }
        }
  }
  return out;
}

// The faces normal to d of the interior cells, i fastest: extent cells + e_d.
FieldArray gather_faces(const Grid& g, const FaceScalars& f, int d, const std::string& label, int material) {
  FieldArray out;
  out.label = label;
  out.material = material;
  const IntVec3 n = g.cells + IntVec3::Unit(d);
  out.values.assign(static_cast<std::size_t>(n.prod()), 0.0);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& p = g.patches[pi];
    const IntVec3 hi = p.hi + IntVec3::Unit(d);
    const GridArray<double>& a = f.at(d, pi);
    for (int k = p.lo[2]; k < hi[2]; ++k)
      for (int j = p.lo[1]; j < hi[1]; ++j)
        for (int i = p.lo[0]; i < hi[0]; ++i)
          out.values[static_cast<std::size_t>(i + n[0] * (j + n[1] * k))] = a(i, j, k);
  }
  return out;
}

// Every stored entry (ghosts too) of a field, for the restart state.
template <class T>
std::vector<double> flatten(const PatchFields<CellField<T>>& f) {
  std::vector<double> out;
  for (const auto& a : f) {
    const double* d = reinterpret_cast<const double*>(a.data());
    out.insert(out.end(), d, d + a.size() * (sizeof(T) / sizeof(double)));
  }
  return out;
}

template <class T>
void restore(const StateArchive& ar, const std::string& name, PatchFields<CellField<T>>& f) {
  const std::vector<double>& v = ar.doubles(name);
  std::size_t total = 0;
  for (const auto& a : f) total += a.size() * (sizeof(T) / sizeof(double));
  if (v.size() != total) throw RuntimeFailure("checkpoint array '" + name + "' has a bad size");
  std::size_t pos = 0;
  for (auto& a : f) {
    double* d = reinterpret_cast<double*>(a.data());
    const std::size_t n = a.size() * (sizeof(T) / sizeof(double));
    std::copy(v.begin() + static_cast<long>(pos), v.begin() + static_cast<long>(pos + n), d);
    pos += n;
  }
}

}  // namespace

std::set<std::string> IceComponent::known_labels() const {
  std::set<std::string> s;
  for (const char* l : kCellLabels) s.insert(l);
  for (const char* l : kFaceLabels) s.insert(l);
  for (const char* l : kReductionLabels) s.insert(l);
  for (const IceModelP& m : setup_.models)
    for (const std::string& l : m->labels()) s.insert(l);
  // The source models' per-step sources (Uintah's modelMass_src, ...), per material.
  if (!setup_.models.empty())
    for (const char* l : {"modelMass_src", "modelMom_src", "modelEng_src", "modelVol_src"}) s.insert(l);
  return s;
}

void IceComponent::fill_output(const std::set<std::string>& labels, OutputFrame& frame) const {
  const Grid& g = setup_.grid;
  frame.grid = &g;
  auto put = [&](const FieldArray& a) { frame.grid_fields.push_back({a, GridLocation::Cell}); };
  auto want = [&](const char* l) { return labels.count(l) > 0; };
  // Pressure-like fields are shared by the materials: material 0, as Uintah saves them.
  if (want("press_CC")) put(gather(g, press_CC_, "press_CC", 0));
  if (want("press_equil_CC")) put(gather(g, press_equil_CC_, "press_equil_CC", 0));
  if (want("delP_Dilatate")) put(gather(g, delP_Dilatate_, "delP_Dilatate", 0));
  // Pressure change by mass exchange (Uintah's delP_MassX): exactly 0 without source models.
  if (want("delP_MassX") && model_src_) {
    put(gather(g, delP_MassX_, "delP_MassX", 0));
  } else if (want("delP_MassX")) {
    CellScalars zero(g, 0);
    zero.fill(0.0);
    put(gather(g, zero, "delP_MassX", 0));
  }
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const IceMaterialFields& f = mats_[m];
    const int mi = static_cast<int>(m);
    if (want("rho_CC")) put(gather(g, f.rho_CC, "rho_CC", mi));
    if (want("temp_CC")) put(gather(g, f.temp_CC, "temp_CC", mi));
    if (want("vel_CC")) put(gather(g, f.vel_CC, "vel_CC", mi));
    if (want("vol_frac_CC")) put(gather(g, f.vol_frac_CC, "vol_frac_CC", mi));
    if (want("sp_vol_CC")) put(gather(g, f.sp_vol_CC, "sp_vol_CC", mi));
    if (want("speedSound_CC")) put(gather(g, f.speedSound_CC, "speedSound_CC", mi));
    if (want("rho_micro_CC")) put(gather(g, f.rho_micro_CC, "rho_micro_CC", mi));
    if (want("mom_L_ME_CC")) put(gather(g, f.mom_L_ME_CC, "mom_L_ME_CC", mi));
    if (want("eng_L_ME_CC")) put(gather(g, f.eng_L_ME_CC, "eng_L_ME_CC", mi));
    if (want("mom_source_CC")) put(gather(g, f.mom_source_CC, "mom_source_CC", mi));
    // Lagrangian values of the last step (eq. 26.8-26.10, before the exchange):
    // interior cells (the extra cells hold 0).
    if (want("mass_L_CC")) put(gather(g, mass_L_[m], "mass_L_CC", mi));
    if (want("mom_L_CC")) put(gather(g, f.mom_L_CC, "mom_L_CC", mi));
    if (want("int_eng_L_CC")) put(gather(g, f.int_eng_L_CC, "int_eng_L_CC", mi));
    if (model_src_) {  // the source models' sources of the last step (IceModelStep.cpp)
      if (want("modelMass_src")) put(gather(g, model_src_->mass[m], "modelMass_src", mi));
      if (want("modelMom_src")) put(gather(g, model_src_->momentum[m], "modelMom_src", mi));
      if (want("modelEng_src")) put(gather(g, model_src_->energy[m], "modelEng_src", mi));
      if (want("modelVol_src")) put(gather(g, model_src_->sp_vol[m], "modelVol_src", mi));
    }
  }
  for (const IceModelP& model : setup_.models)
    for (const ModelField& mf : model->fields())
      if (labels.count(mf.label)) put(gather(g, *mf.field, mf.label, mf.material));
  static const GridLocation kFace[3] = {GridLocation::FaceX, GridLocation::FaceY, GridLocation::FaceZ};
  for (std::size_t m = 0; m < mats_.size(); ++m)
    for (int d = 0; d < 3; ++d)
      for (int me = 0; me < 2; ++me) {
        const std::string label = kFaceLabels[3 * me + d];
        if (!want(label.c_str())) continue;
        const FaceScalars& f = me == 0 ? mats_[m].vel_FC : mats_[m].vel_FCME;
        frame.grid_fields.push_back({gather_faces(g, f, d, label, static_cast<int>(m)), kFace[d]});
      }
}

// As Uintah's ICE sums them over the interior cells of the new state:
//   TotalMass = sum rho V, TotalMomentum = sum rho V u,
//   KineticEnergy = sum 1/2 rho V |u|^2, TotalIntEng = sum rho V cv T.
std::map<std::string, std::vector<double>> IceComponent::reductions(const std::set<std::string>& labels) const {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  double mass = 0, ke = 0, ie = 0;
  Vec3 mom = Vec3::Zero();
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    if (setup_.materials[m].lagrangian) continue;  // MPMICE solids: counted by their particles
    const double cv = setup_.materials[m].cv;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
      const IndexRange r = g.patches[pi].cells();
      for (int k = r.lo[2]; k < r.hi[2]; ++k)
        for (int j = r.lo[1]; j < r.hi[1]; ++j)
          for (int i = r.lo[0]; i < r.hi[0]; ++i) {
            const double M = mats_[m].rho_CC[pi](i, j, k) * V;
            const Vec3& u = mats_[m].vel_CC[pi](i, j, k);
            mass += M;
            mom += M * u;
            ke += 0.5 * M * u.squaredNorm();
            ie += M * cv * mats_[m].temp_CC[pi](i, j, k);
          }
    }
  }
  std::map<std::string, std::vector<double>> out;
  if (labels.count("TotalMass")) out["TotalMass"] = {mass};
  if (labels.count("KineticEnergy")) out["KineticEnergy"] = {ke};
  if (labels.count("TotalIntEng")) out["TotalIntEng"] = {ie};
  if (labels.count("TotalMomentum")) out["TotalMomentum"] = {mom[0], mom[1], mom[2]};
  for (const IceModelP& m : setup_.models) m->reductions(labels, out);
  return out;
}

// The state the next step reads: rho, u, T, v (with extra cells and ghosts)
// plus the pressure (Newton's starting guess) and the sound speed (time
// step); the other saved fields so that the first output after a restart is
// the same.
void IceComponent::save_state(StateArchive& a) const {
  a.put("ice.press_CC", flatten(press_CC_));
  a.put("ice.press_equil_CC", flatten(press_equil_CC_));
  a.put("ice.delP_Dilatate", flatten(delP_Dilatate_));
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const std::string pre = "ice.m" + std::to_string(m) + ".";
    const IceMaterialFields& f = mats_[m];
    a.put(pre + "rho_CC", flatten(f.rho_CC));
    a.put(pre + "vel_CC", flatten(f.vel_CC));
    a.put(pre + "temp_CC", flatten(f.temp_CC));
    a.put(pre + "sp_vol_CC", flatten(f.sp_vol_CC));
    a.put(pre + "rho_micro_CC", flatten(f.rho_micro_CC));
    a.put(pre + "vol_frac_CC", flatten(f.vol_frac_CC));
    a.put(pre + "speedSound_CC", flatten(f.speedSound_CC));
    a.put(pre + "mom_L_ME_CC", flatten(f.mom_L_ME_CC));
    a.put(pre + "eng_L_ME_CC", flatten(f.eng_L_ME_CC));
  }
  for (std::size_t k = 0; k < setup_.models.size(); ++k) {
    const std::string pre = "ice.model" + std::to_string(k) + ".";
    for (auto& [name, field] : setup_.models[k]->state_fields()) a.put(pre + name, flatten(*field));
    for (auto& [name, value] : setup_.models[k]->state_scalars()) a.put_scalar(pre + name, *value);
  }
}

void IceComponent::load_state(const StateArchive& a) {
  restore(a, "ice.press_CC", press_CC_);
  restore(a, "ice.press_equil_CC", press_equil_CC_);
  restore(a, "ice.delP_Dilatate", delP_Dilatate_);
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const std::string pre = "ice.m" + std::to_string(m) + ".";
    IceMaterialFields& f = mats_[m];
    restore(a, pre + "rho_CC", f.rho_CC);
    restore(a, pre + "vel_CC", f.vel_CC);
    restore(a, pre + "temp_CC", f.temp_CC);
    restore(a, pre + "sp_vol_CC", f.sp_vol_CC);
    restore(a, pre + "rho_micro_CC", f.rho_micro_CC);
    restore(a, pre + "vol_frac_CC", f.vol_frac_CC);
    restore(a, pre + "speedSound_CC", f.speedSound_CC);
    restore(a, pre + "mom_L_ME_CC", f.mom_L_ME_CC);
    restore(a, pre + "eng_L_ME_CC", f.eng_L_ME_CC);
  }
  for (std::size_t k = 0; k < setup_.models.size(); ++k) {
    const std::string pre = "ice.model" + std::to_string(k) + ".";
    for (auto& [name, field] : setup_.models[k]->state_fields()) restore(a, pre + name, *field);
    for (auto& [name, value] : setup_.models[k]->state_scalars()) *value = a.scalar(pre + name);
  }
}

}  // namespace tephra
