// The solids' mass fluxes through the cell faces from the particles' motion
// (docs/mpmice.md "Volume fluxes"; used by ICE's delP and the fluids'
// advection, ice/IceLagrangianFlux.cpp).
//
// The solid's cell mass is the projection M_c(x) = sum_p m_p W_c(x_p), W_c the
// node -> cell average of the shape functions (CellProjection.h). Over the
// step the particles move by d_p = dt sum_g S_gp v_g (the P2G grid velocity:
// the MPM position update x += dt sum S v*_g with v*_g not yet known; exact
// for a uniform translation). The change of the projection is split by axis,
//   M(x1, y1, z1) - M(x0, y0, z0) = [M(x1, y0, z0) - M(x0, y0, z0)]   (x motion)
//                                  + [M(x1, y1, z0) - M(x1, y0, z0)]   (y motion)
//                                  + [M(x1, y1, z1) - M(x1, y1, z0)]   (z motion),
// and the change dM^d of axis d along each grid row of that axis is the
// difference of face fluxes, summed from the row's lower end (no flux enters
// below the first extra cell; at a symmetry plane none crosses the plane):
//   F_{i+1/2} = F_{i-1/2} - dM^d_i.
// The total flux of a row vanishes at its upper end to round-off because the
// weights of a particle's x motion, at fixed y and z, sum to the same value
// (partition of unity) - except next to a symmetry plane normal to d, whose
// doubled node weights do not (the mirror particles are not moved).
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "core/grid/Loop.h"
#include "mpm/SymmetryFold.h"
#include "mpm/shape/AxisStencils.h"
#include "mpm/shape/AxisShape.h"
#include "core/parallel/Ranks.h"
#include "mpmice/BandScatter.h"
#include "mpmice/CellProjection.h"
#include "mpmice/MpmIceComponent.h"

namespace tephra {

namespace {

// Index of cell c in a flat array over the grid's cells with extra cells.
struct CellIndex {
  IndexRange r;
  IntVec3 n;
  explicit CellIndex(const Grid& g) : r(g.cells_with_extra()), n(r.hi - r.lo) {}
  std::size_t count() const { return std::size_t(n[0]) * n[1] * n[2]; }
  std::size_t operator()(const IntVec3& c) const {
    const IntVec3 a = c - r.lo;
    return std::size_t(a[0]) + std::size_t(n[0]) * (std::size_t(a[1]) + std::size_t(n[1]) * a[2]);
  }
};

// The particles' 1-D shape factors per axis (the per-axis stencil form of
// mpm/shape/Interpolator.h: S_gp = S_x[a] S_y[b] S_z[c]), kept per axis so that
// a move along one axis recomputes that axis only: the other axes' factors
// depend on the other coordinates, which the move leaves bit for bit.
// The factors come from axis_shape (mpm/shape/AxisShape.h), which
// compute_axis_stencils uses too, so the weights S_x S_y S_z, formed in the
// same order, are the same bits.
struct AxisFactors {
  int N = 0;                       // nodes per axis: 2 linear, 3 GIMP / quadratic B-spline; 0: no per-axis form
  std::vector<int> first[3];       // lowest node of particle i's support along d
  std::vector<double> S[3];        // S[d][i * N + a]

  // Axis d of every particle of q on grid sg (mpm/shape/AxisShape.h, the
  // rule of compute_axis_stencils); false when some particle's support
  // leaves the grid along d.
  bool fill(InterpolatorKind kind, const Particles& q, const NodeGrid& sg, int d) {
    const std::size_t np = q.size();
    first[d].resize(np);
    S[d].resize(np * std::size_t(N));
    bool ok = true;
    for (std::size_t i = 0; i < np; ++i) {
      const double half_length = kind == InterpolatorKind::Gimp ? 0.5 * q.psize[i](d, d) : 0.0;
      ShapeAxis ax;
      if (!axis_shape(kind, q.x[i][d], sg.origin[d], sg.h[d], sg.n[d], half_length, ax)) {
        ok = false;
        continue;
      }
      first[d][i] = ax.first;
      for (int a = 0; a < N; ++a) S[d][i * std::size_t(N) + std::size_t(a)] = ax.S[a];
    }
    return ok;
  }

