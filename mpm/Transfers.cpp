#include "mpm/Transfers.h"

#include "mpm/BandTag.h"
#include "mpm/NodeRuns.h"
#include "mpm/PatchBand.h"
#include "mpm/shape/AxisStencils.h"

#include <algorithm>
#include <type_traits>
#include <cmath>


namespace tephra {

// Threading (OpenMP, thread count from set_thread_count / --threads).
//
// Gathers (G2P, velocity gradients) and node-wise updates are split among
// threads with a static schedule; each writes only its own entries, so they
// are bit-for-bit identical for any thread count.
//
// Scatters (P2G, internal force) visit the particles in the scatter order of
// the stencils (mpm/shape/ScatterOrder.h): colour by colour, the blocks of a
// colour in parallel, each writing straight into the grid arrays (the blocks
// of one colour touch disjoint nodes; no per-thread node buffers). Every
// node's sum is taken in the same particle order for any thread count, so
// the results are bit-for-bit the same with 1, 2 or more threads. Stencils
// without an order (filled by hand) are scattered serially in particle order.
namespace {

// Below this many nodes a parallel region costs more than it saves.
constexpr std::size_t kMinParallel = 4096;

// P2G of particle i into g (V: a stencil view, AxisStencils.h); the V sigma
// sums only if Stress (g.stressFS wanted, NodeGrid::node_stress); with Force
// also f_int,g -= V_p (sigma_p - q_p I) grad S (compute_internal_force's term).
// Band (mpm/PatchBand.h): the particle's patch P >= 0 routes the terms of
// band nodes into the (node, P) partials (layout m, V, m v, f_ext, f_int,
// V sigma), every other node directly; the same expressions either way.
// flatten: everything called inside (the stencil view, the lambdas, Eigen's
// small products) is inlined; without it GCC at -O2 left the Eigen
// assignments as calls once the band variant made the scatter loop larger
// (bench_mpm_spheres linear: P2G 2.1x slower).
// Ext false: the f_ext,g sums are left out (the plain path only, when every
// f_ext,p and b are zero: has_external_force). Each term f S is then +-0
// (S >= 0), and the reset +0 plus +-0 terms is +0 in round-to-nearest, the
// value the node array already holds: the same bits without the 3 loads, 3
// products, 3 sums and 3 stores per stencil entry.
template <bool Stress, bool Force, bool Band, class V, bool Ext = true>
[[gnu::flatten]] inline void p2g_particle(const Particles& p, const V& s, const Vec3& body_force, std::size_t i, NodeGrid& g,
                         PatchBand* band, int P) {
  static_assert(Ext || !Band, "the band path always sums f_ext (its partials are reduced over every slot)");
  const double mp = p.mass[i], vp = p.volume[i];
  const Vec3 momentum = mp * p.v[i];
  Vec3 force;
  if constexpr (Ext) force = p.external_force[i] + mp * body_force;
  Mat3 vol_stress;
  if constexpr (Stress) vol_stress = vp * p.stress[i];
  double* mass = g.mass.data();
  double* volume = g.volume.data();
  Vec3* mom = g.velocity.data();
  Vec3* fext = g.external_force.data();
  Mat3* stress = g.stress.data();
  Mat3 force_stress;
  // sigma - q I: the artificial bulk viscosity acts in the force only.
  if constexpr (Force) force_stress = vp * (p.stress[i] - p.q[i] * Mat3::Identity());
  Vec3* fint = g.internal_force.data();
  auto add = [&](std::size_t gi, double wk) {
    mass[gi] += mp * wk;
    volume[gi] += vp * wk;
    mom[gi] += momentum * wk;
    if constexpr (Ext) fext[gi] += force * wk;
    if constexpr (Stress) stress[gi] += vol_stress * wk;
  };
  if constexpr (Band) {
    auto add_band = [&](std::size_t gi, double wk, const Vec3& gr) {
      const int k = band->slot(gi);
      if (k < 0) {
        add(gi, wk);
        if constexpr (Force) fint[gi] -= force_stress * gr;
        return;
      }
      double* q = band->partial(k, P);
      q[0] += mp * wk;
      q[1] += vp * wk;
      Eigen::Map<Vec3>(q + 2) += momentum * wk;
      Eigen::Map<Vec3>(q + 5) += force * wk;
      if constexpr (Force) Eigen::Map<Vec3>(q + 8) -= force_stress * gr;
      if constexpr (Stress) Eigen::Map<Mat3>(q + 11) += vol_stress * wk;
    };
    if constexpr (Force) s.entries(i, add_band);
    else s.weights(i, [&](std::size_t gi, double wk) { add_band(gi, wk, Vec3::Zero()); });
  } else if constexpr (Force) {
    // entries() gives S_gp with the same product as weights() (AxisStencils.h).
    s.entries(i, [&](std::size_t gi, double wk, const Vec3& gr) {
      add(gi, wk);
      fint[gi] -= force_stress * gr;
    });
  } else {
    s.weights(i, add);
  }
}

// True when some f_ext,p or b is not zero (a NaN counts as not zero): then
// P2G sums f_ext,g; else every f_ext,g is the reset +0 (p2g_particle, Ext).
bool has_external_force(const Particles& p, const Vec3& body_force) {
  if (!(body_force[0] == 0.0 && body_force[1] == 0.0 && body_force[2] == 0.0)) return true;
  const double* f = p.external_force.empty() ? nullptr : p.external_force.front().data();
  const long n = static_cast<long>(3 * p.external_force.size());
  long nonzero = 0;  // a count, the same for any thread split
#pragma omp parallel for schedule(static) reduction(+ : nonzero) if (n >= 3 * 4096)
  for (long k = 0; k < n; ++k) nonzero += !(f[k] == 0.0);
  return nonzero > 0;
}

// The band sums (PatchBand::reduce) into the node arrays of P2G.
void reduce_p2g_band(PatchBand& band, bool stress, bool force, NodeGrid& g) {
  band.reduce(stress ? PatchBand::kMaxWidth : 11, [&](std::size_t gi, const double* q) {
    g.mass[gi] = q[0];
    g.volume[gi] = q[1];
    g.velocity[gi] = Eigen::Map<const Vec3>(q + 2);
    g.external_force[gi] = Eigen::Map<const Vec3>(q + 5);
    if (force) g.internal_force[gi] = Eigen::Map<const Vec3>(q + 8);
    if (stress) g.stress[gi] = Eigen::Map<const Mat3>(q + 11);
  });
}

// P2G (with the internal force when Force), then v_g = momentum / m_g and sigma_g = (V sigma)_g / V_g.
template <bool Force>
void scatter_particles(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g,
                       PatchBand* band) {
  const std::size_t np = p.size(), nn = g.count();
  const bool stress = g.stress.size() == nn;
  band = band_for_scatter(band, s);
  const bool ext = has_external_force(p, body_force);
  visit_stencils(s, [&](const auto& view) {
    using View = std::decay_t<decltype(view)>;
    auto run = [&](auto stress_tag, auto ext_tag) {
      constexpr bool S = decltype(stress_tag)::value, E = decltype(ext_tag)::value;
      if (band)
        for_each_scatter_particle(s.order, np, [&](std::size_t i) {
          const int P = band_tag(*band, view, i, p.x[i]);
          if (P < 0) p2g_particle<S, Force, false, View, E>(p, view, body_force, i, g, band, P);
          else p2g_particle<S, Force, true, View>(p, view, body_force, i, g, band, P);
        });
      else
        for_each_scatter_particle(s.order, np, [&](std::size_t i) {
          p2g_particle<S, Force, false, View, E>(p, view, body_force, i, g, nullptr, -1);
        });
    };
    if (stress) {
      if (ext) run(std::true_type{}, std::true_type{});
      else run(std::true_type{}, std::false_type{});
    } else {
      if (ext) run(std::false_type{}, std::true_type{});
      else run(std::false_type{}, std::false_type{});
    }
  });
  if (band) reduce_p2g_band(*band, stress, Force, g);
  for_each_active_node(g, [&](std::size_t gi) {  // the active box (mpm/NodeRuns.h): the whole grid in one process
    if (g.mass[gi] > 0.0) g.velocity[gi] /= g.mass[gi];
    if (stress && g.volume[gi] > 0.0) g.stress[gi] /= g.volume[gi];
  }, long(kMinParallel));
}

}  // namespace

void particles_to_grid(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g,
                       PatchBand* band) {
  scatter_particles<false>(p, s, body_force, g, band);
}

void particles_to_grid_and_internal_force(const Particles& p, const Stencils& s, const Vec3& body_force,
                                          NodeGrid& g, PatchBand* band) {
  scatter_particles<true>(p, s, body_force, g, band);
}

void compute_internal_force(const Particles& p, const Stencils& s, NodeGrid& g, PatchBand* band) {
  Vec3* fint = g.internal_force.data();
  band = band_for_scatter(band, s);
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      // sigma - q I: the artificial bulk viscosity acts in the force only.
      const Mat3 vol_stress = p.volume[i] * (p.stress[i] - p.q[i] * Mat3::Identity());
      const int P = band ? band_tag(*band, view, i, p.x[i]) : -1;
      if (P < 0) {
        view.entries(i, [&](std::size_t gi, double, const Vec3& gr) { fint[gi] -= vol_stress * gr; });
        return;
      }
      view.entries(i, [&](std::size_t gi, double, const Vec3& gr) {  // band particle (PatchBand.h)
        const int k = band->slot(gi);
        if (k < 0) fint[gi] -= vol_stress * gr;
        else Eigen::Map<Vec3>(band->partial(k, P)) -= vol_stress * gr;
      });
    });
  });
  // The band nodes: 0 - sum over the patches in ascending id of their partials
  // (each partial formed from 0 as -sum ...; the node array held 0 there).
  if (band)
    band->reduce(3, [&](std::size_t gi, const double* q) { fint[gi] = Eigen::Map<const Vec3>(q); });
}

