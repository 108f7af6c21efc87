// The grid transfers of the coupled step (docs/mpmice.md; Vaango theory
// manual sec. 26.1.3 steps 1, 7 and 13; Uintah's MPMICE interpolateNCToCC_0,
// interpolatePAndGradP and interpolateCCToNC for what the manual leaves open).
//
// Node <-> cell: a cell's value is the equal-weight (1/8) average of its 8
// corner nodes, a node's value the 1/8 average of its 8 adjacent cells.
// A node on a symmetry plane weighs double per plane (mpmice/CellProjection.h).
#include <array>
#include <algorithm>
#include <cmath>
#include <vector>

#include "core/grid/Loop.h"
#include "mpmice/BandScatter.h"
#include "mpmice/CellProjection.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/NodeAverages.h"
#include "mpm/SymmetryFold.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {

// node_cell_weight (CellProjection.h) of every node of ng: the weight and
// which symmetry planes the node lies on (bit d: normal to d).
struct MpmIceNodeWeights {
  std::vector<double> w;
  std::vector<unsigned char> plane;
  MpmIceNodeWeights(const NodeGrid& ng, const std::array<bool, 6>& symmetric) : w(ng.count()), plane(ng.count()) {
    for (int k = 0; k < ng.n[2]; ++k)
      for (int j = 0; j < ng.n[1]; ++j)
        for (int i = 0; i < ng.n[0]; ++i) {
          const std::size_t gi = ng.index(i, j, k);
          bool on[3];
          w[gi] = node_cell_weight(ng, symmetric, IntVec3(i, j, k), on);
          plane[gi] = static_cast<unsigned char>((on[0] ? 1 : 0) | (on[1] ? 2 : 0) | (on[2] ? 4 : 0));
        }
  }
};

