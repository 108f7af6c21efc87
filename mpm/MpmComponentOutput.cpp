// MpmComponent: saved labels, reduction variables and the restart state.
#include <string>

#include "mpm/MpmComponent.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <stdexcept>

#include "core/io/StateArchive.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"

namespace tephra {

namespace {

const char* const kParticleLabels[] = {"p.x", "p.particleID", "p.volume", "p.velocity", "p.stress",
                                       "p.mass", "p.deformationMeasure", "p.deformationGradient", "p.displacement",
                                       "p.temperature", "p.color", "p.externalforce", "p.size", "p.q"};
const char* const kNodeLabels[] = {"g.mass", "g.volume", "g.velocity", "g.velocity_star", "g.acceleration",
                                   "g.externalforce", "g.internalforce", "g.stressFS"};
const char* const kReductionLabels[] = {"KineticEnergy", "StrainEnergy", "TotalMass", "TotalMomentum",
                                        "CenterOfMassPosition", "CenterOfMassVelocity", "AccStrainEnergy",
                                        "PlasticWork", "MMSDisplacementErrorL2"};

void append(std::vector<double>& out, double v) { out.push_back(v); }
void append(std::vector<double>& out, const Vec3& v) { out.insert(out.end(), v.data(), v.data() + 3); }
// Row-major xx, xy, xz, yx, ... (OutputFrame.h), whatever Eigen's storage order.
void append(std::vector<double>& out, const Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) out.push_back(m(r, c));
}

template <class T>
FieldArray field(const std::string& label, int material, const std::vector<T>& column) {
  FieldArray f;
  f.label = label;
  f.material = material;
  f.components = std::is_same_v<T, double> ? 1 : (std::is_same_v<T, Vec3> ? 3 : 9);
  f.values.reserve(column.size() * f.components);
  for (const T& v : column) append(f.values, v);
  return f;
}

// Inverse of append for the restart state.
void take(const double* d, double& v) { v = d[0]; }
void take(const double* d, Vec3& v) { v = Vec3(d[0], d[1], d[2]); }
void take(const double* d, Mat3& m) {
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 3; ++c) m(r, c) = d[3 * r + c];
}

template <class T>
void restore(const StateArchive& a, const std::string& name, std::vector<T>& column) {
  constexpr int k = std::is_same_v<T, double> ? 1 : (std::is_same_v<T, Vec3> ? 3 : 9);
  const std::vector<double>& v = a.doubles(name);
  if (v.size() % k != 0) throw RuntimeFailure("checkpoint array '" + name + "' has a bad size");
  column.resize(v.size() / k);
  for (std::size_t i = 0; i < column.size(); ++i) take(v.data() + k * i, column[i]);
}

template <class T>
std::vector<double> flatten(const std::vector<T>& column) {
  std::vector<double> out;
  for (const T& v : column) append(out, v);
  return out;
}

// Calls fn(name, column) for every particle column and node array (the restart state).
template <class P, class G, class Fn>
void for_each_column(P& p, G& g, Fn&& fn) {
  fn("x", p.x);
  fn("v", p.v);
  fn("displacement", p.displacement);
  fn("external_force", p.external_force);
  fn("F", p.F);
  fn("stress", p.stress);
  fn("size", p.psize);
  fn("mass", p.mass);
  fn("volume", p.volume);
  fn("volume0", p.volume0);
  fn("temperature", p.temperature);
  fn("color", p.color);
  fn("wave_speed", p.wave_speed);
  fn("energy_density", p.energy_density);
  fn("q", p.q);
  fn("g.mass", g.mass);
  fn("g.volume", g.volume);
  fn("g.velocity", g.velocity);
  fn("g.velocity_star", g.velocity_star);
  fn("g.acceleration", g.acceleration);
  fn("g.external_force", g.external_force);
  fn("g.internal_force", g.internal_force);
  fn("g.stress", g.stress);
}

