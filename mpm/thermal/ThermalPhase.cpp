// MpmComponent's thermal phases (mpm/thermal/HeatConduction.h for the
// equations): which materials conduct, the conduction and thermal-contact
// rates on the grid, and the particle temperature update with the models'
// internal heating.
#include <algorithm>
#include <limits>

#include "core/base/PhaseTimers.h"
#include "core/base/Errors.h"
#include "mpm/MpmComponent.h"
#include "mpm/PeriodicGrid.h"
#include "mpm/thermal/HeatConduction.h"
#include "mpm/thermal/TemperatureBoundary.h"
#include "mpm/contact/ContactNormals.h"

namespace tephra {

// The deck needs the grid temperature when a material conducts
// (<do_explicit_heat_conduction>, Vaango's default true, and k > 0), when a
// face holds a Dirichlet temperature (with conduction on; Vaango applies it
// whatever k is), or when <thermal_contact/> couples two or more materials.
bool MpmComponent::thermal_grid_needed() const {
  if (setup_.thermal_contact && setup_.materials.size() > 1) return true;
  if (!setup_.flags.explicit_heat_conduction) return false;
  for (const MpmMaterial& m : setup_.materials)
    if (m.thermal_conductivity > 0.0 || has_temperature_bcs(m.bcs)) return true;
  return false;
}

// Forward-Euler limit of the conduction step (conduction_stable_timestep),
// over the conducting materials at their reference density.
double MpmComponent::thermal_stable_timestep() const {
  double dt = std::numeric_limits<double>::infinity();
  if (!thermal_grid_needed() || !setup_.flags.explicit_heat_conduction) return dt;
  // Axisymmetric: z is the hoop direction, without a conduction term (1/h_z^2 -> 0).
  Vec3 h = setup_.grid.dx;
  if (setup_.flags.axisymmetric) h[2] = std::numeric_limits<double>::infinity();
  for (const MpmMaterial& m : setup_.materials)
    if (m.thermal_conductivity > 0.0)
      dt = std::min(dt, conduction_stable_timestep(m.thermal_conductivity / (m.density * m.specific_heat), h));
  return dt;
}

// After P2G of step n: the node temperatures of the particle state at t_n and
// their rates (conduction of each material, then thermal contact, then the
// Dirichlet faces, mpm/thermal/TemperatureBoundary.h). Skipped on a step where
// every particle of every material and every Dirichlet face have the same
// temperature: a uniform T_g has zero gradient and all materials share it, so
// all rates are zero (up to the round-off of the mass-weighted average) and
// there is nothing to conduct.
void MpmComponent::compute_heat_rates(double dt) {
  conducting_ = false;
  if (!thermal_grid_needed()) return;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  const bool faces = setup_.flags.explicit_heat_conduction;  // Dirichlet faces act with conduction on
  for (const MpmMaterial& m : setup_.materials) {
    const std::vector<double>& Tp = m.particles.temperature;
    const long np = long(Tp.size());
    // min / max are exact in any order: the same result for any thread count.
#pragma omp parallel for schedule(static) reduction(min : lo) reduction(max : hi) if (np >= 4096)
    for (long i = 0; i < np; ++i) {
      lo = std::min(lo, Tp[i]);
      hi = std::max(hi, Tp[i]);
    }
    if (faces)
      for (const auto& T : m.bcs.temperature)
        if (T) {
          lo = std::min(lo, *T);
          hi = std::max(hi, *T);
        }
  }
  lo = layout_.min(lo), hi = layout_.max(hi);  // over the MPI ranks: all decide alike
  if (!(hi > lo)) return;
  if (setup_.conduction_unsupported)
    throw MissingFeature(setup_.conduction_unsupported->first, setup_.conduction_unsupported->second);
  conducting_ = true;
  PhaseTimers::Scope timer(phase_timers(), "MPM: heat conduction");
  auto& mats = setup_.materials;
  // P2G temperatures before the face values (Vaango's gTemperatureNoBC), per material with faces.
  std::vector<std::vector<double>> T_free(mats.size());
  for (std::size_t i = 0; i < mats.size(); ++i) {
    MpmMaterial& m = mats[i];
    temperature_to_grid(m.particles, m.stencils, m.grid, m.thermal);
    sum_node_doubles(m.thermal.temperature);  // over the MPI ranks (divided by the global m_g already)
    fold_mass_weighted(periodic_, m.grid.mass, m.thermal.temperature);  // periodic aliases (mpm/PeriodicGrid.h)
    if (faces && has_temperature_bcs(m.bcs)) {
      T_free[i] = m.thermal.temperature;
      apply_temperature_bcs(m.bcs, m.grid, m.thermal.temperature);
    }
    if (setup_.flags.explicit_heat_conduction && m.thermal_conductivity > 0.0)
    {
      add_conduction_rate(m.particles, m.stencils, m.grid, m.thermal_conductivity, m.specific_heat, m.thermal);
      fold_mass_weighted(periodic_, m.grid.mass, m.thermal.rate);  // the rate holds conduction only here
    }
    sum_node_doubles(m.thermal.rate);  // over the MPI ranks (0 before the conduction term)
  }
  if (setup_.thermal_contact && mats.size() > 1) {
    std::vector<const NodeGrid*> grids;
    std::vector<double> cv;
    std::vector<ThermalNodes*> thermal;
    for (MpmMaterial& m : mats) {
      grids.push_back(&m.grid);
      cv.push_back(m.specific_heat);
      thermal.push_back(&m.thermal);
    }
    add_thermal_contact_rate(grids, cv, dt, thermal);
  }
  // The face nodes' rates (mpm/thermal/TemperatureBoundary.h): the P2G
  // temperature is pulled to the value the face predicts at the particles'
  // centroid.
  for (std::size_t i = 0; i < mats.size(); ++i) {
    if (T_free[i].empty()) continue;
    MpmMaterial& m = mats[i];
    std::vector<Vec3> xbar;
    mass_weighted_position(m.particles, m.stencils, m.grid, xbar);
    sum_node_vectors(xbar);  // over the MPI ranks
    face_temperature_rates(m.bcs, m.grid, m.thermal.temperature, T_free[i], xbar, dt, m.thermal.rate);
  }
}

// G2P of the temperature: T_{n+1} = T_n + dt (sum_g rate_g S_gp + hdot_p),
// hdot_p the model's heating rate of the step (adiabatic plastic work, and
// the artificial-viscosity heating when the deck asks for it).
void MpmComponent::update_temperatures(MpmMaterial& m, double dt) {
  Particles& p = m.particles;
  if (conducting_) temperature_rate_to_particles(m.stencils, m.thermal, dt, p);
  const long n = long(std::min(p.size(), m.heating.size()));
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (long i = 0; i < n; ++i) p.temperature[i] += dt * m.heating[i];
}

}  // namespace tephra