// Step 1 (sec. 26.1.3, "project particle state to the grid"): the P2G node
// fields m_g, v_g (and T_g = sum m_p T_p S_gp / m_g) of each MPM material are
// averaged to the cell centres,
//   M_c = 1/8 sum_8 m_g,  u_c = 1/8 sum m_g v_g / M_c,  T_c = 1/8 sum m_g T_g / M_c,
// rho_CC = M_c / V (axisymmetric: the per-radian V = r_c dx dy and the node
// weights of CellProjection.h) (at least tiny_rho rho0: an empty cell keeps a trace of the
// solid, at rest, at its initial temperature), and the solid's micro density
// from its EOS at the cell pressure of the last step,
//   rho_micro = rho(p_CC - p_ref, T_c),  sp_vol = 1/rho_micro
// (Uintah's computeRhoMicroCM), the starting guess of the equilibration.
void MpmIceComponent::solid_state_to_cells() {
  const Grid& g = ice_->grid();
  const double V = g.cell_volume();
  std::vector<IceMaterialFields>& fields = ice_->mutable_fields();
  const IceSetup& is = ice_->setup();
  for (std::size_t s = 0; s < mpm_->materials().size(); ++s) {
    const MpmMaterial& mm = mpm_->materials()[s];
    const NodeGrid& ng = mm.grid;
    const Particles& p = mm.particles;
    const Stencils& st = mm.stencils;
    std::vector<double>& mT = node_mT_;  // sum m_p T_p S_gp (buffer kept across steps)
    mT.assign(ng.count(), 0.0);
    // In patch order at the band nodes (mpmice/BandScatter.h): the same bits on any rank count.
    PatchBand* band = stencil_coupling_band(mpm_->coupling_band(1), st);
    visit_stencils(st, [&](const auto& view) {
      for_each_coupling_particle(st, p.size(), band, [&](std::size_t i) {
        const int P = stencil_coupling_tag(band, view, i, p.x[i]);
        view.weights(i, [&](std::size_t gi, double w) { *band_target(band, P, gi, 0, &mT[gi]) += p.mass[i] * p.temperature[i] * w; });
      });
    });
    if (band) {
      band->reduce(1, [&](std::size_t gi, const double* q) { mT[gi] = q[0]; });
      mpm_->sum_band_node_doubles(mT.data(), 1);  // over the MPI ranks, one contribution per node
    } else {
      mpm_->sum_node_doubles(mT);  // over the MPI ranks (no-op in one process)
    }
    // T_g = sum m_p T_p S_gp / m_g, kept for output (g.temperature).
    node_temperature_.resize(mpm_->materials().size());
    node_temperature_[s].assign(ng.count(), 0.0);
    for (std::size_t gi = 0; gi < ng.count(); ++gi)
      if (ng.mass[gi] > 0.0) node_temperature_[s][gi] = mT[gi] / ng.mass[gi];
    const IntVec3 off = node_offset(g, ng);
    const std::array<bool, 6> symmetric = symmetry_faces(mm.bcs);
    // The node weights depend on the grid and the symmetry faces only: built
    // at the first step (session 19: before, every step, ~20k node_cell_weight
    // calls and two allocations per material).
    if (node_weights_.size() <= s) node_weights_.resize(s + 1);
    if (!node_weights_[s] || node_weights_[s]->w.size() != ng.count())
      node_weights_[s] = std::make_shared<const MpmIceNodeWeights>(ng, symmetric);
    const MpmIceNodeWeights& nw = *node_weights_[s];
    const IceMaterialSpec& spec = is.materials[s];
    const bool axi = is.axisymmetric;  // per-radian masses: the axisymmetric node weights and V = r_c dx dy
    std::vector<double> m_above;  // m_g^+ (axisymmetric only)
    if (axi) {
      node_mass_above(ng, mpm_->setup().flags.interpolator.kind, p.mass, p.x, p.psize, [&](auto&& fn) {
        visit_stencils(st, [&](const auto& view) {
          for (std::size_t i = 0; i < p.size(); ++i) view.weights(i, [&](std::size_t gi, double w) { fn(i, gi, w); });
        });
      }, m_above);
      mpm_->sum_node_doubles(m_above);  // over the MPI ranks
      if (node_share_above_.size() <= s) node_share_above_.resize(s + 1);
      std::vector<double>& share = node_share_above_[s];
      share.assign(ng.count(), 0.5);
      for (std::size_t gi = 0; gi < ng.count(); ++gi)
        if (ng.mass[gi] > 0.0) share[gi] = m_above[gi] / ng.mass[gi];
      // The burn models' surface tests (SolidBurnSupport::corner_masses):
      // the planar-equivalent node mass sum_p m_p (dz/r_p) S_gp, the node
      // mass of the planar run with the same cross-section (m_p/r_p = rho
      // A_p), folded as P2G folds m_g (mpmice/AxisymmetricBurn.h).
      if (!is.models.empty()) {
        if (node_planar_mass_.size() <= s) node_planar_mass_.resize(s + 1);
        std::vector<double>& q = node_planar_mass_[s];
        q.assign(ng.count(), 0.0);
        const double dz = g.dx[2];
        visit_stencils(st, [&](const auto& view) {
          for (std::size_t i = 0; i < p.size(); ++i) {
            if (!(p.x[i][0] > 0)) continue;  // on or across the axis: no planar section (MPM's r > 0 rule)
            const double mq = p.mass[i] * dz / p.x[i][0];
            view.weights(i, [&](std::size_t gi, double w) { q[gi] += mq * w; });
          }
        });
        mpm_->sum_node_doubles(q);  // over the MPI ranks
        fold_symmetry_scalar(mm.bcs, ng, q);
      }
    }
    IceMaterialFields& f = fields[s];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
        const IntVec3 c(i, j, k);
        // An extra cell beyond a symmetry plane is the mirror image of the
        // interior cell across it (normal velocity negated below).
        IntVec3 cm = c;
        Vec3 flip = Vec3::Ones();
        for (int d = 0; d < 3; ++d) {
          if (symmetric[2 * d] && c[d] < 0) cm[d] = -1 - c[d], flip[d] = -1;
          if (symmetric[2 * d + 1] && c[d] >= g.cells[d]) cm[d] = 2 * g.cells[d] - 1 - c[d], flip[d] = -1;
        }
        // The cell's volume: Cartesian V, or per radian r_c dx dy (axisymmetric).
        const double Vc = axi ? (g.lower[0] + (cm[0] + 0.5) * g.dx[0]) * g.dx[0] * g.dx[1] : V;
        const double min_mass = spec.tiny_rho * mm.density * Vc;
        double M = 0, MT = 0;
        Vec3 P = Vec3::Zero();
        for (int n = 0; n < 8; ++n) {
          const IntVec3 node = cm + off + IntVec3(n & 1, (n >> 1) & 1, (n >> 2) & 1);
          const std::size_t gi = ng.index(node);
          // VT step 1: a node on a symmetry plane holds only the particles on
          // the domain's side; its mirror images would give it as much again,
          // so its weight doubles per plane it lies on (x4 on an edge of two
          // planes), and its momentum normal to the plane is zero (the image
          // particles' normal velocities cancel the real ones').
          double w = nw.w[gi];
          if (axi) {  // the share of m_g on the cell's side in r (CellProjection.h)
            const double up = ng.mass[gi] > 0.0 ? m_above[gi] / ng.mass[gi] : 0.5;
            w = axisymmetric_node_cell_weight(w, nw.plane[gi] & 1, (n & 1) == 0 ? up : 1.0 - up);
          }
          Vec3 v = ng.velocity[gi];
          for (int d = 0; d < 3; ++d)
            if (nw.plane[gi] & (1 << d)) v[d] = 0;
          M += w * ng.mass[gi];
          P += w * ng.mass[gi] * v;
          MT += w * mT[gi];
        }
        double T = spec.sources[0].temperature;
        Vec3 u = Vec3::Zero();
        if (M > min_mass) {
          u = (P / M).cwiseProduct(flip);
          T = MT / M;
        } else {
          // An absent solid (a trace of tiny_rho rho0) moves and heats with
          // the fluids of the cell (their mass-weighted u and T), so that its
          // exchange terms K theta_s theta_f (u_s - u_f) vanish: it must not
          // drag the fluid it is absent from.
          M = min_mass;
          double mf = 0;
          Vec3 pf = Vec3::Zero();
          double tf = 0;
          for (std::size_t q = 0; q < fields.size(); ++q) {
            if (is.materials[q].lagrangian) continue;
            const double r = fields[q].rho_CC[pi](c);
            mf += r;
            pf += r * fields[q].vel_CC[pi](c);
            tf += r * fields[q].temp_CC[pi](c);
          }
          if (mf > 0) u = pf / mf, T = tf / mf;
        }
        f.rho_CC[pi](c) = M / Vc;
        f.vel_CC[pi](c) = u;
        f.temp_CC[pi](c) = T;
        f.sp_vol_CC[pi](c) = 1.0 / spec.eos->density_at(ice_->press_CC()[pi](c), T);
      });
    // The ghost cells from the neighbouring patches: the face velocities and
    // the face fractions of a face between two patches are computed on both
    // sides and must agree (else the fluid fluxes there differ and mass is
    // not conserved: guni2dRT.ups on its 2 x 2 patches lost 5e-10 kg a step).
    ice_->exchange_cell_state(s);
  }
}