// The block's particles in ascending id (positions, ids and every field's
// per-particle values): the files do not depend on the storage order of the
// columns (mpm/ParticleReorder.h). Seeding assigns ascending ids, so an
// unreordered run writes exactly the storage order (nothing moves).
void sort_by_id(ParticleBlock& b) {
  const std::size_t n = b.id.size();
  if (std::is_sorted(b.id.begin(), b.id.end())) return;
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t c) { return b.id[a] < b.id[c]; });
  auto gather = [&](auto& column, std::size_t per) {
    auto old = column;
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t k = 0; k < per; ++k) column[j * per + k] = old[order[j] * per + k];
  };
  gather(b.position, 1);
  gather(b.id, 1);
  for (FieldArray& f : b.fields)
    if (f.values.size() == n * std::size_t(f.components)) gather(f.values, std::size_t(f.components));
}

// On MPI ranks: every rank's particles of the block, concatenated in rank
// order (sort_by_id then puts them in id order, as one process writes them).
// Inside TimeLoop's OutputToRoot scope on rank 0 only (core/parallel/OutputGather.h):
// the block is empty on the other ranks.
void gather_block(ParticleBlock& b) {
  std::vector<double> x = flatten(b.position), id(b.id.begin(), b.id.end());  // ids < 2^53: exact
  x = gather_output(x);
  id = gather_output(id);
  b.position.resize(x.size() / 3);
  for (std::size_t i = 0; i < b.position.size(); ++i) take(x.data() + 3 * i, b.position[i]);
  b.id.assign(id.begin(), id.end());
  for (FieldArray& f : b.fields) f.values = gather_output(f.values);
}

std::vector<FieldArray> empty_fields(std::vector<FieldArray> fields) {
  for (FieldArray& f : fields) f.values.clear();
  return fields;
}

std::string prefix(const MpmMaterial& m) { return "mpm.m" + std::to_string(m.index) + "."; }

// Vaango's face names in the BndyForce_<face> / BndyContactArea_<face> labels.
const char* const kFaceNames[6] = {"xminus", "xplus", "yminus", "yplus", "zminus", "zplus"};

}  // namespace

std::set<std::string> MpmComponent::known_labels() const {
  std::set<std::string> s;
  for (const char* l : kParticleLabels) s.insert(l);
  for (const char* l : kNodeLabels) s.insert(l);
  for (const char* l : kReductionLabels) s.insert(l);
  for (const char* l : energy_ledger_labels()) s.insert(l);
  for (const MpmMaterial& m : setup_.materials)
    for (const HistoryVariable& h : m.model->history()) s.insert("p." + h.name);
  // Only the faces of <boundary_traction_faces> are computed (as in Vaango,
  // saving another face's label is an error rather than zeros).
  for (int f : setup_.flags.boundary_traction_faces) {
    s.insert(std::string("BndyForce_") + kFaceNames[f]);
    s.insert(std::string("BndyContactArea_") + kFaceNames[f]);
  }
  return s;
}