  // m_g += m_i S_gp for particle i, its nodes x fastest (the order of
  // visit_stencils, so the same sums); at(gi) the entry to add to
  // (mpmice/BandScatter.h: the node, or a band partial). m_above
  // (axisymmetric, when given, with x the particle's position and
  // half_length its domain's half-length along x in cells): the part above
  // the node (node_mass_above, mpmice/CellProjection.h), m_above indexed by node.
  template <int NN, class At>
  void scatter_mass(std::size_t i, double mass, const NodeGrid& sg, At&& at, const Vec3* x = nullptr,
                    double* m_above = nullptr, InterpolatorKind kind = InterpolatorKind::Linear,
                    double half_length = 0.0) const {
    const std::size_t sy = std::size_t(sg.n[0]), sz = std::size_t(sg.n[0]) * std::size_t(sg.n[1]);
    const double* X = S[0].data() + i * NN;
    const double* Y = S[1].data() + i * NN;
    const double* Z = S[2].data() + i * NN;
    const std::size_t base = sg.index(first[0][i], first[1][i], first[2][i]);
    for (int c = 0; c < NN; ++c)
      for (int b = 0; b < NN; ++b) {
        const std::size_t row = base + sy * std::size_t(b) + sz * std::size_t(c);
        const double y = Y[b], z = Z[c];
        for (int a = 0; a < NN; ++a) *at(row + std::size_t(a)) += mass * (X[a] * y * z);
        if (m_above)  // the share above each node (mpmice/AxisymmetricShare.h)
          for (int a = 0; a < NN; ++a) {
            const double t = ((*x)[0] - (sg.origin[0] + (first[0][i] + a) * sg.h[0])) / sg.h[0];
            m_above[row + std::size_t(a)] += axisymmetric_share_above(kind, t, half_length) * (mass * (X[a] * y * z));
          }
      }
  }
};

// a (flat over the cells with extra cells, CellIndex) summed over the MPI
// ranks through a node-shaped copy (cell c at node c + off).
void sum_cell_array_over_ranks(MpmComponent& mpm, const IndexRange& cells, const IntVec3& off, const NodeGrid& ng,
                               const CellIndex& ci, std::vector<double>& a) {
  std::vector<double> nodes(ng.count(), 0.0);
  auto each = [&](auto&& fn) {
    for_each_cell_serial(cells, [&](int i, int j, int k) {
      const IntVec3 c(i, j, k), n = c + off;
      if ((n.array() < 0).any() || (n.array() >= ng.n.array()).any())
        throw std::logic_error("MPMICE: a cell without its lower node");
      fn(a[ci(c)], nodes[ng.index(n)]);
    });
  };
  each([](double& cell, double& node) { node = cell; });
  mpm.sum_node_doubles(nodes);
  each([](double& cell, double& node) { cell = node; });
}

// dM (flat over the cells with extra cells, CellIndex) on every rank: each
// cell's value from the rank owning its patch (g: this rank's patches; one
// all-gather of (cell, value) pairs).
void gather_own_cells(const Grid& g, const CellIndex& ci, std::vector<double>& dM) {
  std::vector<double> mine;
  for (const Patch& patch : g.patches)
    for_each_cell_serial(patch.cells_with_extra(), [&](int i, int j, int k) {
      const std::size_t c = ci(IntVec3(i, j, k));
      mine.insert(mine.end(), {double(c), dM[c]});
    });
  const std::vector<double> all = all_gather(mine);
  std::fill(dM.begin(), dM.end(), 0.0);
  for (std::size_t k = 0; k + 2 <= all.size(); k += 2) dM[std::size_t(all[k])] = all[k + 1];
}

}  // namespace

// Cost (docs/performance.md, MPMICE): per material, one projection of the
// particles' start positions and one per axis along which some particle
// moves (an axis with no displacement at all - z of a 2-D deck - has
// M1 = M0 bit for bit and so zero flux: skipped); each projection
// recomputes only the moved axis' shape factors, scatters the mass alone
// (not the whole NodeGrid) and averages nodes to cells with the node
// weights tabulated once. The result is bit for bit that of projecting all
// particles with compute_axis_stencils + P2G + fold + the node -> cell sum;
// an interpolator without the per-axis form, or a particle whose per-axis
// support fails, takes that general route (project_general below).
void MpmIceComponent::solid_mass_fluxes(double dt) {
  const Grid& g = ice_->grid();
  const CellIndex ci(g);
  const InterpolatorSpec& spec = mpm_->setup().flags.interpolator;
  for (std::size_t s = 0; s < mpm_->materials().size(); ++s) {
    const MpmMaterial& mm = mpm_->materials()[s];
    const NodeGrid& ng = mm.grid;
    const Particles& p = mm.particles;
    const IntVec3 off = node_offset(g, ng);
    const std::array<bool, 6> symmetric = symmetry_faces(mm.bcs);
    std::vector<double> node_mass, node_above;  // node_above: m_g^+ (axisymmetric only)
    const bool axi = ice_->setup().axisymmetric;
    // d_p = dt sum_g S_gp v_g.
    std::vector<Vec3> disp(p.size(), Vec3::Zero());
    double moved_cells = 0;  // the largest |d_p| along an axis, in cells
    visit_stencils(mm.stencils, [&](const auto& view) {
      for (std::size_t i = 0; i < p.size(); ++i) {
        view.weights(i, [&](std::size_t gi, double w) { disp[i] += dt * w * ng.velocity[gi]; });
        for (int d = 0; d < 3; ++d) moved_cells = std::max(moved_cells, std::abs(disp[i][d]) / ng.h[d]);
      }
    });
    // The projections in patch order at the band nodes (mpmice/BandScatter.h):
    // a particle tagged by its patch (its position at the step's start, where
    // it lives on the ranks) reaches at most ceil(moved_cells) nodes beyond
    // its stencil, so the band is widened by that much (at least 1, as the
    // other coupled scatters ask). The particles' nodes then all lie in
    // their patch's reach box, and the projected node masses (so M_c and
    // the fluxes) have the same bits on any rank count.
    PatchBand* band = mpm_->coupling_band(std::max(1, int(std::ceil(moved_cells))));
    const bool by_band = band != nullptr;  // the same on every rank (MpmComponent::coupling_band)
    // The node masses of the projection, the band partials added in patch
    // order and, on ranks, combined (one contribution per node): the sums
    // of every patch at the nodes of the own cells.
    auto reduce_band = [&] {  // collective on ranks: every rank calls it once per projection
      if (!band) return;
      band->reduce(1, [&](std::size_t gi, const double* q) { node_mass[gi] = q[0]; });
      mpm_->sum_band_node_doubles(node_mass.data(), 1);
    };
    auto scatter = [&](auto&& particle_mass) {
      node_mass.assign(ng.count(), 0.0);  // ng: the grid of sg
      for_each_coupling_particle(mm.stencils, p.size(), band, [&](std::size_t i) {
        const int P = coupling_tag(band, p.x[i]);
        particle_mass(i, [&](std::size_t gi) { return band_target(band, P, gi, 0, &node_mass[gi]); });
      });
      reduce_band();
    };
    // Scratch particles (position and domain: what the per-axis factors read).
    Particles& q = flux_particles_;
    q.x = p.x;
    q.psize = p.psize;
    NodeGrid& sg = flux_grid_;
    sg.origin = ng.origin;
    sg.h = ng.h;
    sg.n = ng.n;
    sg.extra = ng.extra;
    // The node -> cell weight of every node (CellProjection.h).
    std::vector<double> wnode(sg.count());
    for (int k = 0; k < sg.n[2]; ++k)
      for (int j = 0; j < sg.n[1]; ++j)
        for (int i = 0; i < sg.n[0]; ++i) wnode[sg.index(i, j, k)] = node_cell_weight(sg, symmetric, IntVec3(i, j, k));
    // M_c = sum of its 8 corner nodes' w_n m_n (n in the order 0..7, x fastest).
    auto nodes_to_cells = [&](std::vector<double>& M) {
      M.assign(ci.count(), 0.0);
      for_each_cell_serial(g.cells_with_extra(), [&](int i, int j, int k) {
        const IntVec3 c(i, j, k);
        double sum = 0;
        for (int n = 0; n < 8; ++n) {
          const IntVec3 node = c + off + IntVec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
          if ((node.array() < 0).any() || (node.array() >= sg.n.array()).any()) continue;
          const std::size_t gi = sg.index(node);
          if (axi) {  // per-radian masses: the share of m_g on the cell's side in r (CellProjection.h)
            const bool on_x = (symmetric[0] && node[0] == sg.extra[0]) || (symmetric[1] && node[0] == sg.n[0] - 1 - sg.extra[0]);
            const double up = node_mass[gi] > 0.0 ? node_above[gi] / node_mass[gi] : 0.5;
            sum += axisymmetric_node_cell_weight(wnode[gi], on_x, (n & 1) == 0 ? up : 1.0 - up) * node_mass[gi];
            continue;
          }
          sum += wnode[gi] * node_mass[gi];
        }
        M[ci(c)] = sum;
      });
    };
    // The general route: stencils of the scratch particles, P2G of the mass,
    // symmetry fold.
    auto project_general = [&](std::vector<double>& M) {
      q.F = p.F;  // CPDI-type domains
      Stencils st;
      if (!compute_axis_stencils(q, sg, spec, st) && compute_stencils(q, sg, spec, st) >= 0) {
        // A particle would leave the grid during the step: no flux for it
        // (MPM reports the particle when it does leave).
        node_mass.assign(sg.count(), 0.0);
        reduce_band();  // the other ranks' band collectives
        M.assign(ci.count(), 0.0);
        return false;
      }
      visit_stencils(st, [&](const auto& view) {
        scatter([&](std::size_t i, auto&& at) {
          view.weights(i, [&](std::size_t gi, double w) { *at(gi) += p.mass[i] * w; });
        });
      });
      fold_symmetry_scalar(mm.bcs, sg, node_mass);
      if (axi) {
        node_mass_above(sg, spec.kind, p.mass, q.x, q.psize, [&](auto&& fn) {
          visit_stencils(st, [&](const auto& view) {
            for (std::size_t i = 0; i < q.size(); ++i) view.weights(i, [&](std::size_t gi, double w) { fn(i, gi, w); });
          });
        }, node_above);
        fold_symmetry_scalar(mm.bcs, sg, node_above);
      }
      nodes_to_cells(M);
      return true;
    };
    AxisFactors fac;
    fac.N = axis_nodes_of(spec.kind);
    bool axis_ok[3] = {false, false, false};
    if (fac.N)
      for (int d = 0; d < 3; ++d) axis_ok[d] = fac.fill(spec.kind, q, sg, d);
    // M_c of the scratch particles' present positions, every cell with extra cells.
    auto project = [&](std::vector<double>& M) {
      if (!(fac.N && axis_ok[0] && axis_ok[1] && axis_ok[2])) return project_general(M);
      if (axi) node_above.assign(sg.count(), 0.0);
      double* above = axi ? node_above.data() : nullptr;
      auto half = [&](std::size_t i) { return 0.5 * q.psize[i](0, 0); };
      if (fac.N == 2)
        scatter([&](std::size_t i, auto&& at) { fac.scatter_mass<2>(i, p.mass[i], sg, at, &q.x[i], above, spec.kind, half(i)); });
      else
        scatter([&](std::size_t i, auto&& at) { fac.scatter_mass<3>(i, p.mass[i], sg, at, &q.x[i], above, spec.kind, half(i)); });
      fold_symmetry_scalar(mm.bcs, sg, node_mass);
      if (axi) fold_symmetry_scalar(mm.bcs, sg, node_above);
      nodes_to_cells(M);
      return true;
    };
    FaceScalars& F = ice_->lagrangian_mass_flux(s);
    std::vector<double> M0, M1, flux(ci.count()), dM(ci.count());
    bool ok = project(M0);
    for (int d = 0; d < 3; ++d) {
      bool moved = false;
      for (std::size_t i = 0; i < p.size(); ++i) moved = moved || disp[i][d] != 0.0;
      moved = mpm_->layout().any(moved);  // every rank takes the same branch (the sums below are collective)
      if (!moved) {
        // x_d unchanged: M1 = M0 bit for bit, every face flux along d is 0.
        for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
          GridArray<double>& Fd = F.at(d, pi);
          const Patch& patch = g.patches[pi];
          for_each_cell_serial({patch.lo, patch.hi + IntVec3::Unit(d)}, [&](int i, int j, int k) { Fd(i, j, k) = 0.0; });
        }
        continue;
      }
      for (std::size_t i = 0; i < p.size(); ++i) q.x[i][d] += disp[i][d];
      if (fac.N) axis_ok[d] = fac.fill(spec.kind, q, sg, d);
      ok = project(M1) && ok;
      // Row sums along d: flux[c] = mass through c's lower face along d.
      const IndexRange r = g.cells_with_extra();
      IndexRange rows = r;
      rows.hi[d] = rows.lo[d] + 1;
      // dM_c = M1_c - M0_c of every cell. With the band on ranks each rank
      // has the whole sums at its own cells only: their dM gathered from
      // their owners (values, not sums: the one-process bits).
      for (std::size_t c = 0; c < dM.size(); ++c) dM[c] = M1[c] - M0[c];
      if (by_band && mpm_->layout().distributed) gather_own_cells(g, ci, dM);
      for_each_cell_serial(rows, [&](int i, int j, int k) {
        IntVec3 c(i, j, k);
        double f = 0;
        const int first = symmetric[2 * d] ? 0 : r.lo[d];
        for (c[d] = r.lo[d]; c[d] < r.hi[d]; ++c[d]) {
          if (c[d] < first) {
            flux[ci(c)] = 0;
            continue;
          }
          flux[ci(c)] = f;
          f -= dM[ci(c)];
        }
      });
      // MPI ranks without the band (periodic, axisymmetric): each rank's
      // fluxes are those of its own particles (M is linear in them); the sum
      // over the ranks at the nodes c + off (the node arrays' sums,
      // mpm/RankNodeSums.h) gives each face its total, to round-off.
      if (!by_band && mpm_->layout().distributed) sum_cell_array_over_ranks(*mpm_, r, off, ng, ci, flux);
      const bool all_ok = !mpm_->layout().any(!ok);
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        GridArray<double>& Fd = F.at(d, pi);
        const Patch& patch = g.patches[pi];
        for_each_cell_serial({patch.lo, patch.hi + IntVec3::Unit(d)}, [&](int i, int j, int k) {
          const IntVec3 c(i, j, k);
          Fd(c) = all_ok ? flux[ci(c)] : 0.0;
          // Axisymmetric: the per-radian mass F_rad through the face in ICE's
          // Cartesian flux units (ice/RadialWeights.h: cell i gains (r_f/r_i) F_x
          // and F_y of Cartesian content, i.e. F_rad dz/r_i): F_x = F_rad dz/r_f
          // on r-faces (0 on the axis), F = F_rad dz/r_i on the others.
          if (axi) {
            const double r = g.lower[0] + (d == 0 ? i : i + 0.5) * g.dx[0];
            Fd(c) = r > 0.0 ? Fd(c) * g.dx[2] / r : 0.0;
          }
        });
      }
      std::swap(M0, M1);
    }
  }
}

}  // namespace tephra