// Step 7 (Uintah's interpolatePressCCToPressNC + interpolatePAndGradP): the
// time-advanced cell pressure p_CC to the nodes (1/8 of the 8 adjacent
// cells) and to the particles, p_p = sum_g S_gp p_g - p_ref. The internal
// force then uses sigma_p + p_p I (add_internal_forces): the isotropic part
// sigma = -p I the cells already apply to the solid through -theta grad p is
// taken out of the particle stress (eq. 26.6: div theta_r (sigma_r - sigma)).
void MpmIceComponent::pressure_to_particles() {
  const Grid& g = ice_->grid();
  const IndexRange all = g.cells_with_extra();
  particle_pressure_.resize(mpm_->materials().size());
  for (std::size_t s = 0; s < mpm_->materials().size(); ++s) {
    const MpmMaterial& mm = mpm_->materials()[s];
    const NodeGrid& ng = mm.grid;
    const IntVec3 off = node_offset(g, ng);
    // p_g at the nodes of the own patches (press_CC's ghosts are filled by
    // the pressure phase), then over the ranks (mpmice/NodeAverages.h).
    std::vector<double> pN(ng.count(), 0.0);
    own_node_averages(g, ice_->press_CC(), ng, off, all, [](std::size_t) { return true; }, pN);
    mpm_->sum_node_doubles(pN);
    const Stencils& st = mm.stencils;
    std::vector<double>& pp = particle_pressure_[s];
    pp.assign(mm.particles.size(), 0.0);
    visit_stencils(st, [&](const auto& view) {
      for (std::size_t i = 0; i < mm.particles.size(); ++i) {
        double sum = 0;
        view.weights(i, [&](std::size_t gi, double w) { sum += w * pN[gi]; });
        pp[i] = sum - p_ref_;
      }
    });
  }
}