void MpmComponent::fill_output(const std::set<std::string>& labels, OutputFrame& frame) const {
  frame.grid = &setup_.grid;
  for (const MpmMaterial& m : setup_.materials) {
    const Particles& p = m.particles;
    ParticleBlock b;
    b.material = m.index;
    b.position = p.x;
    b.id = p.id;
    auto want = [&](const char* l) { return labels.count(l) > 0; };
    if (want("p.volume")) b.fields.push_back(field("p.volume", m.index, p.volume));
    if (want("p.velocity")) b.fields.push_back(field("p.velocity", m.index, p.v));
    if (want("p.stress")) b.fields.push_back(field("p.stress", m.index, p.stress));
    if (want("p.mass")) b.fields.push_back(field("p.mass", m.index, p.mass));
    if (want("p.deformationMeasure")) b.fields.push_back(field("p.deformationMeasure", m.index, p.F));
    // Newer Vaango's name of the same F (pDefGradLabel).
    if (want("p.deformationGradient")) b.fields.push_back(field("p.deformationGradient", m.index, p.F));
    if (want("p.displacement")) b.fields.push_back(field("p.displacement", m.index, p.displacement));
    if (want("p.temperature")) b.fields.push_back(field("p.temperature", m.index, p.temperature));
    if (want("p.color")) b.fields.push_back(field("p.color", m.index, p.color));
    if (want("p.externalforce")) b.fields.push_back(field("p.externalforce", m.index, p.external_force));
    if (want("p.size")) b.fields.push_back(field("p.size", m.index, p.psize));
    if (want("p.q")) b.fields.push_back(field("p.q", m.index, p.q));
    // The model's history columns, p.<name>, as declared (already flat).
    const std::vector<HistoryVariable> hist = m.model->history();
    for (std::size_t k = 0; k < hist.size(); ++k) {
      const std::string label = "p." + hist[k].name;
      if (!labels.count(label)) continue;
      FieldArray f;
      f.label = label;
      f.material = m.index;
      f.components = hist[k].components;
      f.values = p.history[k];
      b.fields.push_back(std::move(f));
    }
    if (layout_.distributed) gather_block(b);  // every rank's particles (mpm/MpmRanks.cpp)
    // Per-rank output without distributed patches: every rank holds them all, rank 0 writes them.
    else if (output_per_rank() && !world_ranks().is_root()) b = ParticleBlock{m.index, {}, {}, empty_fields(b.fields)};
    sort_by_id(b);
    frame.particles.push_back(std::move(b));

    const NodeGrid& g = m.grid;
    // The frame's nodes: without the periodic ghost layers (mpm/PeriodicGrid.h).
    const std::vector<std::size_t> kept = nodes_without_ghosts(g);
    auto node = [&](const char* label, const auto& column) {
      if (!want(label)) return;
      GridFieldArray gf;
      gf.location = GridLocation::Node;
      if (kept.empty() || column.empty()) {
        gf.data = field(label, m.index, column);
      } else {
        std::decay_t<decltype(column)> cropped;
        cropped.reserve(kept.size());
        for (std::size_t n : kept) cropped.push_back(column[n]);
        gf.data = field(label, m.index, cropped);
      }
      // On MPI ranks each node from a rank whose box holds it (mpm/RankNodeSums.h).
      // Periodic grids (ghost layers cropped above) are not run on ranks (exit 3).
      if (layout_.distributed && !column.empty())
        gf.data.values = node_sums_.whole(gf.data.values.data(), gf.data.components);
      mark_node_pieces(gf);  // per-rank output: the nodes this rank writes
      frame.grid_fields.push_back(std::move(gf));
    };
    node("g.mass", g.mass);
    node("g.volume", g.volume);
    node("g.velocity", g.velocity);
    node("g.velocity_star", g.velocity_star);
    node("g.acceleration", g.acceleration);
    node("g.externalforce", g.external_force);
    node("g.internalforce", g.internal_force);
    node("g.stressFS", g.stress);
  }
}

