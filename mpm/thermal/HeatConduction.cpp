#include "mpm/thermal/HeatConduction.h"

#include <limits>

#include "mpm/shape/AxisStencils.h"

namespace tephra {

void temperature_to_grid(const Particles& p, const Stencils& s, const NodeGrid& g, ThermalNodes& t) {
  const std::size_t nn = g.count();
  t.temperature.assign(nn, 0.0);
  t.rate.assign(nn, 0.0);
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      const double mT = p.mass[i] * p.temperature[i];
      view.weights(i, [&](std::size_t gi, double w) { t.temperature[gi] += mT * w; });
    }
  });
  for (std::size_t gi = 0; gi < nn; ++gi)
    if (g.mass[gi] > 0.0) t.temperature[gi] /= g.mass[gi];
}

void add_conduction_rate(const Particles& p, const Stencils& s, const NodeGrid& g, double conductivity,
                         double specific_heat, ThermalNodes& t) {
  // The heat flow into node g, Q_g = -sum_p k V_p grad S_gp . grad T_p [W],
  // gathered first and divided by the node's heat capacity m_g c_v after.
  // Axisymmetric stencils: only the in-plane (r, z) components are
  // derivatives (grad T has no hoop component); with per-radian V_p and m_g
  // the sum is the Galerkin form of (1/r) d/dr (r k dT/dr) + d/dz (k dT/dz),
  // int k grad S . grad T r dr dz, evaluated at the particles.
  const Vec3 mask = s.hoop_factor ? Vec3(1.0, 1.0, 0.0) : Vec3(1.0, 1.0, 1.0);
  std::vector<double> heat_flow(g.count(), 0.0);
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      Vec3 grad_T = Vec3::Zero();
      view.entries(i, [&](std::size_t gi, double, const Vec3& gr) { grad_T += t.temperature[gi] * gr; });
      grad_T = grad_T.cwiseProduct(mask);
      const Vec3 flux_volume = conductivity * p.volume[i] * grad_T;  // -q V_p, q = -k grad T
      view.entries(i, [&](std::size_t gi, double, const Vec3& gr) { heat_flow[gi] -= gr.dot(flux_volume); });
    }
  });
  for (std::size_t gi = 0; gi < heat_flow.size(); ++gi)
    if (g.mass[gi] > 0.0) t.rate[gi] += heat_flow[gi] / (g.mass[gi] * specific_heat);
}

void add_thermal_contact_rate(const std::vector<const NodeGrid*>& grids, const std::vector<double>& specific_heat,
                              double dt, std::vector<ThermalNodes*>& thermal) {
  if (grids.empty()) return;
  const std::size_t nn = grids[0]->count();
  for (std::size_t gi = 0; gi < nn; ++gi) {
    double capacity = 0.0, energy = 0.0;
    for (std::size_t m = 0; m < grids.size(); ++m) {
      const double C = grids[m]->mass[gi] * specific_heat[m];
      capacity += C;
      energy += C * thermal[m]->temperature[gi];
    }
    if (!(capacity > 0.0)) continue;
    const double T_contact = energy / capacity;
    for (std::size_t m = 0; m < grids.size(); ++m)
      if (grids[m]->mass[gi] > 0.0) thermal[m]->rate[gi] += (T_contact - thermal[m]->temperature[gi]) / dt;
  }
}

void temperature_rate_to_particles(const Stencils& s, const ThermalNodes& t, double dt, Particles& p) {
  visit_stencils(s, [&](const auto& view) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      double rate = 0.0;
      view.weights(i, [&](std::size_t gi, double w) { rate += t.rate[gi] * w; });
      p.temperature[i] += dt * rate;
    }
  });
}

double conduction_stable_timestep(double diffusivity, const Vec3& h) {
  if (!(diffusivity > 0.0)) return std::numeric_limits<double>::infinity();
  const double inv_h2 = 1.0 / (h[0] * h[0]) + 1.0 / (h[1] * h[1]) + 1.0 / (h[2] * h[2]);
  return 1.0 / (2.0 * diffusivity * inv_h2);
}

}  // namespace tephra
