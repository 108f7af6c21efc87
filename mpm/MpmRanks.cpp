// MpmComponent on MPI ranks (issue 7, docs/parallel.md "MPM on ranks").
//
// Ownership: a particle belongs to the rank that owns the patch holding it
// (the cell of its position; a position in an extra cell counts for the
// nearest interior cell). Patches go to ranks by the load balancer
// (core/parallel/LoadBalancer: cells + particles of the seeded state).
// Every rank seeds the whole deck (so particle ids are the one-process ids)
// and keeps its own particles.
//
// Node fields: each rank keeps full-size NodeGrids (memory O(grid) per rank)
// and scatters its own particles; mpm/RankNodeSums combines the arrays over
// the ranks whose node boxes overlap, right after each scatter (P2G, internal
// force, MUSL velocity, contact normals and positions), before any node-wise
// step. The node-wise steps (grid BCs, symmetry folds, integration, contact,
// damping) then run on every rank on identical values; G2P reads only nodes
// of the rank's own box.
//
// Migration: after G2P (and deletion) a particle whose new position lies in
// another rank's patch moves there with every column (Particles, history),
// its id kept; it is appended after the receiver's particles (the scatter
// order of mpm/ParticleReorder then takes over).
#include <algorithm>
#include <cmath>
#include <string>

#include "core/base/Errors.h"
#include "core/base/PhaseTimers.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"
#include "mpm/MpmComponent.h"
#include "mpm/ParticleDeletion.h"