// As Vaango sums them at the end of a step (new particle state):
//   KineticEnergy = sum 1/2 m |v|^2, TotalMass = sum m, TotalMomentum = sum m v,
//   CenterOfMassPosition = sum m x / sum m, CenterOfMassVelocity = sum m v / sum m,
//   StrainEnergy = sum W(F_p) V0_p: the stored energy of the hyperelastic model
//   (Vaango's CompNeoHook sums the same W(F) V0), not an integral of sigma:d.
std::map<std::string, std::vector<double>> MpmComponent::reductions(const std::set<std::string>& labels) const {
  double ke = 0, se = 0, mass = 0;
  Vec3 mom = Vec3::Zero(), mx = Vec3::Zero();
  const bool thermal_sum = labels.count("ThermalEnergy") > 0;
  double thermal = 0.0;  // ThermalEnergy = sum m_p c_v T_p
  if (laid_out_ && setup_.grid.patches.size() > 1 && !setup_.materials.empty()) {
    // Several patches (session 21, issue 7): one partial per patch, its
    // particles material by material in ascending id, the partials added in
    // ascending patch id (PatchLayout::ordered_sum). A particle lives on the
    // rank of its patch (patch_of, migration after G2P) and the order of
    // the terms depends on ids and positions only, so one process and any
    // number of ranks add the same terms in the same order: the same bits
    // (before: storage order, and per rank then in rank order on ranks).
    const std::size_t np = setup_.grid.patches.size();
    std::vector<std::array<double, 10>> part(np);
    for (auto& a : part) a.fill(0.0);
    for (const MpmMaterial& m : setup_.materials) {
      const Particles& p = m.particles;
      std::vector<std::tuple<int, long long, std::size_t>> key(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) key[i] = {patch_of(p.x[i]), p.id[i], i};
      std::sort(key.begin(), key.end());
      for (const auto& [P, id, i] : key) {
        std::array<double, 10>& a = part[std::size_t(P)];
        a[0] += 0.5 * p.mass[i] * p.v[i].squaredNorm();
        a[1] += p.energy_density[i] * p.volume0[i];
        a[2] += p.mass[i];
        Eigen::Map<Vec3>(&a[3]) += p.mass[i] * p.v[i];
        Eigen::Map<Vec3>(&a[6]) += p.mass[i] * p.x[i];
        if (thermal_sum) a[9] += p.mass[i] * m.specific_heat * p.temperature[i];
      }
    }
    std::vector<char> own(np, 0);
    for (int P : layout_.own) own[std::size_t(P)] = 1;
    for (std::size_t P = 0; P < np; ++P)
      if (!own[P] && part[P][2] != 0.0)
        throw std::logic_error("MPM reductions: particles of patch " + std::to_string(P) + " on a rank that does not own it");
    std::vector<PatchPartial> partials;
    for (int P : layout_.own) {
      const std::array<double, 10>& a = part[std::size_t(P)];
      partials.push_back({P, std::vector<double>(a.begin(), a.end())});
    }
    const std::vector<double> total = layout_.ordered_sum(partials, 10);
    ke = total[0], se = total[1], mass = total[2], thermal = total[9];
    mom = Vec3(total[3], total[4], total[5]);
    mx = Vec3(total[6], total[7], total[8]);
  } else {
    for (const MpmMaterial& m : setup_.materials) {
      const Particles& p = m.particles;
      for (std::size_t i = 0; i < p.size(); ++i) {
        ke += 0.5 * p.mass[i] * p.v[i].squaredNorm();
        se += p.energy_density[i] * p.volume0[i];
        mass += p.mass[i];
        mom += p.mass[i] * p.v[i];
        mx += p.mass[i] * p.x[i];
      }
    }
    if (thermal_sum)
      for (const MpmMaterial& m : setup_.materials)
        for (std::size_t i = 0; i < m.particles.size(); ++i)
          thermal += m.particles.mass[i] * m.specific_heat * m.particles.temperature[i];
  }
  std::map<std::string, std::vector<double>> out;
  if (labels.count("KineticEnergy")) out["KineticEnergy"] = {ke};
  if (labels.count("StrainEnergy")) out["StrainEnergy"] = {se};
  // AccStrainEnergy: the work of the stresses summed over the steps (mpm/StrainWork.h).
  // PlasticWork: the models' plastic work summed over the steps (a Tephra label; mpm/StrainWork.h).
  // Both are summed during the steps only when the deck saves them: asking for
  // one that was not summed is a caller's error, not a zero.
  if (labels.count("AccStrainEnergy")) {
    if (!setup_.accumulate_strain_energy)
      throw std::logic_error("MPM reductions: AccStrainEnergy is summed only when the deck saves it");
    out["AccStrainEnergy"] = {acc_strain_energy_};
  }
  if (labels.count("PlasticWork")) {
    if (!setup_.accumulate_plastic_work)
      throw std::logic_error("MPM reductions: PlasticWork is summed only when the deck saves it");
    out["PlasticWork"] = {plastic_work_};
  }
  // The kinetic-energy ledger summed over the steps (Tephra labels; mpm/EnergyLedger.h).
  if (labels.count("ContactKineticEnergyRemoved")) out["ContactKineticEnergyRemoved"] = {ledger_.contact_removed};
  if (labels.count("BoundaryKineticEnergyRemoved")) out["BoundaryKineticEnergyRemoved"] = {ledger_.boundary_removed};
  if (labels.count("GridForceWork")) out["GridForceWork"] = {ledger_.grid_force_work};
  if (labels.count("TransferKineticEnergyLoss")) out["TransferKineticEnergyLoss"] = {ledger_.transfer_loss};
  if (labels.count("TotalMass")) out["TotalMass"] = {mass};
  if (labels.count("TotalMomentum")) out["TotalMomentum"] = {mom[0], mom[1], mom[2]};
  // sqrt(sum V0 |u_p - u_exact(X_p, t)|^2 / sum V0) with <run_MMS_problem>
  // (a Tephra label: Vaango computes this error in post-processing scripts).
  // ThermalEnergy = sum m_p c_v T_p (Vaango's definition, c_v the material's
  // <specific_heat>), summed only when the deck saves it.
  if (labels.count("ThermalEnergy")) out["ThermalEnergy"] = {thermal};
  if (labels.count("MMSDisplacementErrorL2")) out["MMSDisplacementErrorL2"] = {mms_displacement_error()};
  if (labels.count("CenterOfMassPosition")) {
    const Vec3 c = mass > 0 ? Vec3(mx / mass) : Vec3::Zero();
    out["CenterOfMassPosition"] = {c[0], c[1], c[2]};
  }
  if (labels.count("CenterOfMassVelocity")) {
    const Vec3 v = mass > 0 ? Vec3(mom / mass) : Vec3::Zero();
    out["CenterOfMassVelocity"] = {v[0], v[1], v[2]};
  }
  for (int f : setup_.flags.boundary_traction_faces) {
    const std::string force = std::string("BndyForce_") + kFaceNames[f];
    const std::string area = std::string("BndyContactArea_") + kFaceNames[f];
    const Vec3& F = boundary_force_[f];
    if (labels.count(force)) out[force] = {F[0], F[1], F[2]};
    if (labels.count(area)) out[area] = {boundary_area_[f]};
  }
  return out;
}

