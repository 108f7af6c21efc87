#include "mpm/Transfers.h"

#include "mpm/shape/AxisStencils.h"

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace tephra {

// Threading (OpenMP, thread count from set_thread_count / --threads).
//
// Gathers (G2P, velocity gradients) and node-wise updates are split among
// threads with a static schedule; each writes only its own entries, so they
// are bit-for-bit identical for any thread count.
//
// Scatters (P2G, internal force) give thread t the contiguous particle range
// [t np / T, (t+1) np / T). Thread 0 adds into the grid arrays; thread t > 0
// into its own zeroed node buffer; the buffers are then added to the grid
// node by node in thread order (g += b_1 + ... in sequence). Each node's sum
// is therefore taken in a fixed order: results are bit-for-bit reproducible
// for a given thread count, and with one thread identical to the serial loop
// (particle order). Different thread counts differ by round-off in the node
// sums (the summation is split at a different particle).
namespace {

int threads_available() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

int this_thread() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

int team_size() {
#ifdef _OPENMP
  return omp_get_num_threads();
#else
  return 1;
#endif
}

// Below this many particles or nodes a parallel region costs more than it saves.
constexpr std::size_t kMinParallel = 4096;

// The node sums of P2G (and of the internal force), one set per thread.
struct NodeSums {
  double* mass = nullptr;
  double* volume = nullptr;
  Vec3* momentum = nullptr;
  Vec3* external_force = nullptr;
  Mat3* vol_stress = nullptr;
};

// Scratch node buffers of threads 1..T-1, kept between steps (no allocation
// in the step once sized) and zero outside the scatter.
struct ScatterScratch {
  std::vector<std::vector<double>> mass, volume;
  std::vector<std::vector<Vec3>> momentum, external_force, internal_force;
  std::vector<std::vector<Mat3>> vol_stress;

  void size_p2g(int extra_threads, std::size_t nodes) {
    size(mass, extra_threads, nodes, 0.0);
    size(volume, extra_threads, nodes, 0.0);
    size(momentum, extra_threads, nodes, Vec3::Zero().eval());
    size(external_force, extra_threads, nodes, Vec3::Zero().eval());
    size(vol_stress, extra_threads, nodes, Mat3::Zero().eval());
  }
  void size_fint(int extra_threads, std::size_t nodes) {
    size(internal_force, extra_threads, nodes, Vec3::Zero().eval());
  }
  template <class T>
  static void size(std::vector<std::vector<T>>& b, int count, std::size_t nodes, const T& zero) {
    if (b.size() < std::size_t(count)) b.resize(count);
    for (int t = 0; t < count; ++t)
      if (b[t].size() != nodes) b[t].assign(nodes, zero);
  }
};

ScatterScratch& scratch() {
  static ScatterScratch s;  // the transfers are called from one thread at a time
  return s;
}

// P2G sums of particles [begin, end) into `a` (V: a stencil view, AxisStencils.h).
template <class V>
void p2g_range(const Particles& p, const V& s, const Vec3& body_force, std::size_t begin, std::size_t end,
               const NodeSums& a) {
  for (std::size_t i = begin; i < end; ++i) {
    const double mp = p.mass[i], vp = p.volume[i];
    const Vec3 momentum = mp * p.v[i];
    const Vec3 force = p.external_force[i] + mp * body_force;
    const Mat3 vol_stress = vp * p.stress[i];
    s.weights(i, [&](std::size_t gi, double wk) {
      a.mass[gi] += mp * wk;
      a.volume[gi] += vp * wk;
      a.momentum[gi] += momentum * wk;
      a.external_force[gi] += force * wk;
      a.vol_stress[gi] += vol_stress * wk;
    });
  }
}

template <class V>
void fint_range(const Particles& p, const V& s, std::size_t begin, std::size_t end, Vec3* fint) {
  for (std::size_t i = begin; i < end; ++i) {
    // sigma - q I: the artificial bulk viscosity acts in the force only.
    const Mat3 vol_stress = p.volume[i] * (p.stress[i] - p.q[i] * Mat3::Identity());
    s.entries(i, [&](std::size_t gi, double, const Vec3& gr) { fint[gi] -= vol_stress * gr; });
  }
}

void p2g_range(const Particles& p, const Stencils& s, const Vec3& body_force, std::size_t begin,
               std::size_t end, const NodeSums& a) {
  visit_stencils(s, [&](const auto& v) { p2g_range(p, v, body_force, begin, end, a); });
}

void fint_range(const Particles& p, const Stencils& s, std::size_t begin, std::size_t end, Vec3* fint) {
  visit_stencils(s, [&](const auto& v) { fint_range(p, v, begin, end, fint); });
}

}  // namespace

void particles_to_grid(const Particles& p, const Stencils& s, const Vec3& body_force, NodeGrid& g) {
  const std::size_t np = p.size(), nn = g.count();
  const int T = np >= kMinParallel ? threads_available() : 1;
  if (T == 1) {
    p2g_range(p, s, body_force, 0, np,
              NodeSums{g.mass.data(), g.volume.data(), g.velocity.data(), g.external_force.data(), g.stress.data()});
  } else {
    ScatterScratch& b = scratch();
    b.size_p2g(T - 1, nn);
#pragma omp parallel num_threads(T)
    {
      const int t = this_thread(), nt = team_size();
      const std::size_t begin = np * t / nt, end = np * (t + 1) / nt;
      const NodeSums a = t == 0 ? NodeSums{g.mass.data(), g.volume.data(), g.velocity.data(), g.external_force.data(),
                                           g.stress.data()}
                                : NodeSums{b.mass[t - 1].data(), b.volume[t - 1].data(), b.momentum[t - 1].data(),
                                           b.external_force[t - 1].data(), b.vol_stress[t - 1].data()};
      p2g_range(p, s, body_force, begin, end, a);
#pragma omp barrier
      // g += b_1 + ... + b_{T-1}, in thread order; the buffers are left zero.
#pragma omp for schedule(static)
      for (std::size_t gi = 0; gi < nn; ++gi)
        for (int u = 0; u < nt - 1; ++u) {
          g.mass[gi] += b.mass[u][gi];
          g.volume[gi] += b.volume[u][gi];
          g.velocity[gi] += b.momentum[u][gi];
          g.external_force[gi] += b.external_force[u][gi];
          g.stress[gi] += b.vol_stress[u][gi];
          b.mass[u][gi] = 0.0;
          b.volume[u][gi] = 0.0;
          b.momentum[u][gi].setZero();
          b.external_force[u][gi].setZero();
          b.vol_stress[u][gi].setZero();
        }
    }
  }
#pragma omp parallel for schedule(static) if (nn >= kMinParallel)
  for (std::size_t gi = 0; gi < nn; ++gi) {
    if (g.mass[gi] > 0.0) g.velocity[gi] /= g.mass[gi];
    if (g.volume[gi] > 0.0) g.stress[gi] /= g.volume[gi];
  }
}

void compute_internal_force(const Particles& p, const Stencils& s, NodeGrid& g) {
  const std::size_t np = p.size(), nn = g.count();
  const int T = np >= kMinParallel ? threads_available() : 1;
  if (T == 1) {
    fint_range(p, s, 0, np, g.internal_force.data());
    return;
  }
  ScatterScratch& b = scratch();
  b.size_fint(T - 1, nn);
#pragma omp parallel num_threads(T)
  {
    const int t = this_thread(), nt = team_size();
    fint_range(p, s, np * t / nt, np * (t + 1) / nt, t == 0 ? g.internal_force.data() : b.internal_force[t - 1].data());
#pragma omp barrier
#pragma omp for schedule(static)
    for (std::size_t gi = 0; gi < nn; ++gi)
      for (int u = 0; u < nt - 1; ++u) {
        g.internal_force[gi] += b.internal_force[u][gi];
        b.internal_force[u][gi].setZero();
      }
  }
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
