// The particle side of the burn models (mpmice/SolidBurn.h; Vaango theory
// manual sec. 26.1.3 step 4 "mass conversion").
//
// Rule. Cell c burns dm_c. The particles' share of cell c is W_c(x_p) =
// sum_{n in c} w_n S_np (w_n the node -> cell weight of step 1,
// CellProjection.h; S_np the particle's shape function), so the particles'
// mass in the cell is M'_c = sum_p m_p W_c(x_p). The cell takes the fraction
//   f_c = min(dm_c / M'_c, 1)
// of every particle's share: particle p loses
//   dm_p = m_p sum_c f_c W_c(x_p) = m_p sum_n S_np phi_n,  phi_n = w_n sum_{c ∋ n} f_c
// (phi_n: the node's burn fraction; interior cells only). Summed over the
// particles the loss in cell c is f_c M'_c = min(dm_c, M'_c) exactly, so the
// particles lose what the product gains to round-off. A particle left with
// m_p - dm_p <= <minimum_particle_mass> burns entirely (its remainder is
// split over its cells in proportion to f_c W_c): the product gets it, and
// MPM's end-of-step deletion removes the empty particle. The particle's
// volume (V_p and V0_p) shrinks with its mass; its momentum dm_p v_p and
// energy dm_p c_v T_p go with the burned mass.
//
// Uintah does the same in two steps: MPMICE's interpolateCCToNC sends the
// cell's burned-mass fraction to the nodes, and interpolateToParticlesAndUpdate
// scales p.mass and p.volume by 1 - sum_n S_np (node fraction) at the end of
// the step; its node fraction is not built from the same weights as the cell
// mass, so the particles do not lose exactly the product's mass. Here the
// mass leaves the particles at step 4, and the node sums of this step's P2G
// (m_g, m_g v_g, V_g and the body force m_g b) drop by the node sums of the
// removed mass (folded at symmetry planes as P2G folds), so the rest of the
// step (internal force, accelerations, the solid's Lagrangian cell values
// with the same loss) works on the remaining solid.
#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/grid/Loop.h"
#include "core/parallel/Ranks.h"
#include "mpm/SymmetryFold.h"
#include "mpm/shape/AxisStencils.h"
#include "mpmice/BandScatter.h"
#include "mpmice/CellProjection.h"
#include "mpmice/MpmIceComponent.h"