// On MPI ranks: the particles of every rank in ascending id (a checkpoint
// that any rank count can read) and whole-grid node arrays (mpm/RankNodeSums.h).
// Inside an OutputToRoot scope the gathers land on rank 0 only: the other
// ranks make the same collective calls and are left with empty columns.
// Inside TimeLoop's OutputPerRank scope (session 27) nothing moves: this
// rank's particles in ascending id and its node box (save_state marks them).
void gather_for_checkpoint(const RankNodeSums& sums, const std::vector<HistoryVariable>& hist, Particles& p,
                           NodeGrid& g) {
  std::vector<double> ids(p.id.begin(), p.id.end());
  ids = gather_output(ids);
  std::vector<std::size_t> order(ids.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return ids[x] < ids[y]; });
  for_each_column(p, g, [&](const char* name, auto& col) {
    using T = typename std::decay_t<decltype(col)>::value_type;
    constexpr int k = std::is_same_v<T, double> ? 1 : (std::is_same_v<T, Vec3> ? 3 : 9);
    if (name[0] == 'g') {
      if (col.empty()) return;
      const std::vector<double> w = sums.whole(flatten(col).data(), k);
      if (w.size() != col.size() * std::size_t(k)) {  // not the receiving rank
        col.clear();
        return;
      }
      for (std::size_t i = 0; i < col.size(); ++i) take(w.data() + k * i, col[i]);
      return;
    }
    const std::vector<double> flat = gather_output(flatten(col));
    col.resize(order.size());
    for (std::size_t j = 0; j < order.size(); ++j) take(flat.data() + k * order[j], col[j]);
  });
  for (std::size_t h = 0; h < hist.size(); ++h) {
    const std::size_t c = std::size_t(hist[h].components);
    const std::vector<double> flat = gather_output(p.history[h]);
    p.history[h].resize(order.size() * c);
    for (std::size_t j = 0; j < order.size(); ++j)
      std::copy(flat.begin() + long(order[j] * c), flat.begin() + long((order[j] + 1) * c), p.history[h].begin() + long(j * c));
  }
  p.id.resize(order.size());
  for (std::size_t j = 0; j < order.size(); ++j) p.id[j] = static_cast<long long>(ids[order[j]]);
}

