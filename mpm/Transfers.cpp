#include "mpm/Transfers.h"

#include "mpm/shape/AxisStencils.h"

#include <algorithm>
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
template <bool Stress, bool Force, class V>
inline void p2g_particle(const Particles& p, const V& s, const Vec3& body_force, std::size_t i, NodeGrid& g) {
  const double mp = p.mass[i], vp = p.volume[i];
  const Vec3 momentum = mp * p.v[i];
  const Vec3 force = p.external_force[i] + mp * body_force;
  Mat3 vol_stress;
  if constexpr (Stress) vol_stress = vp * p.stress[i];
  double* mass = g.mass.data();
  double* volume = g.volume.data();
  Vec3* mom = g.velocity.data();
  Vec3* fext = g.external_force.data();
  Mat3* stress = g.stress.data();
  auto add = [&](std::size_t gi, double wk) {
    mass[gi] += mp * wk;
    volume[gi] += vp * wk;
    mom[gi] += momentum * wk;
    fext[gi] += force * wk;
    if constexpr (Stress) stress[gi] += vol_stress * wk;
  };
  if constexpr (Force) {
    // sigma - q I: the artificial bulk viscosity acts in the force only.
    const Mat3 force_stress = vp * (p.stress[i] - p.q[i] * Mat3::Identity());
    Vec3* fint = g.internal_force.data();
    // entries() gives S_gp with the same product as weights() (AxisStencils.h).
    s.entries(i, [&](std::size_t gi, double wk, const Vec3& gr) {
      add(gi, wk);
      fint[gi] -= force_stress * gr;
    });
  } else {
    s.weights(i, add);
  }
}

// P2G (with the internal force when Force), then v_g = momentum / m_g and sigma_g = (V sigma)_g / V_g.
template <bool Force>
void scatter_particles(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g) {
  const std::size_t np = p.size(), nn = g.count();
  const bool stress = g.stress.size() == nn;
  visit_stencils(s, [&](const auto& view) {
    if (stress)
      for_each_scatter_particle(s.order, np,
                                [&](std::size_t i) { p2g_particle<true, Force>(p, view, body_force, i, g); });
    else
      for_each_scatter_particle(s.order, np,
                                [&](std::size_t i) { p2g_particle<false, Force>(p, view, body_force, i, g); });
  });
#pragma omp parallel for schedule(static) if (nn >= kMinParallel)
  for (std::size_t gi = 0; gi < nn; ++gi) {
    if (g.mass[gi] > 0.0) g.velocity[gi] /= g.mass[gi];
    if (stress && g.volume[gi] > 0.0) g.stress[gi] /= g.volume[gi];
  }
}

}  // namespace

void particles_to_grid(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g) {
  scatter_particles<false>(p, s, body_force, g);
}

void particles_to_grid_and_internal_force(const Particles& p, const Stencils& s, const Vec3& body_force,
                                          NodeGrid& g) {
  scatter_particles<true>(p, s, body_force, g);
}

void compute_internal_force(const Particles& p, const Stencils& s, NodeGrid& g) {
  Vec3* fint = g.internal_force.data();
  visit_stencils(s, [&](const auto& view) {
    for_each_scatter_particle(s.order, p.size(), [&](std::size_t i) {
      // sigma - q I: the artificial bulk viscosity acts in the force only.
      const Mat3 vol_stress = p.volume[i] * (p.stress[i] - p.q[i] * Mat3::Identity());
      view.entries(i, [&](std::size_t gi, double, const Vec3& gr) { fint[gi] -= vol_stress * gr; });
    });
  });
}

void integrate_grid_velocity(NodeGrid& g, double dt) {
  const std::size_t nn = g.count();
#pragma omp parallel for schedule(static) if (nn >= kMinParallel)
  for (std::size_t gi = 0; gi < nn; ++gi) {
    if (g.mass[gi] > 0.0) {
      g.acceleration[gi] = (g.internal_force[gi] + g.external_force[gi]) / g.mass[gi];
      g.velocity_star[gi] = g.velocity[gi] + g.acceleration[gi] * dt;
    } else {
      g.acceleration[gi].setZero();
      g.velocity_star[gi].setZero();
    }
  }
}

void acceleration_from_velocities(NodeGrid& g, double dt) {
  const std::size_t nn = g.count();
#pragma omp parallel for schedule(static) if (nn >= kMinParallel)
  for (std::size_t gi = 0; gi < nn; ++gi) g.acceleration[gi] = (g.velocity_star[gi] - g.velocity[gi]) / dt;
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

void velocity_gradients_and_first_order_F(const Stencils& s, const NodeGrid& g, double dt, std::vector<Mat3>& L,
                                          const std::vector<Mat3>& F_old, std::vector<Mat3>& F) {
  const std::size_t np = s.particles();
  L.resize(np);
  F.resize(F_old.size());
  const Vec3* vstar = g.velocity_star.data();
  visit_stencils(s, [&](const auto& view) {
#pragma omp parallel for schedule(static) if (np >= kMinParallel)
    for (std::size_t i = 0; i < np; ++i) {
      const Mat3 l = particle_velocity_gradient(view, i, vstar);
      L[i] = l;
      F[i] = (Mat3::Identity() + dt * l) * F_old[i];  // as update_deformation_gradients (FirstOrder)
    }
  });
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