namespace tephra {

namespace {

// Calls fn(column) for every fixed column of p (one value per particle).
template <class P, class Fn>
void for_each_fixed_column(P& p, Fn&& fn) {
  fn(p.x);
  fn(p.v);
  fn(p.displacement);
  fn(p.external_force);
  fn(p.F);
  fn(p.stress);
  fn(p.psize);
  fn(p.mass);
  fn(p.volume);
  fn(p.volume0);
  fn(p.temperature);
  fn(p.color);
  fn(p.wave_speed);
  fn(p.energy_density);
  fn(p.q);
  fn(p.id);
}

int width_of(const double&) { return 1; }
int width_of(const long long&) { return 1; }
int width_of(const Vec3&) { return 3; }
int width_of(const Mat3&) { return 9; }

void put(std::vector<double>& b, double v) { b.push_back(v); }
void put(std::vector<double>& b, long long v) { b.push_back(static_cast<double>(v)); }  // ids < 2^53: exact
void put(std::vector<double>& b, const Vec3& v) { b.insert(b.end(), v.data(), v.data() + 3); }
void put(std::vector<double>& b, const Mat3& m) { b.insert(b.end(), m.data(), m.data() + 9); }  // storage order both ways
void get(const double* d, double& v) { v = d[0]; }
void get(const double* d, long long& v) { v = static_cast<long long>(d[0]); }
void get(const double* d, Vec3& v) { v = Vec3(d[0], d[1], d[2]); }
void get(const double* d, Mat3& m) { std::copy(d, d + 9, m.data()); }

// Doubles per particle in a migration record of p (fixed columns + history).
std::size_t record_width(const Particles& p, const std::vector<HistoryVariable>& hist) {
  std::size_t w = 0;
  for_each_fixed_column(p, [&](const auto& col) { w += std::size_t(width_of(typename std::decay_t<decltype(col)>::value_type{})); });
  for (const HistoryVariable& h : hist) w += std::size_t(h.components);
  return w;
}

}  // namespace

// Every explicit MPM feature of the deck reader runs on ranks since session 18
// (pressure stabilisation, prescribed deformation, MMS, the energy ledger were
// the last to exit 3); the hook stays for features added later.
void MpmComponent::check_rank_support() const {}

int MpmComponent::patch_of(const Vec3& x) const {
  const Grid& g = layout_.level;
  IntVec3 c;
  for (int d = 0; d < 3; ++d)
    c[d] = std::clamp(int(std::floor((x[d] - g.lower[d]) / g.dx[d])), 0, g.cells[d] - 1);
  const int p = g.patch_owning_cell(c);
  if (p < 0) throw std::logic_error("MpmComponent: no patch holds interior cell of a particle");
  return p;
}

void MpmComponent::keep_own_particles(MpmMaterial& m) {
  if (!layout_.distributed) return;
  const int me = world_ranks().rank;
  Particles& p = m.particles;
  std::vector<char> keep(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) keep[i] = layout_.owner[std::size_t(patch_of(p.x[i]))] == me;
  m.plastic_work.clear(), m.heating.clear(), m.L.clear(), m.F_old.clear();
  remove_particles(p, keep);
  size_step_columns(m);
}

void MpmComponent::size_step_columns(MpmMaterial& m) {
  const std::size_t n = m.particles.size();
  m.plastic_work.resize(n, 0.0);
  m.heating.resize(n, 0.0);
  m.L.resize(keeps_L(m) ? n : 0, Mat3::Zero());
  m.F_old.resize(n, Mat3::Identity());
}

void MpmComponent::lay_out_patches() {
  if (laid_out_) return;
  laid_out_ = true;
  if (keep_whole_level_ || launched_rank_count() <= 1) {  // one process: every patch here, nothing counted
    layout_ = PatchLayout::whole(setup_.grid);
    return;
  }
  layout_.level = setup_.grid;  // patch_of reads it
  std::vector<long long> count(setup_.grid.patches.size(), 0);
  for (const MpmMaterial& m : setup_.materials)
    for (const Vec3& x : m.particles.x) ++count[std::size_t(patch_of(x))];
  layout_ = PatchLayout::over_world_ranks(setup_.grid, count);
  if (!layout_.distributed) return;
  // The band exchange timed as its own phase (nested in the scatter's phase).
  band_.set_ranks(layout_.owner, world_ranks().rank, [](const std::vector<double>& v) {
    PhaseTimers::Scope t(phase_timers(), "MPI: collectives");
    return all_gather(v);
  });
  check_rank_support();
  for (MpmMaterial& m : setup_.materials) keep_own_particles(m);
}

// The node range the stencils of this rank's particles can reach: around
// each particle its domain (the larger of the seeded size and F times it,
// covering uGIMP, CPDI and CPGIMP corners) plus 3 nodes (the widest support
// beyond the domain, 4thorderBS: 2.5 cells), clamped to the grid.
void MpmComponent::set_node_boxes() {
  if (!layout_.distributed || setup_.materials.empty()) return;
  const NodeGrid& g = setup_.materials.front().grid;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (const MpmMaterial& m : setup_.materials) {
    const Particles& p = m.particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Mat3 deformed = p.F[i] * p.psize[i];
      for (int d = 0; d < 3; ++d) {
        const double e = 0.5 * std::max(p.psize[i].row(d).cwiseAbs().sum(), deformed.row(d).cwiseAbs().sum());
        const double xi = (p.x[i][d] - g.origin[d]) / g.h[d];
        lo[d] = std::min(lo[d], xi - e);
        hi[d] = std::max(hi[d], xi + e);
      }
    }
  }
  NodeBox box;
  const bool particles = lo[0] <= hi[0] && lo[1] <= hi[1] && lo[2] <= hi[2];
  for (int d = 0; d < 3; ++d) {
    if (!particles) break;  // no particles: an empty box (unless MPMICE adds its cells below)
    box.lo[d] = std::clamp(int(std::floor(lo[d])) - 3, 0, g.n[d]);
    box.hi[d] = std::clamp(int(std::floor(hi[d])) + 4, 0, g.n[d]);
  }
  // MPMICE: the nodes of the own patches' cells (with their extra cells) and
  // one node more on each side, whatever the particles: the coupled step
  // projects the nodes around each own cell to it (step 1, the burn's corner
  // masses, the face mass fluxes) and computes the cell -> node averages at
  // the nodes of its own cells (steps 7 and 13, mpmice/MpmIceRanks.cpp), so
  // those nodes must hold the sums of every rank.
  if (coupling_)
    for (int p : layout_.own) {
      const IndexRange cells = layout_.level.patches[std::size_t(p)].cells_with_extra();
      NodeBox own;
      for (int d = 0; d < 3; ++d) {
        const int off = int(std::lround((layout_.level.lower[d] - g.origin[d]) / g.h[d]));
        own.lo[d] = std::clamp(cells.lo[d] + off - 1, 0, g.n[d]);
        own.hi[d] = std::clamp(cells.hi[d] + off + 2, 0, g.n[d]);
      }
      if (own.empty()) continue;
      if (box.empty()) box = own;
      else box = NodeBox{box.lo.cwiseMin(own.lo), box.hi.cwiseMax(own.hi)};
    }
  // Periodic directions (mpm/PeriodicGrid.h): the aliases of a node lie whole
  // periods apart, and the folds after each combine add over every alias
  // set. So a box that holds any node holds the whole periodic direction:
  // every alias of every node it holds then carries the sums of all ranks
  // (the other side's image nodes may belong to another rank's particles).
  for (int d = 0; d < 3; ++d)
    if (!box.empty() && layout_.level.periodic[d]) box.lo[d] = 0, box.hi[d] = g.n[d];
  node_sums_.set_boxes(box, g.n);
  // The node-wise passes (NodeGrid::active, mpm/NodeRuns.h) visit this box
  // only, instead of the whole grid on every rank (session 23): a node outside
  // it gets no particle sum of this rank and no combine, so it holds 0 and
  // nothing of the step reads it here. Closed under the symmetry faces'
  // (extra node, mirror node) pairs: a box reaching any node of the layers
  // within 2 extra of a face takes all of them, so that the folds and the
  // grid BCs pair nodes inside the box.
  NodeBox active = box;
  for (int d = 0; d < 3 && !active.empty(); ++d) {
    const int e = g.extra[d];
    if (e <= 0 || layout_.level.periodic[d]) continue;
    if (active.lo[d] <= 2 * e) active.lo[d] = 0, active.hi[d] = std::max(active.hi[d], std::min(2 * e + 1, g.n[d]));
    if (active.hi[d] - 1 >= g.n[d] - 1 - 2 * e)
      active.hi[d] = g.n[d], active.lo[d] = std::min(active.lo[d], std::max(g.n[d] - 1 - 2 * e, 0));
  }
  for (MpmMaterial& m : setup_.materials) {
    m.grid.restricted = true;
    m.grid.active = active;
  }
}