// The node runs (offset, length in doubles of a node array of `width` per
// node, NodeGrid order) of the boxes: one run per (j, k) row of a box.
static std::vector<std::pair<std::size_t, std::size_t>> node_runs(const std::vector<ArrayBox>& boxes, const IntVec3& n,
                                                           std::size_t width) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for (const ArrayBox& b : boxes) {
    if (b.empty()) continue;
    for (int k = b.lo[2]; k < b.hi[2]; ++k)
      for (int j = b.lo[1]; j < b.hi[1]; ++j) {
        const std::size_t first = std::size_t(b.lo[0]) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * std::size_t(k));
        runs.emplace_back(first * width, std::size_t(b.hi[0] - b.lo[0]) * width);
      }
  }
  return runs;
}

// Per-rank checkpoints (session 27, core/io/RankCheckpoint.h): inside
// TimeLoop's OutputPerRank scope gather_for_checkpoint leaves this rank's
// particles (ascending id) and its node box; each rank puts its particles as
// rows keyed by the material's ids and the nodes RankNodeSums::whole takes
// from it (output_pieces) as runs, so the rank files merge into the arrays
// the gathered checkpoint holds.
void MpmComponent::save_state(StateArchive& a) const {
  const bool per_rank = layout_.distributed && output_per_rank();
  const std::vector<ArrayBox> node_pieces = per_rank ? node_sums_.output_pieces() : std::vector<ArrayBox>{};
  for (const MpmMaterial& m : setup_.materials) {
    const std::string pre = prefix(m);
    const std::vector<HistoryVariable> hist = m.model->history();
    Particles gathered;
    NodeGrid whole_grid;
    if (layout_.distributed) {
      gathered = m.particles;
      whole_grid = m.grid;
      gather_for_checkpoint(node_sums_, hist, gathered, whole_grid);
    }
    const Particles& p = layout_.distributed ? gathered : m.particles;
    const NodeGrid& g = layout_.distributed ? whole_grid : m.grid;
    if (!per_rank) {
      for_each_column(p, g, [&](const char* name, const auto& col) { a.put(pre + name, flatten(col)); });
      a.put(pre + "id", std::vector<long long>(p.id));
      for (std::size_t k = 0; k < hist.size(); ++k) a.put(pre + "history." + hist[k].name, p.history[k]);
      continue;
    }
    const std::string key = pre + "id";
    for_each_column(p, g, [&](const char* name, const auto& col) {
      using T = typename std::decay_t<decltype(col)>::value_type;
      constexpr std::size_t k = std::is_same_v<T, double> ? 1 : (std::is_same_v<T, Vec3> ? 3 : 9);
      const std::vector<double> flat = flatten(col);
      if (name[0] != 'g') {
        a.put(pre + name, flat, ArchivePart::as_rows(key, k));
      } else if (col.empty()) {
        a.put(pre + name, flat);  // an unused node array: empty on every rank
      } else {
        auto runs = node_runs(node_pieces, g.n, k);
        std::vector<double> mine;
        for (const auto& [offset, length] : runs) mine.insert(mine.end(), flat.begin() + long(offset), flat.begin() + long(offset + length));
        a.put(pre + name, std::move(mine), ArchivePart::as_runs(flat.size(), std::move(runs)));
      }
    });
    a.put(key, std::vector<long long>(p.id), ArchivePart::as_rows(key, 1));
    for (std::size_t k = 0; k < hist.size(); ++k)
      a.put(pre + "history." + hist[k].name, p.history[k], ArchivePart::as_rows(key, std::size_t(hist[k].components)));
  }
  a.put_scalar("mpm.stable_dt", stable_dt_);
  a.put_scalar("mpm.time", time_);
  a.put_scalar("mpm.acc_strain_energy", acc_strain_energy_);
  a.put_scalar("mpm.plastic_work", plastic_work_);
  a.put("mpm.energy_ledger", std::vector<double>{ledger_.contact_removed, ledger_.boundary_removed,
                                                 ledger_.grid_force_work, ledger_.transfer_loss});
  std::vector<double> bndy;
  for (int f = 0; f < 6; ++f) {
    append(bndy, boundary_force_[f]);
    bndy.push_back(boundary_area_[f]);
  }
  a.put("mpm.boundary_force_area", bndy);
}