namespace tephra {

void MpmIceComponent::corner_masses(std::size_t s, const IntVec3& c, double wm[8]) const {
  const MpmMaterial& mm = mpm_->materials()[s];
  const NodeGrid& ng = mm.grid;
  const IntVec3 off = node_offset(ice_->grid(), ng);
  const std::array<bool, 6> symmetric = symmetry_faces(mm.bcs);
  // Axisymmetric: the planar-equivalent node masses sum_p m_p (dz/r_p) S_np
  // (solid_state_to_cells): the per-radian m_g grows with r_g inside a
  // uniform solid, so its corner ratios would flag cells near the axis as
  // surface cells and tilt the normals; the planar section has the
  // Cartesian corner values of the same cross-section (mpmice/AxisymmetricBurn.h).
  const bool axi = ice_->setup().axisymmetric;
  if (axi && node_planar_mass_.size() <= s)
    throw std::logic_error("MPMICE burn: no planar-equivalent node masses (axisymmetric) for solid " + std::to_string(s));
  const std::vector<double>& m = axi ? node_planar_mass_[s] : ng.mass;
  for (int n = 0; n < 8; ++n) {
    const IntVec3 node = c + off + IntVec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
    wm[n] = node_cell_weight(ng, symmetric, node) * m[ng.index(node)];
  }
}

// The cell holding x_p: floor((x_p - lower)/dx), interior cells only.
void MpmIceComponent::particles_per_cell(std::size_t s, CellScalars& out) const {
  const Grid& g = ice_->grid();
  out.fill(0.0);
  for (const Vec3& x : mpm_->materials()[s].particles.x) {
    IntVec3 c;
    for (int d = 0; d < 3; ++d) c[d] = int(std::floor((x[d] - g.lower[d]) / g.dx[d]));
    const int level_patch = g.patch_owning_cell(c);  // a level index (-1: outside the interior)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)  // g: this rank's patches under mpirun
      if (g.patches[pi].id == level_patch) out[pi](c) += 1.0;
  }
}

bool MpmIceComponent::particle_history_max(std::size_t s, const std::string& name, CellScalars& out) const {
  const MpmMaterial& mm = mpm_->materials()[s];
  const std::vector<HistoryVariable> h = mm.model->history();
  std::size_t k = h.size();
  for (std::size_t i = 0; i < h.size(); ++i)
    if (h[i].name == name && h[i].components == 1) k = i;
  if (k == h.size() || k >= mm.particles.history.size()) return false;
  const Grid& g = ice_->grid();
  const std::vector<double>& col = mm.particles.history[k];
  out.fill(0.0);
  for (std::size_t p = 0; p < mm.particles.size(); ++p) {
    IntVec3 c;
    for (int d = 0; d < 3; ++d) c[d] = int(std::floor((mm.particles.x[p][d] - g.lower[d]) / g.dx[d]));
    const int level_patch = g.patch_owning_cell(c);  // a level index (-1: outside the interior)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)  // g: this rank's patches under mpirun
      if (g.patches[pi].id == level_patch) out[pi](c) = std::max(out[pi](c), col[p]);
  }
  return true;
}

void MpmIceComponent::reactant_particles(std::size_t s, std::vector<BurnParticle>& out) const {
  const Grid& g = ice_->grid();
  const Particles& pa = mpm_->materials()[s].particles;
  out.clear();
  for (std::size_t p = 0; p < pa.size(); ++p) {
    IntVec3 c;
    for (int d = 0; d < 3; ++d) c[d] = int(std::floor((pa.x[p][d] - g.lower[d]) / g.dx[d]));
    const int level_patch = g.patch_owning_cell(c);  // a level index (-1: outside the interior)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      if (g.patches[pi].id == level_patch) out.push_back({pa.id[p], pi, c, pa.mass[p], pa.temperature[p]});
  }
}

void MpmIceComponent::burn_particles(std::size_t s, const CellScalars& dm, BurnedCells& out) {
  const Grid& g = ice_->grid();
  MpmMaterial& mm = mpm_->materials()[s];
  NodeGrid& ng = mm.grid;
  Particles& p = mm.particles;
  const IntVec3 off = node_offset(g, ng);
  const std::array<bool, 6> symmetric = symmetry_faces(mm.bcs);
  const double min_mass = mpm_->setup().flags.minimum_particle_mass;
  const double cv = ice_->setup().materials[s].cv;
  const Vec3 gravity = mpm_->setup().gravity;
  out.mass.fill(0.0);
  out.energy.fill(0.0);
  out.momentum.fill(Vec3::Zero());

  // Interior cells, flat: index i + nx (j + ny k); the patch holding each.
  const IntVec3 nc = g.cells;
  const std::size_t ncell = std::size_t(nc[0]) * nc[1] * nc[2];
  auto flat = [&](const IntVec3& c) { return std::size_t(c[0]) + std::size_t(nc[0]) * (std::size_t(c[1]) + std::size_t(nc[1]) * c[2]); };
  std::vector<double> dmc(ncell, 0.0);
  std::vector<int> patch_of(ncell, -1);  // own patch (index in g) of each interior cell; -1: another rank's
  bool any = false;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      dmc[flat(c)] = dm[pi](c);
      patch_of[flat(c)] = int(pi);
      any = any || dm[pi](c) > 0;
    });
  if (!mpm_->layout().any(any)) return;  // every MPI rank takes the same branch (collectives below)
  // Axisymmetric (x = r): along r a particle's share of node n goes to the
  // node's cell on the particle's side (r_p >= r_n: the cell above; a
  // particle whose domain straddles the node splits it by its share a,
  // mpmice/AxisymmetricShare.h), with weight 2 w_n (w_n on the axis plane),
  // as the projection does (mpmice/CellProjection.h):
  // W_c(x_p) = sum_{n in c} W_n S_np (a if c is above n, else 1 - a),
  // so M'_c is the projected cell mass M_c (f_c <= 1 <=> dm_c <= the solid's cell mass).
  const bool axi = ice_->setup().axisymmetric;
  // The interior cells that share node gi (up to 8), with the node's weight
  // (axisymmetric: W_n), the flat index of the cell's lower corner node
  // (where a band keeps the cell's partials) and whether the cell lies above
  // the node in x.
  auto for_node_cells = [&](std::size_t gi, auto&& fn) {
    const std::size_t nx = std::size_t(ng.n[0]), ny = std::size_t(ng.n[1]);
    const IntVec3 node(int(gi % nx), int((gi / nx) % ny), int(gi / (nx * ny)));
    bool on[3];
    double w = node_cell_weight(ng, symmetric, node, on);
    if (axi) w = axisymmetric_node_cell_weight(w, on[0], 1.0);
    for (int q = 0; q < 8; ++q) {
      const IntVec3 corner = node - IntVec3(q & 1, (q >> 1) & 1, (q >> 2) & 1);
      const IntVec3 c = corner - off;
      if ((c.array() < 0).any() || (c.array() >= nc.array()).any()) continue;
      fn(flat(c), w, ng.index(corner), (q & 1) == 0);
    }
  };
  // Node and cell sums in patch order at the band nodes (mpmice/BandScatter.h):
  // the same bits on any rank count.
  PatchBand* band = mpm_->coupling_band(1);
  if (axi && band) throw std::logic_error("MPMICE burn: axisymmetric runs have no coupling band");
  const std::size_t node_nx = std::size_t(ng.n[0]);
  // Axisymmetric: particle i's share above node gi in r (CellProjection.h's
  // rule, mpmice/AxisymmetricShare.h: 1 above, 0 below, the domain overlap
  // where the domain straddles the node).
  const InterpolatorKind kind = mpm_->setup().flags.interpolator.kind;
  auto above = [&](std::size_t i, std::size_t gi) {
    const double r_g = ng.origin[0] + double(gi % node_nx) * ng.h[0];
    return axisymmetric_share_above(kind, (p.x[i][0] - r_g) / ng.h[0], 0.5 * p.psize[i](0, 0));
  };
  // M'_c = sum_p m_p W_c(x_p), from the unfolded node sums m'_n = sum_p m_p S_np
  // (axisymmetric: m'_n = sum_p a m_p S_np above the node, m_below with 1 - a).
  std::vector<double> m_unfolded(ng.count(), 0.0), m_below;
  if (axi) m_below.assign(ng.count(), 0.0);
  stencil_coupling_band(band, mm.stencils);
  visit_stencils(mm.stencils, [&](const auto& view) {
    for_each_coupling_particle(mm.stencils, p.size(), band, [&](std::size_t i) {
      const int P = stencil_coupling_tag(band, view, i, p.x[i]);
      view.weights(i, [&](std::size_t gi, double S) {
        if (axi) {  // no band in axisymmetric runs (checked above)
          const double a = above(i, gi);
          m_unfolded[gi] += a * (p.mass[i] * S);
          m_below[gi] += (1.0 - a) * (p.mass[i] * S);
        } else {
          *band_target(band, P, gi, 0, &m_unfolded[gi]) += p.mass[i] * S;
        }
      });
    });
  });
  if (axi) mpm_->sum_node_doubles(m_below);
  // MPI ranks: the node sums of every rank's particles, at the nodes of the
  // rank's box (which holds its own cells' corners); no-ops in one process.
  if (band) {
    band->reduce(1, [&](std::size_t gi, const double* q) { m_unfolded[gi] = q[0]; });
    mpm_->sum_band_node_doubles(m_unfolded.data(), 1);
  } else {
    mpm_->sum_node_doubles(m_unfolded);
  }
  std::vector<double> Mc(ncell, 0.0);
  for (std::size_t gi = 0; gi < ng.count(); ++gi) {
    const double mb = axi ? m_below[gi] : 0.0;
    if (m_unfolded[gi] > 0 || mb > 0)
      for_node_cells(gi, [&](std::size_t c, double w, std::size_t, bool up) { Mc[c] += w * (axi && !up ? mb : m_unfolded[gi]); });
  }
  std::vector<double> f(ncell, 0.0);
  for (std::size_t c = 0; c < ncell; ++c)
    if (dmc[c] > 0 && Mc[c] > 0) f[c] = std::min(dmc[c] / Mc[c], 1.0);
  // MPI ranks: f_c is computed by the rank owning c; a particle near a patch
  // cut also burns in the other rank's cells, so every rank gets every
  // burning cell's f_c (few: surface cells), then phi_n has one-process bits.
  if (mpm_->layout().distributed) {
    std::vector<double> mine;
    for (std::size_t c = 0; c < ncell; ++c)
      if (f[c] > 0) mine.insert(mine.end(), {double(c), f[c]});
    const std::vector<double> all = all_gather(mine);
    for (std::size_t k = 0; k + 2 <= all.size(); k += 2) f[std::size_t(all[k])] = all[k + 1];
  }
  // phi_n = w_n sum_{c ∋ n} f_c (axisymmetric: phi over the cells above the
  // node for the particles above it, phi_below over the cells below).
  std::vector<double> phi(ng.count(), 0.0), phi_below;
  if (axi) phi_below.assign(ng.count(), 0.0);
  for (std::size_t gi = 0; gi < ng.count(); ++gi)
    if (m_unfolded[gi] > 0 || (axi && m_below[gi] > 0))
      for_node_cells(gi, [&](std::size_t c, double w, std::size_t, bool up) { (axi && !up ? phi_below : phi)[gi] += w * f[c]; });

  // The particles: their loss, its cell shares, and the node sums of the loss.
  NodeGrid& d = burn_grid_;
  d.origin = ng.origin;
  d.h = ng.h;
  d.n = ng.n;
  d.extra = ng.extra;
  d.node_stress = false;
  d.reset();
  std::vector<double> cell_mass(ncell, 0.0), cell_energy(ncell, 0.0);
  std::vector<Vec3> cell_mom(ncell, Vec3::Zero());
  // Band partial columns (mpmice/BandScatter.h): at a node, the removed m (0),
  // m v (1-3), m b (4-6) and V (7); at a cell's lower corner node, the
  // cell's share of mass (8), momentum (9-11) and energy (12).
  visit_stencils(mm.stencils, [&](const auto& view) {
    for_each_coupling_particle(mm.stencils, p.size(), band, [&](std::size_t i) {
      // The particle's burn fraction through node gi (axisymmetric: its sides' by its shares).
      auto phi_of = [&](std::size_t gi) {
        if (!axi) return phi[gi];
        const double a = above(i, gi);
        return a * phi[gi] + (1.0 - a) * phi_below[gi];
      };
      double a = 0;
      view.weights(i, [&](std::size_t gi, double S) { a += S * phi_of(gi); });
      if (!(a > 0)) return;
      const int P = coupling_tag(band, p.x[i]);
      const double m0 = p.mass[i];
      double dmp = std::min(a * m0, m0);
      if (m0 - dmp <= min_mass) dmp = m0;
      const double scale = dmp / a;  // cell c's share: scale x S w_n f_c
      const Vec3 v = p.v[i];
      const double e = cv * p.temperature[i];
      view.weights(i, [&](std::size_t gi, double S) {
        if (!(phi_of(gi) > 0)) return;
        const double a = axi ? above(i, gi) : 1.0;
        for_node_cells(gi, [&](std::size_t c, double w, std::size_t corner, bool up) {
          const double side = !axi ? 1.0 : up ? a : 1.0 - a;  // the particle's share on c's side of the node
          if (!(f[c] > 0) || side == 0.0) return;
          const double share = scale * S * w * f[c] * side;
          *band_target(band, P, corner, 8, &cell_mass[c]) += share;
          Eigen::Map<Vec3>(band_target(band, P, corner, 9, cell_mom[c].data())) += share * v;
          *band_target(band, P, corner, 12, &cell_energy[c]) += share * e;
        });
        *band_target(band, P, gi, 0, &d.mass[gi]) += dmp * S;
        Eigen::Map<Vec3>(band_target(band, P, gi, 1, d.velocity[gi].data())) += dmp * S * v;  // momentum until the fold below
        Eigen::Map<Vec3>(band_target(band, P, gi, 4, d.external_force[gi].data())) += dmp * S * gravity;
      });
      const double ratio = dmp == m0 ? 0.0 : (m0 - dmp) / m0;
      const double dV = p.volume[i] * (1 - ratio);
      view.weights(i, [&](std::size_t gi, double S) { *band_target(band, P, gi, 7, &d.volume[gi]) += dV * S; });
      p.mass[i] = m0 - dmp;
      if (dmp == m0) p.mass[i] = 0.0;
      p.volume[i] *= ratio;
      p.volume0[i] *= ratio;
    });
  });
  // MPI ranks: the removed sums of every rank's particles, and the shares of
  // cells another rank owns sent to it. With a band, every rank holds the
  // whole ordered sum at a band node after reduce (a cell there is not
  // sent: its owner has it); any other node or cell is reached by the
  // particles of one patch only, so its one rank's value is the sum.
  if (band) {
    band->reduce(13, [&](std::size_t gi, const double* q) {
      d.mass[gi] = q[0];
      d.velocity[gi] = Eigen::Map<const Vec3>(q + 1);
      d.external_force[gi] = Eigen::Map<const Vec3>(q + 4);
      d.volume[gi] = q[7];
      const std::size_t nx = std::size_t(ng.n[0]), ny = std::size_t(ng.n[1]);
      const IntVec3 c = IntVec3(int(gi % nx), int((gi / nx) % ny), int(gi / (nx * ny))) - off;
      if ((c.array() < 0).any() || (c.array() >= nc.array()).any()) return;
      cell_mass[flat(c)] = q[8];
      cell_mom[flat(c)] = Eigen::Map<const Vec3>(q + 9);
      cell_energy[flat(c)] = q[12];
    });
    mpm_->sum_band_node_doubles(d.mass.data(), 1);
    mpm_->sum_band_node_doubles(d.velocity.front().data(), 3);
    mpm_->sum_band_node_doubles(d.external_force.front().data(), 3);
    mpm_->sum_band_node_doubles(d.volume.data(), 1);
  } else {
    mpm_->sum_node_doubles(d.mass);
    mpm_->sum_node_vectors(d.velocity);
    mpm_->sum_node_vectors(d.external_force);
    mpm_->sum_node_doubles(d.volume);
  }
  if (mpm_->layout().distributed) {
    std::vector<char> in_band(ncell, 0);  // cells whose lower corner node is a band node
    if (band)
      for (std::size_t c = 0; c < ncell; ++c) {
        const IntVec3 cell(int(c % std::size_t(nc[0])), int((c / std::size_t(nc[0])) % std::size_t(nc[1])),
                           int(c / (std::size_t(nc[0]) * nc[1])));
        in_band[c] = band->slot(ng.index(cell + off)) >= 0;
      }
    send_burned_shares(patch_of, in_band, cell_mass, cell_mom, cell_energy);
  }
  // Fold the removed sums as P2G folds its sums (symmetry planes), then take
  // them out of this step's node sums.
  for (std::size_t gi = 0; gi < d.count(); ++gi)
    if (d.mass[gi] > 0) d.velocity[gi] /= d.mass[gi];
  fold_symmetry_particle_sums(mm.bcs, d, mpm_->setup().flags.axisymmetric ? 2 : 3);  // as P2G folds (not the hoop faces)
  for (std::size_t gi = 0; gi < ng.count(); ++gi) {
    if (!(d.mass[gi] > 0)) continue;
    const double m_old = ng.mass[gi];
    const Vec3 P = ng.velocity[gi] * m_old - d.velocity[gi] * d.mass[gi];
    double m_new = m_old - d.mass[gi];
    if (m_new <= 1e-12 * m_old) {  // the node's solid is gone (round-off left)
      ng.mass[gi] = 0;
      ng.velocity[gi] = Vec3::Zero();
      ng.volume[gi] = 0;
      ng.external_force[gi] = Vec3::Zero();
      continue;
    }
    ng.mass[gi] = m_new;
    ng.velocity[gi] = P / m_new;
    ng.volume[gi] = std::max(0.0, ng.volume[gi] - d.volume[gi]);
    ng.external_force[gi] -= d.external_force[gi];
  }
  mm.bcs.apply(ng, ng.velocity);
  for (std::size_t c = 0; c < ncell; ++c) {
    if (!(cell_mass[c] > 0) || patch_of[c] < 0) continue;
    const std::size_t pi = std::size_t(patch_of[c]);
    const IntVec3 cell(int(c % std::size_t(nc[0])), int((c / std::size_t(nc[0])) % std::size_t(nc[1])),
                       int(c / (std::size_t(nc[0]) * nc[1])));
    out.mass[pi](cell) = cell_mass[c];
    out.momentum[pi](cell) = cell_mom[c];
    out.energy[pi](cell) = cell_energy[c];
  }
}