// P2G's arrays: m_g, V_g, f_ext sums; v_g the m-weighted and sigma_g the V-weighted mean.
void MpmComponent::sum_particles_to_grid(NodeGrid& g) {
  if (!layout_.distributed) return;
  std::vector<NodeArray> a = {{g.mass.data(), 1, -1},
                              {g.volume.data(), 1, -1},
                              {g.velocity.front().data(), 3, 0},
                              {g.external_force.front().data(), 3, -1}};
  if (!g.stress.empty()) a.push_back({g.stress.front().data(), 9, 1});
  if (band())
    for (const NodeArray& x : a) keep_band_on_one_rank(x.data, x.width);
  node_sums_.combine(a);
}

// After PatchBand::reduce every rank holds the same ordered sum at every band
// node, and a node outside the band holds its sum on the rank owning the one
// patch that reaches it (0 on the others). Kept on the lowest rank whose box
// holds it and zeroed elsewhere, each node has one non-zero contribution, and
// the combine's rank-ordered sum 0 + ... + x + 0 ... is x, bit for bit (a
// weighted mean with one rank of non-zero weight keeps that rank's value).
void MpmComponent::keep_band_on_one_rank(double* data, int width) {
  if (!layout_.distributed || !band() || data == nullptr) return;
  const int me = node_sums_.rank();
  const IntVec3 n = setup_.materials.front().grid.n;
  for (std::size_t gi : band_.band_node_index()) {
    const int i = int(gi % std::size_t(n[0])), j = int((gi / std::size_t(n[0])) % std::size_t(n[1])),
              k = int(gi / (std::size_t(n[0]) * std::size_t(n[1])));
    int keeper = -1;
    for (int r = 0; r < node_sums_.size() && keeper < 0; ++r)
      if (node_sums_.box(r).contains(i, j, k)) keeper = r;
    if (keeper != me) std::fill(data + gi * std::size_t(width), data + (gi + 1) * std::size_t(width), 0.0);
  }
}

void MpmComponent::sum_band_node_doubles(double* data, int width) {
  if (!layout_.distributed || data == nullptr) return;
  keep_band_on_one_rank(data, width);
  node_sums_.combine({{data, width, -1}});
}

void MpmComponent::sum_node_vectors(std::vector<Vec3>& v) {
  if (!layout_.distributed || v.empty()) return;
  node_sums_.combine({{v.front().data(), 3, -1}});
}

void MpmComponent::sum_node_doubles(std::vector<double>& v, int width) {
  if (!layout_.distributed || v.empty()) return;
  node_sums_.combine({{v.data(), width, -1}});
}

std::vector<double> MpmComponent::whole_node_array(const std::vector<double>& data, int width) const {
  if (!layout_.distributed) return data;
  return node_sums_.whole(data.data(), width);
}

// Per-rank output (OutputPerRank, session 25): a rank writes the nodes that
// RankNodeSums::whole takes from it. Without distributed patches every rank
// holds the whole array: left unmarked, rank 0 alone writes it
// (core/io/RankFrameFile.h).
void MpmComponent::mark_node_pieces(GridFieldArray& g) const {
  if (!output_per_rank() || !layout_.distributed) return;
  g.partial = true;
  g.pieces = node_sums_.output_pieces();
}

// Entry by entry, the partials of all ranks added in rank order (the same bits on every rank).
RankSum MpmComponent::load_totals() const {
  if (!layout_.distributed) return {};
  return [](std::vector<double> partial) {
    const std::size_t n = partial.size();
    const std::vector<double> all = all_gather(partial);
    if (n == 0 || all.size() % n != 0) throw std::logic_error("MPM load totals: ranks gathered other sizes");
    std::vector<double> total(n, 0.0);
    for (std::size_t s = 0; s < all.size() / n; ++s)
      for (std::size_t k = 0; k < n; ++k) total[k] += all[s * n + k];
    return total;
  };
}

