// IceComponent: saved labels (Uintah's names), reduction variables and the
// restart state.
#include <string>

#include "core/io/ArrayBoxes.h"
#include "core/parallel/OutputGather.h"
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

// Values of one patch over `r`, i fastest, `comps` doubles per entry.
template <class A>
std::vector<double> pack(const A& a, const IndexRange& r, int comps) {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(r.size()) * comps);
  for (int k = r.lo[2]; k < r.hi[2]; ++k)
    for (int j = r.lo[1]; j < r.hi[1]; ++j)
      for (int i = r.lo[0]; i < r.hi[0]; ++i) {
        const double* v = reinterpret_cast<const double*>(&a(i, j, k));
        out.insert(out.end(), v, v + comps);
      }
  return out;
}

// Inside TimeLoop's OutputToRoot scope (core/parallel/OutputGather.h) a
// distributed layout's gathers land on rank 0 only: the other ranks hand back
// empty arrays (TimeLoop writes nothing there).
bool receives_gather(const PatchLayout& layout) { return !layout.distributed || output_gather_lands_here(); }
FieldArray empty(FieldArray f) {
  f.values.clear();
  return f;
}

// Per-rank output (OutputPerRank, session 25): the blocks of the other ranks'
// patches are empty and left out; `range(p)` is patch p's block and `first`
// the array's first (i,j,k). Later patches overwrite shared entries (faces),
// so patch p owns its block minus those of the later patches.
template <class Range>
GridFieldArray with_own_pieces(FieldArray a, GridLocation loc, const PatchLayout& layout, const IntVec3& first,
                               Range range) {
  GridFieldArray g;
  g.data = std::move(a);
  g.location = loc;
  if (!output_per_rank() || !layout.distributed) return g;  // unmarked: rank 0 writes it whole
  g.partial = true;
  std::vector<ArrayBox> boxes;
  for (const Patch& p : layout.level.patches) {
    const IndexRange r = range(p);
    boxes.push_back({r.lo - first, r.hi - first});
  }
  for (int p : layout.own)
    for (const ArrayBox& b : kept_when_later_wins(boxes, static_cast<std::size_t>(p))) g.pieces.push_back(b);
  return g;
}

// The cells of the whole level with the extra cells, i fastest (OutputFrame.h).
// Each patch's cells_with_extra() block comes from the process that holds it
// (layout.gather_blocks) and is written in level patch order, so every rank
// count writes the same array.
template <class T>
FieldArray gather(const PatchLayout& layout, const PatchFields<CellField<T>>& f, const std::string& label,
                  int material) {
  const Grid& g = layout.level;
  FieldArray out;
  out.label = label;
  out.material = material;
  out.components = std::is_same_v<T, double> ? 1 : 3;
  const int nc = out.components;
  const IndexRange all = g.cells_with_extra();
  const IntVec3 n = all.extent();
  out.values.assign(static_cast<std::size_t>(all.size()) * nc, 0.0);
  std::vector<std::vector<double>> own;
  for (std::size_t pi = 0; pi < f.size(); ++pi)
    own.push_back(pack(f[pi], g.patches[static_cast<std::size_t>(f.patch_index(pi))].cells_with_extra(), nc));
  const std::vector<std::vector<double>> blocks = layout.gather_blocks(own);
  if (!receives_gather(layout)) return empty(out);
  for (std::size_t p = 0; p < g.patches.size(); ++p) {
    const IndexRange r = g.patches[p].cells_with_extra();
    if (blocks[p].empty()) continue;  // another rank's patch (per-rank output)
    const double* v = blocks[p].data();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) {
          const std::size_t idx = static_cast<std::size_t>((i - all.lo[0]) + n[0] * ((j - all.lo[1]) + n[1] * (k - all.lo[2])));
          for (int c = 0; c < nc; ++c) out.values[nc * idx + c] = *v++;
        }
  }
  return out;
}

