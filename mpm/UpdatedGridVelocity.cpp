#include "mpm/UpdatedGridVelocity.h"

#include <algorithm>

#include "mpm/BandTag.h"
#include "mpm/NodeRuns.h"
#include "mpm/PatchBand.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {

namespace {

// o[gi] += S momentum for every stencil node of particle i; with a band and a
// band particle (patch P >= 0) the band nodes' terms go to their (node, P) partials.
template <class View>
[[gnu::flatten]] inline void scatter_momentum(const View& view, std::size_t i, const Vec3& momentum, Vec3* o, PatchBand* band,
                             int P) {
  if (P < 0) {
    view.weights(i, [&](std::size_t gi, double wk) { o[gi] += wk * momentum; });
    return;
  }
  view.weights(i, [&](std::size_t gi, double wk) {
    const int k = band->slot(gi);
    if (k < 0) o[gi] += wk * momentum;
    else Eigen::Map<Vec3>(band->partial(k, P)) += wk * momentum;
  });
}

void reduce_momentum(PatchBand* band, Vec3* o) {
  if (band) band->reduce(3, [&](std::size_t gi, const double* q) { o[gi] = Eigen::Map<const Vec3>(q); });
}

}  // namespace

void updated_particle_grid_velocity(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                    const std::vector<std::size_t>* canonical, std::vector<Vec3>& out,
                                    PatchBand* band) {
  band = band_for_scatter(band, s);
  const std::size_t nodes = g.mass.size();
  out.assign(nodes, Vec3::Zero());
  // sum m_p S_gp v_p^{n+1}, in the scatter order of P2G (ScatterOrder.h: the
  // same bits for any thread count).
  Vec3* o = out.data();
  const Vec3* acc = g.acceleration.data();
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      Vec3 a = Vec3::Zero();
      view.weights(i, [&](std::size_t gi, double wk) { a += wk * acc[gi]; });
      const Vec3 momentum = p.mass[i] * (p.v[i] + dt * a);
      scatter_momentum(view, i, momentum, o, band, band ? band_tag(*band, view, i, p.x[i]) : -1);
    });
  });
  reduce_momentum(band, o);
  if (canonical && !canonical->empty()) {
    std::vector<Vec3> sum(nodes, Vec3::Zero());
    for (std::size_t n = 0; n < nodes; ++n) sum[(*canonical)[n]] += out[n];
    for (std::size_t n = 0; n < nodes; ++n) out[n] = sum[(*canonical)[n]];
  }
  for (std::size_t n = 0; n < nodes; ++n) out[n] = g.mass[n] > 0.0 ? Vec3(out[n] / g.mass[n]) : Vec3::Zero();
}

}  // namespace tephra

namespace tephra {

void keep_stable_usl_nodes(const NodeGrid& g, double limit, double cell_volume, const std::vector<Vec3>& v_star,
                           std::vector<Vec3>& v, const std::vector<double>* full_x) {
  // Node by node over the active box (the whole grid in one process), no sums:
  // the same bits for any thread count.
  if (full_x) {
    const std::size_t nx = std::size_t(g.n[0]);
    const double* full = full_x->data();
    for_each_active_node(g, [&](std::size_t n) {
      if (g.volume[n] >= limit * full[n % nx]) v[n] = v_star[n];
    });
    return;
  }
  for_each_active_node(g, [&](std::size_t n) {
    if (g.volume[n] >= limit * cell_volume) v[n] = v_star[n];
  });
}

}  // namespace tephra