void MpmComponent::load_state(const StateArchive& a) {
  for (MpmMaterial& m : setup_.materials) {
    const std::string pre = prefix(m);
    for_each_column(m.particles, m.grid, [&](const char* name, auto& col) { restore(a, pre + name, col); });
    m.particles.id = a.ints(pre + "id");
    const std::size_t n = m.particles.size();
    bool ok = m.particles.id.size() == n;
    for_each_column(m.particles, m.grid, [&](const char* name, auto& col) {
      if (name[0] != 'g') ok = ok && col.size() == n;
      else ok = ok && (col.size() == m.grid.count() || (col.empty() && std::string(name) == "g.stress"));
    });
    const std::vector<HistoryVariable> hist = m.model->history();
    m.particles.history.assign(hist.size(), {});
    for (std::size_t k = 0; k < hist.size(); ++k) {
      m.particles.history[k] = a.doubles(pre + "history." + hist[k].name);
      ok = ok && m.particles.history[k].size() == n * std::size_t(hist[k].components);
    }
    if (!ok) throw RuntimeFailure("checkpoint arrays of MPM material " + std::to_string(m.index) +
                                  " have inconsistent sizes");
    m.grid.cleared = NodeBox{IntVec3::Zero(), m.grid.n};  // whole node arrays restored: the next reset zeroes all
  }
  stable_dt_ = a.scalar("mpm.stable_dt");
  time_ = a.scalar("mpm.time");
  acc_strain_energy_ = a.has("mpm.acc_strain_energy") ? a.scalar("mpm.acc_strain_energy") : 0.0;
  plastic_work_ = a.has("mpm.plastic_work") ? a.scalar("mpm.plastic_work") : 0.0;
  ledger_ = EnergyLedger{};
  if (a.has("mpm.energy_ledger")) {
    const std::vector<double>& e = a.doubles("mpm.energy_ledger");
    if (e.size() != 4) throw RuntimeFailure("checkpoint array 'mpm.energy_ledger' has a bad size");
    ledger_ = EnergyLedger{e[0], e[1], e[2], e[3]};
  }
  const std::vector<double>& bndy = a.doubles("mpm.boundary_force_area");
  if (bndy.size() != 24) throw RuntimeFailure("checkpoint array 'mpm.boundary_force_area' has a bad size");
  for (int f = 0; f < 6; ++f) {
    boundary_force_[f] = Vec3(bndy[4 * f], bndy[4 * f + 1], bndy[4 * f + 2]);
    boundary_area_[f] = bndy[4 * f + 3];
  }
  // Under mpirun each rank keeps the particles of its patches (mpm/MpmRanks.cpp);
  // the node arrays stay whole (the next step's P2G rebuilds them).
  const bool was_laid_out = laid_out_;
  lay_out_patches();
  if (was_laid_out)
    for (MpmMaterial& m : setup_.materials) keep_own_particles(m);
}

}  // namespace tephra