// The faces normal to d of the interior cells, i fastest: extent cells + e_d
// (a face two patches share is written by the later one, as in one process).
FieldArray gather_faces(const PatchLayout& layout, const FaceScalars& f, int d, const std::string& label,
                        int material) {
  const Grid& g = layout.level;
  FieldArray out;
  out.label = label;
  out.material = material;
  const IntVec3 n = g.cells + IntVec3::Unit(d);
  out.values.assign(static_cast<std::size_t>(n.prod()), 0.0);
  auto faces = [&](const Patch& p) { return IndexRange{p.lo, p.hi + IntVec3::Unit(d)}; };
  std::vector<std::vector<double>> own;
  for (std::size_t pi = 0; pi < f.x.size(); ++pi)
    own.push_back(pack(f.at(d, pi), faces(g.patches[static_cast<std::size_t>(f.x.patch_index(pi))]), 1));
  const std::vector<std::vector<double>> blocks = layout.gather_blocks(own);
  if (!receives_gather(layout)) return empty(out);
  for (std::size_t p = 0; p < g.patches.size(); ++p) {
    const IndexRange r = faces(g.patches[p]);
    if (blocks[p].empty()) continue;  // another rank's patch (per-rank output)
    const double* v = blocks[p].data();
    for (int k = r.lo[2]; k < r.hi[2]; ++k)
      for (int j = r.lo[1]; j < r.hi[1]; ++j)
        for (int i = r.lo[0]; i < r.hi[0]; ++i) out.values[static_cast<std::size_t>(i + n[0] * (j + n[1] * k))] = *v++;
  }
  return out;
}

// Every stored entry (ghosts too) of a field, for the restart state: the
// patches' storage concatenated in level patch order, whichever process holds
// them, so a checkpoint does not depend on the rank count.
template <class T>
std::vector<double> flatten(const PatchLayout& layout, const PatchFields<CellField<T>>& f) {
  std::vector<std::vector<double>> own;
  for (const auto& a : f) {
    const double* d = reinterpret_cast<const double*>(a.data());
    own.emplace_back(d, d + a.size() * (sizeof(T) / sizeof(double)));
  }
  std::vector<double> out;
  for (const std::vector<double>& b : layout.gather_blocks(own)) out.insert(out.end(), b.begin(), b.end());
  return out;
}

// Where each level patch's storage starts in a flatten()ed array (and its
// size at the end): each patch's storage is that of a field of the same
// ghost width on it.
template <class T>
std::vector<std::size_t> storage_offsets(const PatchLayout& layout, const PatchFields<CellField<T>>& f) {
  const std::size_t per = sizeof(T) / sizeof(double);
  std::vector<std::size_t> offset(layout.level.patches.size() + 1, 0);
  for (std::size_t p = 0; p < layout.level.patches.size(); ++p)
    offset[p + 1] = offset[p] + CellField<T>(layout.level.patches[p], f.ghost_width()).size() * per;
  return offset;
}

// Puts a field's flatten()ed array. Per-rank checkpoints (session 27,
// core/io/RankCheckpoint.h): this rank's patches only, each a run at its
// patch's offset, so the rank files merge into the flatten()ed array.
template <class T>
void put_flat(StateArchive& a, const std::string& name, const PatchLayout& layout, const PatchFields<CellField<T>>& f) {
  if (!(output_per_rank() && layout.distributed)) {
    a.put(name, flatten(layout, f));
    return;
  }
  const std::vector<std::size_t> offset = storage_offsets(layout, f);
  std::vector<double> mine;
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (std::size_t n = 0; n < f.size(); ++n) {
    const auto p = static_cast<std::size_t>(f.patch_index(n));
    const double* d = reinterpret_cast<const double*>(f[n].data());
    runs.emplace_back(offset[p], offset[p + 1] - offset[p]);
    mine.insert(mine.end(), d, d + (offset[p + 1] - offset[p]));
  }
  a.put(name, std::move(mine), ArchivePart::as_runs(offset.back(), std::move(runs)));
}