double MpmComponent::sum_over_ranks(double local) const {
  if (!layout_.distributed) return local;
  const std::vector<double> all = all_gather({local});
  double sum = 0.0;
  for (double v : all) sum += v;  // rank order: the same bits on every rank
  return sum;
}

std::vector<char> MpmComponent::first_holder_nodes() const {
  const NodeGrid& g = setup_.materials.front().grid;
  std::vector<char> mine(g.count(), 0);
  const int me = node_sums_.rank();
  const NodeBox& b = node_sums_.box(me);
  if (b.empty()) return mine;
  for (int k = b.lo[2]; k < b.hi[2]; ++k)
    for (int j = b.lo[1]; j < b.hi[1]; ++j)
      for (int i = b.lo[0]; i < b.hi[0]; ++i) {
        bool lower = false;  // held by a rank before me
        for (int r = 0; r < me && !lower; ++r) lower = node_sums_.box(r).contains(i, j, k);
        if (!lower) mine[g.index(i, j, k)] = 1;
      }
  return mine;
}

void MpmComponent::migrate_particles() {
  if (!layout_.distributed) return;
  const Ranks r = world_ranks();
  for (MpmMaterial& m : setup_.materials) {
    Particles& p = m.particles;
    const std::vector<HistoryVariable> hist = m.model->history();
    const std::size_t width = record_width(p, hist);
    std::vector<int> dest(p.size());
    std::vector<std::vector<std::size_t>> leaving(std::size_t(r.size));
    std::vector<char> keep(p.size(), 1);
    // A particle still in one of this rank's patches stays: patch_of's cell
    // (floor, clamped to the interior) tested against the own patches' cell
    // ranges first, the level's lookup only for the others (the same answer:
    // the patches do not overlap).
    const Grid& lv = layout_.level;
    bool any_leaving = false;
    for (std::size_t i = 0; i < p.size(); ++i) {
      IntVec3 c;
      for (int d = 0; d < 3; ++d)
        c[d] = std::clamp(int(std::floor((p.x[i][d] - lv.lower[d]) / lv.dx[d])), 0, lv.cells[d] - 1);
      bool own = false;
      for (int q : layout_.own) {
        const Patch& P = lv.patches[std::size_t(q)];
        if ((c.array() >= P.lo.array()).all() && (c.array() < P.hi.array()).all()) {
          own = true;
          break;
        }
      }
      dest[i] = own ? r.rank : layout_.owner[std::size_t(patch_of(p.x[i]))];
      if (dest[i] != r.rank) leaving[std::size_t(dest[i])].push_back(i), keep[i] = 0, any_leaving = true;
    }
    // Column by column: each block holds every fixed column of its particles, then the history.
    std::vector<std::vector<double>> send(std::size_t(r.size));
    for (int s = 0; s < r.size; ++s) {
      const std::vector<std::size_t>& rows = leaving[std::size_t(s)];
      if (rows.empty()) continue;
      std::vector<double>& b = send[std::size_t(s)];
      b.reserve(rows.size() * width);
      for_each_fixed_column(p, [&](const auto& col) {
        for (std::size_t i : rows) put(b, col[i]);
      });
      for (std::size_t k = 0; k < hist.size(); ++k) {
        const std::size_t c = std::size_t(hist[k].components);
        for (std::size_t i : rows) b.insert(b.end(), p.history[k].begin() + long(i * c), p.history[k].begin() + long((i + 1) * c));
      }
    }
    const std::vector<std::vector<double>> recv = exchange_blocks(send);
    if (any_leaving) remove_particles(p, keep, {&m.plastic_work, &m.heating}, {&m.L, &m.F_old});  // else the identity
    for (int s = 0; s < r.size; ++s) {
      const std::vector<double>& b = recv[std::size_t(s)];
      if (s == r.rank || b.empty()) continue;
      if (b.size() % width != 0) throw std::logic_error("MPM migration: a record of another width");
      const std::size_t n = b.size() / width;
      const double* d = b.data();
      for_each_fixed_column(p, [&](auto& col) {
        using T = typename std::decay_t<decltype(col)>::value_type;
        const std::size_t w = std::size_t(width_of(T{}));
        for (std::size_t j = 0; j < n; ++j, d += w) {
          T v;
          get(d, v);
          col.push_back(v);
        }
      });
      for (std::size_t k = 0; k < hist.size(); ++k) {
        const std::size_t c = std::size_t(hist[k].components);
        p.history[k].insert(p.history[k].end(), d, d + n * c);
        d += n * c;
      }
    }
    size_step_columns(m);
  }
}

}  // namespace tephra