// Over the active box (NodeGrid::active_box: the whole grid in one process).
void integrate_grid_velocity(NodeGrid& g, double dt) {
  for_each_active_node(g, [&](std::size_t gi) {
    if (g.mass[gi] > 0.0) {
      g.acceleration[gi] = (g.internal_force[gi] + g.external_force[gi]) / g.mass[gi];
      g.velocity_star[gi] = g.velocity[gi] + g.acceleration[gi] * dt;
    } else {
      g.acceleration[gi].setZero();
      g.velocity_star[gi].setZero();
    }
  }, long(kMinParallel));
}

void acceleration_from_velocities(NodeGrid& g, double dt) {
  for_each_active_node(g, [&](std::size_t gi) { g.acceleration[gi] = (g.velocity_star[gi] - g.velocity[gi]) / dt; },
                       long(kMinParallel));
}

void velocity_gradients(const Stencils& s, const NodeGrid& g, std::vector<Mat3>& L) {
  const std::size_t np = s.particles();
  L.resize(np);
  const Vec3* vstar = g.velocity_star.data();
  visit_stencils(s, [&](const auto& view) {
#pragma omp parallel for schedule(static) if (np >= kMinParallel)
    for (std::size_t i = 0; i < np; ++i) L[i] = particle_velocity_gradient(view, i, vstar);
  });
}