// f_int,g -= V_p p_p grad S_gp (Uintah's computeInternalForce with ICE: the
// stress sigma_p + p_p I).
// MPM has combined f_int,g over the MPI ranks before this hook, so the
// pressure term is scattered into an array of its own, summed over the ranks,
// then added: f_int,g + (-sum_p V_p p_p grad S_gp). One process does the same
// (session 18; before, it subtracted each particle's term from f_int,g in
// place): with one association on 1 and N ranks a node that only one rank's
// particles reach gets the same bits on any rank count; before, every node
// with solid differed in its last bits between 1 and N ranks
// (f - a - b against f + (-a - b)), not only the nodes at patch cuts.
void MpmIceComponent::add_internal_forces() {
  for (std::size_t s = 0; s < mpm_->materials().size(); ++s) {
    MpmMaterial& mm = mpm_->materials()[s];
    const Stencils& st = mm.stencils;
    const std::vector<double>& pp = particle_pressure_[s];
    std::vector<Vec3> pressure_force(mm.grid.count(), Vec3::Zero());
    // In patch order at the band nodes (mpmice/BandScatter.h): the same bits on any rank count.
    PatchBand* band = stencil_coupling_band(mpm_->coupling_band(1), st);
    // Axisymmetric: grad = (dS/dr, dS/dz, T = hoop factor) (mpm/Axisymmetric.h); the
    // stress p_p I gives f_r = -V_p p_p (dS/dr + T) (its sigma_thth hoop term), f_z = -V_p p_p dS/dz.
    const bool axi = mpm_->setup().flags.axisymmetric;
    visit_stencils(st, [&](const auto& view) {
      for_each_coupling_particle(st, mm.particles.size(), band, [&](std::size_t i) {
        const double vp = mm.particles.volume[i] * pp[i];
        const int P = stencil_coupling_tag(band, view, i, mm.particles.x[i]);
        if (axi)
          view.entries(i, [&](std::size_t gi, double, const Vec3& grad) {
            Eigen::Map<Vec3>(band_target(band, P, gi, 0, pressure_force[gi].data())) -=
                vp * Vec3(grad[0] + grad[2], grad[1], 0.0);
          });
        else
          view.entries(i, [&](std::size_t gi, double, const Vec3& grad) {
            Eigen::Map<Vec3>(band_target(band, P, gi, 0, pressure_force[gi].data())) -= vp * grad;
          });
      });
    });
    if (band) {
      band->reduce(3, [&](std::size_t gi, const double* q) { pressure_force[gi] = Eigen::Map<const Vec3>(q); });
      mpm_->sum_band_node_doubles(pressure_force.front().data(), 3);
    } else {
      mpm_->sum_node_vectors(pressure_force);  // over the MPI ranks (no-op in one process)
    }
    for (std::size_t gi = 0; gi < pressure_force.size(); ++gi) mm.grid.internal_force[gi] += pressure_force[gi];
  }
}