namespace tephra {

std::size_t usl_needed_nodes(const NodeGrid& g, double limit, double cell_volume, std::vector<unsigned char>& needed,
                             const std::vector<double>* full_x) {
  const std::size_t nodes = g.count();
  // Restricted to the active box (on MPI ranks, NodeGrid.h): 0 outside it
  // (no particle of this rank reaches a node there); in one process every
  // entry is written below (0 or 1), no separate zero fill.
  if (g.restricted) needed.assign(nodes, 0);
  else needed.resize(nodes);
  unsigned char* need = needed.data();
  const long count = long(nodes);
  const NodeRuns runs = node_runs(g);
  const long nruns = runs.count;
  const std::size_t len = runs.length;
  std::size_t weak = 0;
  const double* full = full_x ? full_x->data() : nullptr;  // per node index along x (axisymmetric), else cell_volume
  const std::size_t row = std::size_t(g.n[0]);
  // Threaded over the runs (one run, split over the threads, for the whole
  // grid): a count is exact in any order.
  if (nruns == 1) {
    const long n0 = long(runs.first), n1 = long(runs.first + len);
#pragma omp parallel for schedule(static) reduction(+ : weak) if (count >= 4096)
    for (long n = n0; n < n1; ++n) {
      const bool w = !(g.volume[n] >= limit * (full ? full[std::size_t(n) % row] : cell_volume));  // keep_stable_usl_nodes' test negated
      need[n] = w;
      weak += w;
    }
  } else {
#pragma omp parallel for schedule(static) reduction(+ : weak) if (long(runs.nodes()) >= 4096)
    for (long q = 0; q < nruns; ++q)
      for (std::size_t n = runs.begin(q), e = runs.begin(q) + len; n < e; ++n) {
        const bool w = !(g.volume[n] >= limit * (full ? full[n % row] : cell_volume));
        need[n] = w;
        weak += w;
      }
  }
  if (weak == 0) return 0;
  // The node planes c_d <= 2 extra_d or c_d >= n_d - 1 - 2 extra_d of any
  // direction d: whole rows of i where (j, k) is in a y or z layer, else the
  // first and last 2 extra_x + 1 nodes of the row.
  // Rows of the active box only (the whole grid in one process).
  const int nx = g.n[0], ny = g.n[1], nz = g.n[2];
  const int ex = 2 * g.extra[0], ey = 2 * g.extra[1], ez = 2 * g.extra[2];
  const NodeBox box = g.active_box();
  const int by = box.hi[1] - box.lo[1];
  const long rows = long(by) * (box.hi[2] - box.lo[2]);
#pragma omp parallel for schedule(static) if (count >= 4096)
  for (long r = 0; r < rows; ++r) {
    const int j = box.lo[1] + int(r % by), k = box.lo[2] + int(r / by);
    unsigned char* row = need + g.index(0, j, k);
    const bool layer = j <= ey || j >= ny - 1 - ey || k <= ez || k >= nz - 1 - ez;
    for (int i = box.lo[0]; i < box.hi[0]; ++i)
      if (layer || i <= ex || i >= nx - 1 - ex) row[i] = 1;
  }
  return weak;
}

void updated_particle_grid_velocity_at(const Particles& p, const Stencils& s, const NodeGrid& g, double dt,
                                       const std::vector<unsigned char>& needed, std::vector<Vec3>& out,
                                       PatchBand* band) {
  band = band_for_scatter(band, s);
  const std::size_t nodes = g.mass.size();
  const bool resized = out.size() != nodes;
  out.resize(nodes);
  Vec3* o = out.data();
  // Threaded zero fill (same bits). On MPI ranks (NodeGrid::restricted) only
  // where this buffer or g.velocity_star, which it is swapped with, held values
  // since the last reset: the hull of the last two active boxes (NodeGrid::cleared).
  const NodeBox zero_box = g.restricted && !resized ? g.cleared : NodeBox{IntVec3::Zero(), g.n};
  for_each_run_node(node_runs(g, zero_box), [&](std::size_t n) { o[n].setZero(); });
  // No needed node here: nothing to sum. But the band reduce below is
  // collective on ranks (PatchBand::reduce gathers every rank's partials), and
  // whether a rank has a needed node is its own answer: a rank whose node box
  // is the whole grid can have none while a rank without patches (empty box,
  // V_g = 0 at every node) needs them all. So with a band every rank still
  // takes part in the reduce (its partials are zero: a particle reaches only
  // nodes of its rank's box, where every rank holds the same V_g and so the
  // same needed flags), else the others wait for it for ever (issue 7: the
  // 4-rank hang with fewer patches than ranks).
  // 0 outside the active box. A threaded OR (was std::find on the main thread
  // while the other threads waited: ~0.3 M instructions per step on spheres.ups).
  const long flags = long(needed.size());
  const unsigned char* flag = needed.data();
  unsigned char any = 0;
#pragma omp parallel for schedule(static) reduction(| : any) if (flags >= 4096)
  for (long n = 0; n < flags; ++n) any |= flag[n];
  const bool any_needed = any != 0;
  if (!any_needed) {
    reduce_momentum(band, o);  // every rank's band partials are zero then (no particle reaches a needed node)
    return;
  }
  // The scatter order of P2G (ScatterOrder.h), threaded; the particles whose
  // stencil reaches no needed node are skipped.
  const Vec3* acc = g.acceleration.data();
  const unsigned char* need = needed.data();
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      bool reaches = false;
      view.weights(i, [&](std::size_t gi, double) { reaches = reaches || need[gi]; });
      if (!reaches) return;
      Vec3 a = Vec3::Zero();
      view.weights(i, [&](std::size_t gi, double wk) { a += wk * acc[gi]; });
      const Vec3 momentum = p.mass[i] * (p.v[i] + dt * a);
      scatter_momentum(view, i, momentum, o, band, band ? band_tag(*band, view, i, p.x[i]) : -1);
    });
  });
  reduce_momentum(band, o);
  for_each_active_node(g, [&](std::size_t n) {  // needed nodes lie in the active box
    if (need[n]) o[n] = g.mass[n] > 0.0 ? Vec3(o[n] / g.mass[n]) : Vec3::Zero();
  });
}

}  // namespace tephra