namespace {

// l_p and F_{n+1} = (I + dt l_p) F_n in one pass; l_p stored when KeepL.
template <bool KeepL>
void first_order_F_pass(const Stencils& s, const NodeGrid& g, double dt, std::vector<Mat3>* L,
                        const std::vector<Mat3>& F_old, std::vector<Mat3>& F) {
  const std::size_t np = s.particles();
  if constexpr (KeepL) L->resize(np);
  F.resize(F_old.size());
  const Vec3* vstar = g.velocity_star.data();
  visit_stencils(s, [&](const auto& view) {
#pragma omp parallel for schedule(static) if (np >= kMinParallel)
    for (std::size_t i = 0; i < np; ++i) {
      const Mat3 l = particle_velocity_gradient(view, i, vstar);
      if constexpr (KeepL) (*L)[i] = l;
      F[i] = (Mat3::Identity() + dt * l) * F_old[i];  // as update_deformation_gradients (FirstOrder)
    }
  });
}

}  // namespace

void velocity_gradients_and_first_order_F(const Stencils& s, const NodeGrid& g, double dt, std::vector<Mat3>& L,
                                          const std::vector<Mat3>& F_old, std::vector<Mat3>& F) {
  first_order_F_pass<true>(s, g, dt, &L, F_old, F);
}

void first_order_F(const Stencils& s, const NodeGrid& g, double dt, const std::vector<Mat3>& F_old,
                   std::vector<Mat3>& F) {
  first_order_F_pass<false>(s, g, dt, nullptr, F_old, F);
}

void grid_to_particles(const Stencils& s, const NodeGrid& g, double dt, Particles& p) {
  const std::size_t np = s.particles();
  const Vec3* acc = g.acceleration.data();
  const Vec3* vstar = g.velocity_star.data();
  visit_stencils(s, [&](const auto& view) {
#pragma omp parallel for schedule(static) if (np >= kMinParallel)
    for (std::size_t i = 0; i < np; ++i) {
      Vec3 a = Vec3::Zero(), v = Vec3::Zero();
      view.weights(i, [&](std::size_t gi, double wk) {
        a += acc[gi] * wk;
        v += vstar[gi] * wk;
      });
      p.v[i] += dt * a;
      p.x[i] += dt * v;
      p.displacement[i] += dt * v;
    }
  });
}

}  // namespace tephra