// The burned shares of interior cells this rank does not own (patch_of < 0),
// flat index i + nx (j + ny k), go to the owning ranks (one all-to-all), which
// add them to their own: records (cell, mass, momentum x3, energy).
void MpmIceComponent::send_burned_shares(const std::vector<int>& patch_of, const std::vector<char>& in_band,
                                         std::vector<double>& mass, std::vector<Vec3>& momentum,
                                         std::vector<double>& energy) const {
  const PatchLayout& layout = ice_->layout();
  const IntVec3 nc = layout.level.cells;
  const Ranks r = world_ranks();
  std::vector<std::vector<double>> send(std::size_t(r.size));
  for (std::size_t c = 0; c < mass.size(); ++c) {
    if (patch_of[c] >= 0 || !(mass[c] > 0)) continue;
    if (in_band[c]) {  // the owner holds the whole sum already (PatchBand::reduce)
      mass[c] = 0, momentum[c] = Vec3::Zero(), energy[c] = 0;
      continue;
    }
    const IntVec3 cell(int(c % std::size_t(nc[0])), int((c / std::size_t(nc[0])) % std::size_t(nc[1])),
                       int(c / (std::size_t(nc[0]) * nc[1])));
    const int p = layout.level.patch_owning_cell(cell);
    if (p < 0) throw std::logic_error("MPMICE burn: an interior cell without a patch");
    std::vector<double>& b = send[std::size_t(layout.owner[std::size_t(p)])];
    b.insert(b.end(), {double(c), mass[c], momentum[c][0], momentum[c][1], momentum[c][2], energy[c]});
    mass[c] = 0, momentum[c] = Vec3::Zero(), energy[c] = 0;
  }
  const std::vector<std::vector<double>> recv = exchange_blocks(send);
  for (int s = 0; s < r.size; ++s) {
    if (s == r.rank) continue;
    const std::vector<double>& b = recv[std::size_t(s)];
    for (std::size_t k = 0; k + 6 <= b.size(); k += 6) {
      const std::size_t c = std::size_t(b[k]);
      mass[c] += b[k + 1];
      momentum[c] += Vec3(b[k + 2], b[k + 3], b[k + 4]);
      energy[c] += b[k + 5];
    }
  }
}

}  // namespace tephra