// Reads this process's patches out of a flatten()ed array: each level patch's
// storage size is that of a field of the same ghost width on it.
template <class T>
void restore(const PatchLayout& layout, const StateArchive& ar, const std::string& name, PatchFields<CellField<T>>& f) {
  const std::vector<double>& v = ar.doubles(name);
  const std::vector<std::size_t> offset = storage_offsets(layout, f);
  if (v.size() != offset.back()) throw RuntimeFailure("checkpoint array '" + name + "' has a bad size");
  for (std::size_t n = 0; n < f.size(); ++n) {
    const auto p = static_cast<std::size_t>(f.patch_index(n));
    double* d = reinterpret_cast<double*>(f[n].data());
    std::copy(v.begin() + static_cast<long>(offset[p]), v.begin() + static_cast<long>(offset[p + 1]), d);
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
  frame.grid = &layout_.level;
  const IntVec3 first = layout_.level.cells_with_extra().lo;
  auto put = [&](const FieldArray& a) {
    frame.grid_fields.push_back(with_own_pieces(a, GridLocation::Cell, layout_, first,
                                                [](const Patch& p) { return p.cells_with_extra(); }));
  };
  auto want = [&](const char* l) { return labels.count(l) > 0; };
  // Pressure-like fields are shared by the materials: material 0, as Uintah saves them.
  if (want("press_CC")) put(gather(layout_, press_CC_, "press_CC", 0));
  if (want("press_equil_CC")) put(gather(layout_, press_equil_CC_, "press_equil_CC", 0));
  if (want("delP_Dilatate")) put(gather(layout_, delP_Dilatate_, "delP_Dilatate", 0));
  // Pressure change by mass exchange (Uintah's delP_MassX): exactly 0 without source models.
  if (want("delP_MassX") && model_src_) {
    put(gather(layout_, delP_MassX_, "delP_MassX", 0));
  } else if (want("delP_MassX")) {
    CellScalars zero(g, 0);
    zero.fill(0.0);
    put(gather(layout_, zero, "delP_MassX", 0));
  }
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const IceMaterialFields& f = mats_[m];
    const int mi = static_cast<int>(m);
    if (want("rho_CC")) put(gather(layout_, f.rho_CC, "rho_CC", mi));
    if (want("temp_CC")) put(gather(layout_, f.temp_CC, "temp_CC", mi));
    if (want("vel_CC")) put(gather(layout_, f.vel_CC, "vel_CC", mi));
    if (want("vol_frac_CC")) put(gather(layout_, f.vol_frac_CC, "vol_frac_CC", mi));
    if (want("sp_vol_CC")) put(gather(layout_, f.sp_vol_CC, "sp_vol_CC", mi));
    if (want("speedSound_CC")) put(gather(layout_, f.speedSound_CC, "speedSound_CC", mi));
    if (want("rho_micro_CC")) put(gather(layout_, f.rho_micro_CC, "rho_micro_CC", mi));
    if (want("mom_L_ME_CC")) put(gather(layout_, f.mom_L_ME_CC, "mom_L_ME_CC", mi));
    if (want("eng_L_ME_CC")) put(gather(layout_, f.eng_L_ME_CC, "eng_L_ME_CC", mi));
    if (want("mom_source_CC")) put(gather(layout_, f.mom_source_CC, "mom_source_CC", mi));
    // Lagrangian values of the last step (eq. 26.8-26.10, before the exchange):
    // interior cells (the extra cells hold 0).
    if (want("mass_L_CC")) put(gather(layout_, mass_L_[m], "mass_L_CC", mi));
    if (want("mom_L_CC")) put(gather(layout_, f.mom_L_CC, "mom_L_CC", mi));
    if (want("int_eng_L_CC")) put(gather(layout_, f.int_eng_L_CC, "int_eng_L_CC", mi));
    if (model_src_) {  // the source models' sources of the last step (IceModelStep.cpp)
      if (want("modelMass_src")) put(gather(layout_, model_src_->mass[m], "modelMass_src", mi));
      if (want("modelMom_src")) put(gather(layout_, model_src_->momentum[m], "modelMom_src", mi));
      if (want("modelEng_src")) put(gather(layout_, model_src_->energy[m], "modelEng_src", mi));
      if (want("modelVol_src")) put(gather(layout_, model_src_->sp_vol[m], "modelVol_src", mi));
    }
  }
  for (const IceModelP& model : setup_.models)
    for (const ModelField& mf : model->fields())
      if (labels.count(mf.label)) put(gather(layout_, *mf.field, mf.label, mf.material));
  static const GridLocation kFace[3] = {GridLocation::FaceX, GridLocation::FaceY, GridLocation::FaceZ};
  for (std::size_t m = 0; m < mats_.size(); ++m)
    for (int d = 0; d < 3; ++d)
      for (int me = 0; me < 2; ++me) {
        const std::string label = kFaceLabels[3 * me + d];
        if (!want(label.c_str())) continue;
        const FaceScalars& f = me == 0 ? mats_[m].vel_FC : mats_[m].vel_FCME;
        frame.grid_fields.push_back(with_own_pieces(
            gather_faces(layout_, f, d, label, static_cast<int>(m)), kFace[d], layout_, IntVec3::Zero(),
            [d](const Patch& p) { return IndexRange{p.lo, p.hi + IntVec3::Unit(d)}; }));
      }
}