// Step 13 (sec. 26.1.3, "update nodal solid quantities"; Uintah's
// computeLagrangianValuesMPM + interpolateCCToNC): the solid's cell velocity
// and temperature changes of the step, from the pressure force and the
// exchange,
//   du_c = u_L^ME - u_c,   dT_c = T_L^ME - T_c,
// go to the nodes as 1/8 of the 8 adjacent cells (the extra cells take the
// value of their interior neighbour), v*_g += du_g (the acceleration du_g/dt
// joins a_g through the grid BCs that follow), and to the particles,
// T_p += sum_g S_gp dT_g.
void MpmIceComponent::cell_changes_to_nodes_and_particles() {
  const Grid& g = ice_->grid();
  const IndexRange interior{IntVec3::Zero(), g.cells};
  const std::vector<IceMaterialFields>& fields = ice_->fields();
  // du, dT with one ghost layer: buffers kept across steps (every interior
  // cell is written below, the ghosts by the exchange).
  if (change_du_.size() != g.patches.size()) change_du_ = CellVectors(g, 1), change_dT_ = CellScalars(g, 1);
  CellVectors& du = change_du_;
  CellScalars& dT = change_dT_;
  for (std::size_t s = 0; s < mpm_->materials().size(); ++s) {
    const IceMaterialFields& f = fields[s];
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        du[pi](i, j, k) = ice_->lagrangian_velocity(s)[pi](i, j, k) - f.vel_CC[pi](i, j, k);
        dT[pi](i, j, k) = ice_->lagrangian_temperature(s)[pi](i, j, k) - f.temp_CC[pi](i, j, k);
      });
    ice_->exchange_halo(du);  // the first ghost layer of the node averages
    ice_->exchange_halo(dT);
    MpmMaterial& mm = mpm_->materials()[s];
    NodeGrid& ng = mm.grid;
    const IntVec3 off = node_offset(g, ng);
    auto solid = [&](std::size_t gi) { return ng.mass[gi] > 0.0; };
    std::vector<Vec3> duN(ng.count(), Vec3::Zero());
    std::vector<double> dTN(ng.count(), 0.0);
    // Axisymmetric: the cells' changes back with the projection's node -> cell
    // weights (the share in r, mpmice/NodeAverages.h). With the Cartesian 1/8 the
    // node on the cylinder's surface r = R, whose mass all went to the steel
    // cell below, took half the change of the trace solid in the air cell
    // above (locked to the air at rest by the exchange): the outer particles
    // were dragged along z (-0.04 m/s in 7 steps) and the steel's projected
    // volume no longer followed the flux divergence (issue 6, docs/mpmice.md).
    const std::vector<double>* share =
        ice_->setup().axisymmetric && s < node_share_above_.size() ? &node_share_above_[s] : nullptr;
    own_node_averages(g, du, ng, off, interior, solid, duN, share);
    own_node_averages(g, dT, ng, off, interior, solid, dTN, share);
    mpm_->sum_node_vectors(duN);  // over the MPI ranks (mpmice/NodeAverages.h)
    mpm_->sum_node_doubles(dTN);
    for (std::size_t gi = 0; gi < ng.count(); ++gi)
      if (solid(gi)) ng.velocity_star[gi] += duN[gi];
    Particles& p = mm.particles;
    const Stencils& st = mm.stencils;
    visit_stencils(st, [&](const auto& view) {
      for (std::size_t i = 0; i < p.size(); ++i)
        view.weights(i, [&](std::size_t gi, double w) { p.temperature[i] += w * dTN[gi]; });
    });
  }
}

}  // namespace tephra
