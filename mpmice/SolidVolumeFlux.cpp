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
#include <stdexcept>
#include <vector>

#include "core/grid/Loop.h"
#include "mpm/SymmetryFold.h"
#include "mpm/shape/AxisStencils.h"
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

}  // namespace

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
    // d_p = dt sum_g S_gp v_g.
    std::vector<Vec3> disp(p.size(), Vec3::Zero());
    visit_stencils(mm.stencils, [&](const auto& view) {
      for (std::size_t i = 0; i < p.size(); ++i)
        view.weights(i, [&](std::size_t gi, double w) { disp[i] += dt * w * ng.velocity[gi]; });
    });
    // Scratch particles (position, domain, F: what the stencils read).
    Particles& q = flux_particles_;
    q.x = p.x;
    q.psize = p.psize;
    q.F = p.F;
    NodeGrid& sg = flux_grid_;
    sg.origin = ng.origin;
    sg.h = ng.h;
    sg.n = ng.n;
    sg.extra = ng.extra;
    // M_c of the scratch particles' positions, every cell with extra cells.
    auto project = [&](std::vector<double>& M) {
      Stencils st;
      if (!compute_axis_stencils(q, sg, spec, st) && compute_stencils(q, sg, spec, st) >= 0) {
        // A particle would leave the grid during the step: no flux for it
        // (MPM reports the particle when it does leave).
        M.assign(ci.count(), 0.0);
        return false;
      }
      sg.reset();
      visit_stencils(st, [&](const auto& view) {
        for (std::size_t i = 0; i < q.size(); ++i)
          view.weights(i, [&](std::size_t gi, double w) { sg.mass[gi] += p.mass[i] * w; });
      });
      fold_symmetry_particle_sums(mm.bcs, sg);
      M.assign(ci.count(), 0.0);
      for_each_cell_serial(g.cells_with_extra(), [&](int i, int j, int k) {
        const IntVec3 c(i, j, k);
        double sum = 0;
        for (int n = 0; n < 8; ++n) {
          const IntVec3 node = c + off + IntVec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
          if ((node.array() < 0).any() || (node.array() >= sg.n.array()).any()) continue;
          sum += node_cell_weight(sg, symmetric, node) * sg.mass[sg.index(node)];
        }
        M[ci(c)] = sum;
      });
      return true;
    };
    FaceScalars& F = ice_->lagrangian_mass_flux(s);
    std::vector<double> M0, M1, flux(ci.count());
    bool ok = project(M0);
    for (int d = 0; d < 3; ++d) {
      for (std::size_t i = 0; i < p.size(); ++i) q.x[i][d] += disp[i][d];
      ok = project(M1) && ok;
      // Row sums along d: flux[c] = mass through c's lower face along d.
      const IndexRange r = g.cells_with_extra();
      IndexRange rows = r;
      rows.hi[d] = rows.lo[d] + 1;
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
          f -= M1[ci(c)] - M0[ci(c)];
        }
      });
      // MPI ranks: each rank's fluxes are those of its own particles (M is
      // linear in them); the sum over the ranks at the nodes c + off (the
      // node arrays' sums, mpm/RankNodeSums.h) gives each face its total.
      if (mpm_->layout().distributed) sum_cell_array_over_ranks(*mpm_, r, off, ng, ci, flux);
      const bool all_ok = !mpm_->layout().any(!ok);
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        GridArray<double>& Fd = F.at(d, pi);
        const Patch& patch = g.patches[pi];
        for_each_cell_serial({patch.lo, patch.hi + IntVec3::Unit(d)}, [&](int i, int j, int k) {
          const IntVec3 c(i, j, k);
          Fd(c) = all_ok ? flux[ci(c)] : 0.0;
        });
      }
      std::swap(M0, M1);
    }
  }
}

}  // namespace tephra