// As Uintah's ICE sums them over the interior cells of the new state:
//   TotalMass = sum rho V, TotalMomentum = sum rho V u,
//   KineticEnergy = sum 1/2 rho V |u|^2, TotalIntEng = sum rho V cv T.
std::map<std::string, std::vector<double>> IceComponent::reductions(const std::set<std::string>& labels) const {
  const Grid& g = setup_.grid;
  const double V = g.cell_volume();
  // One partial per patch (its cells in (k, j, i) order, materials in turn),
  // added in ascending patch id (PatchLayout::ordered_sum): the same bits on
  // any number of ranks.
  std::vector<PatchPartial> partials;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    double mass = 0, ke = 0, ie = 0;
    Vec3 mom = Vec3::Zero();
    for (std::size_t m = 0; m < mats_.size(); ++m) {
      if (setup_.materials[m].lagrangian) continue;  // MPMICE solids: counted by their particles
      const double cv = setup_.materials[m].cv;
      // A per-cell ideal gas (SimpleRxn): the mixture's cv of the cell.
      const GridArray<double>* cell_cv =
          m < cell_gas_.size() && cell_gas_[m] ? &(*cell_gas_[m]->cell_ideal_gas()->cv)[pi] : nullptr;
      const IndexRange r = g.patches[pi].cells();
      for (int k = r.lo[2]; k < r.hi[2]; ++k)
        for (int j = r.lo[1]; j < r.hi[1]; ++j)
          for (int i = r.lo[0]; i < r.hi[0]; ++i) {
            const double M = mats_[m].rho_CC[pi](i, j, k) * V;
            const Vec3& u = mats_[m].vel_CC[pi](i, j, k);
            mass += M;
            mom += M * u;
            ke += 0.5 * M * u.squaredNorm();
            ie += M * (cell_cv ? (*cell_cv)(i, j, k) : cv) * mats_[m].temp_CC[pi](i, j, k);
          }
    }
    partials.push_back({g.patches[pi].id, {mass, ke, ie, mom[0], mom[1], mom[2]}});
  }
  const std::vector<double> sum = layout_.ordered_sum(partials, 6);
  const double mass = sum[0], ke = sum[1], ie = sum[2];
  const Vec3 mom(sum[3], sum[4], sum[5]);
  std::map<std::string, std::vector<double>> out;
  if (labels.count("TotalMass")) out["TotalMass"] = {mass};
  if (labels.count("KineticEnergy")) out["KineticEnergy"] = {ke};
  if (labels.count("TotalIntEng")) out["TotalIntEng"] = {ie};
  if (labels.count("TotalMomentum")) out["TotalMomentum"] = {mom[0], mom[1], mom[2]};
  model_reductions(labels, out);
  return out;
}

// The source models' sums (issue 7): per-patch sums (ModelSum) added over the
// patches of all ranks in ascending patch id -- the same bits on any rank
// count; plain per-process sums (models without per-patch sums) added over
// the ranks (one partial per rank, keyed by its first patch: right to
// round-off only). Every rank makes the same calls (labels and models are
// the same everywhere), so the collectives match.
void IceComponent::model_reductions(const std::set<std::string>& labels,
                                    std::map<std::string, std::vector<double>>& out) const {
  for (const IceModelP& m : setup_.models) {
    std::map<const PatchSums*, std::vector<double>> totals;
    std::set<std::string> rest = labels;
    for (const ModelSum& s : m->patch_sums()) {
      rest.erase(s.label);
      if (!labels.count(s.label)) continue;
      auto it = totals.find(s.sums);
      if (it == totals.end()) it = totals.emplace(s.sums, layout_.ordered_sum(s.sums->partials(), s.sums->width())).first;
      out[s.label].assign(it->second.begin() + s.first, it->second.begin() + s.first + s.width);
    }
    std::map<std::string, std::vector<double>> plain;
    m->reductions(rest, plain);
    for (auto& [label, v] : plain) {
      if (layout_.distributed) {
        std::vector<PatchPartial> mine;
        if (!layout_.own.empty()) mine.push_back({layout_.own.front(), v});
        v = layout_.ordered_sum(mine, int(v.size()));
      }
      out[label] = v;
    }
  }
}

