// MpmComponent: the <PhysicalBC><MPM><velocity> phases (mpm/loads/ParticleLoads.h,
// VelocitySurface): the flagged particles take v(t_n) at the start of the
// step, and the nodes their stencils reach take v(t_n) after P2G and
// v(t_{n+1}) with the grid boundary conditions.
#include <algorithm>

#include "core/base/PhaseTimers.h"
#include "mpm/MpmComponent.h"

namespace tephra {

// Start of step n: v_p = v_k(t_n) on the particles of velocity surface k.
void MpmComponent::prescribe_surface_velocities(double t) {
  PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
  const auto& surfaces = setup_.loads.velocity;
  surface_of_particle_.resize(setup_.materials.size());
  for (std::size_t mi = 0; mi < setup_.materials.size(); ++mi) {
    Particles& p = setup_.materials[mi].particles;
    surface_of_particle_[mi] = velocity_surface_of_particles(setup_.loads, setup_.grid.dx, p);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (const int k = surface_of_particle_[mi][i]; k >= 0) p.v[i] = surfaces[std::size_t(k)].curve.at(t);
  }
}

// After P2G (the step's stencils exist): the nodes each flagged particle
// weights (S_gp > 0), with the surface that drives them, then v_g = v_k(t_n)
// there. The flagged particles' stencils are recomputed in the flat form
// (whatever form the step chose) so that this phase depends only on
// compute_stencils.
void MpmComponent::find_surface_velocity_nodes(double t) {
  PhaseTimers::Scope timer(phase_timers(), "MPM: set grid boundary conditions");
  surface_nodes_.resize(setup_.materials.size());
  for (std::size_t mi = 0; mi < setup_.materials.size(); ++mi) {
    MpmMaterial& m = setup_.materials[mi];
    const Particles& p = m.particles;
    const std::vector<int>& surface = surface_of_particle_[mi];
    Particles flagged;
    std::vector<int> flagged_surface;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (surface[i] >= 0) {
        flagged.add(p.x[i], p.v[i], p.mass[i], p.volume0[i], p.temperature[i], p.color[i], p.id[i], p.psize[i]);
        flagged.F.back() = p.F[i];
        flagged_surface.push_back(surface[i]);
      }
    std::vector<std::pair<std::size_t, int>>& nodes = surface_nodes_[mi];
    nodes.clear();
    // On MPI ranks every rank takes part in the node combine below, flagged particles or not.
    if (flagged.size() == 0 && !layout_.distributed) continue;
    Stencils st;
    const long bad = compute_stencils(flagged, m.grid, setup_.flags.interpolator, st);
    if (bad >= 0) return;  // interpolate_to_grid already stopped on a particle outside the grid
    // A node reached by particles of several surfaces takes the highest
    // surface index (as a particle on several surfaces does): a rule that
    // does not depend on the particle order, so the ranks can apply it.
    std::vector<int> node_surface(m.grid.count(), -1);
    for (std::size_t q = 0; q < flagged.size(); ++q)
      for (int e = 0; e < st.width; ++e) {
        const std::size_t k = q * std::size_t(st.width) + std::size_t(e);
        if (st.w[k] > 0.0) node_surface[st.node[k]] = std::max(node_surface[st.node[k]], flagged_surface[q]);
      }
    if (layout_.distributed) {
      // A node near a rank cut may be reached by another rank's flagged
      // particles: count per surface the ranks that flag it (a node sum over
      // the boxes, mpm/RankNodeSums.h), then the highest surface flagged anywhere.
      const std::size_t K = setup_.loads.velocity.size();
      std::vector<double> flags(node_surface.size() * K, 0.0);
      for (std::size_t g = 0; g < node_surface.size(); ++g)
        if (node_surface[g] >= 0) flags[g * K + std::size_t(node_surface[g])] = 1.0;
      sum_node_doubles(flags, int(K));
      for (std::size_t g = 0; g < node_surface.size(); ++g)
        for (std::size_t k = 0; k < K; ++k)
          if (flags[g * K + k] > 0.0) node_surface[g] = std::max(node_surface[g], int(k));
    }
    for (std::size_t g = 0; g < node_surface.size(); ++g)
      if (node_surface[g] >= 0) nodes.emplace_back(g, node_surface[g]);
    impose_surface_velocities(mi, t, m.grid.velocity);
  }
}

// v = v_k(t) at the nodes found by find_surface_velocity_nodes.
void MpmComponent::impose_surface_velocities(std::size_t material, double t, std::vector<Vec3>& velocity) const {
  if (material >= surface_nodes_.size()) return;
  const auto& surfaces = setup_.loads.velocity;
  for (const auto& [g, k] : surface_nodes_[material]) velocity[g] = surfaces[std::size_t(k)].curve.at(t);
}

}  // namespace tephra