// The state the next step reads: rho, u, T, v (with extra cells and ghosts)
// plus the pressure (Newton's starting guess) and the sound speed (time
// step); the other saved fields so that the first output after a restart is
// the same.
void IceComponent::save_state(StateArchive& a) const {
  put_flat(a, "ice.press_CC", layout_, press_CC_);
  put_flat(a, "ice.press_equil_CC", layout_, press_equil_CC_);
  put_flat(a, "ice.delP_Dilatate", layout_, delP_Dilatate_);
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const std::string pre = "ice.m" + std::to_string(m) + ".";
    const IceMaterialFields& f = mats_[m];
    put_flat(a, pre + "rho_CC", layout_, f.rho_CC);
    put_flat(a, pre + "vel_CC", layout_, f.vel_CC);
    put_flat(a, pre + "temp_CC", layout_, f.temp_CC);
    put_flat(a, pre + "sp_vol_CC", layout_, f.sp_vol_CC);
    put_flat(a, pre + "rho_micro_CC", layout_, f.rho_micro_CC);
    put_flat(a, pre + "vol_frac_CC", layout_, f.vol_frac_CC);
    put_flat(a, pre + "speedSound_CC", layout_, f.speedSound_CC);
    put_flat(a, pre + "mom_L_ME_CC", layout_, f.mom_L_ME_CC);
    put_flat(a, pre + "eng_L_ME_CC", layout_, f.eng_L_ME_CC);
  }
  for (std::size_t k = 0; k < setup_.models.size(); ++k) {
    const std::string pre = "ice.model" + std::to_string(k) + ".";
    for (auto& [name, field] : setup_.models[k]->state_fields()) put_flat(a, pre + name, layout_, *field);
    for (auto& [name, value] : setup_.models[k]->state_scalars()) a.put_scalar(pre + name, *value);
    for (auto& [name, sums] : setup_.models[k]->state_sums())
      a.put(pre + "sums." + name, layout_.ordered_sum(sums->partials(), sums->width()));
  }
}

void IceComponent::load_state(const StateArchive& a) {
  // A restart (tephra --restart) builds a fresh component: lay out the
  // patches and allocate the fields first; the archive then overwrites them.
  if (!laid_out_) initialize();
  restore(layout_, a, "ice.press_CC", press_CC_);
  restore(layout_, a, "ice.press_equil_CC", press_equil_CC_);
  restore(layout_, a, "ice.delP_Dilatate", delP_Dilatate_);
  for (std::size_t m = 0; m < mats_.size(); ++m) {
    const std::string pre = "ice.m" + std::to_string(m) + ".";
    IceMaterialFields& f = mats_[m];
    restore(layout_, a, pre + "rho_CC", f.rho_CC);
    restore(layout_, a, pre + "vel_CC", f.vel_CC);
    restore(layout_, a, pre + "temp_CC", f.temp_CC);
    restore(layout_, a, pre + "sp_vol_CC", f.sp_vol_CC);
    restore(layout_, a, pre + "rho_micro_CC", f.rho_micro_CC);
    restore(layout_, a, pre + "vol_frac_CC", f.vol_frac_CC);
    restore(layout_, a, pre + "speedSound_CC", f.speedSound_CC);
    restore(layout_, a, pre + "mom_L_ME_CC", f.mom_L_ME_CC);
    restore(layout_, a, pre + "eng_L_ME_CC", f.eng_L_ME_CC);
  }
  for (std::size_t k = 0; k < setup_.models.size(); ++k) {
    const std::string pre = "ice.model" + std::to_string(k) + ".";
    for (auto& [name, field] : setup_.models[k]->state_fields()) restore(layout_, a, pre + name, *field);
    for (auto& [name, value] : setup_.models[k]->state_scalars()) *value = a.scalar(pre + name);
    for (auto& [name, sums] : setup_.models[k]->state_sums()) sums->restore_totals(a.doubles(pre + "sums." + name));
  }
}

}  // namespace tephra
