#include "mpm/MpmComponent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/LU>

#include "core/base/Errors.h"
#include "core/base/PhaseTimers.h"
#include "mpm/Transfers.h"

namespace tephra {

MpmComponent::MpmComponent(MpmSetup setup) : setup_(std::move(setup)) {
  const Grid& g = setup_.grid;
  for (MpmMaterial& m : setup_.materials) {
    // Nodes of the interior and extra cells: node 0 at lower - extra*dx.
    m.grid.origin = g.lower - (g.extra_cells.cast<double>().array() * g.dx.array()).matrix();
    m.grid.h = g.dx;
    m.grid.n = g.cells + 2 * g.extra_cells + IntVec3::Ones();
    m.grid.extra = g.extra_cells;
    m.grid.reset();
  }
}

void MpmComponent::initialize() {
  long long next_id = 0;
  for (MpmMaterial& m : setup_.materials) {
    m.particles = Particles{};
    seed_particles(setup_.grid, m.sources, m.density, m.particles, next_id);
    if (m.mms) initialize_mms_particles(*m.mms, m.particles);  // x = X + u(X,0), v, F at t = 0
    // The model's history columns at their declared initial values.
    m.particles.history.clear();
    for (const HistoryVariable& h : m.model->history()) {
      std::vector<double> column;
      column.reserve(m.particles.size() * h.initial.size());
      for (std::size_t i = 0; i < m.particles.size(); ++i) column.insert(column.end(), h.initial.begin(), h.initial.end());
      m.particles.history.push_back(std::move(column));
    }
    m.F_old = m.particles.F;
    m.L.assign(m.particles.size(), Mat3::Zero());
    update_stress(m, 0, 0.0);  // sigma(F = I) = 0, and the initial wave speeds
    project_to_grid(m, 0, "initialize");  // g.* fields of the initial state
  }
  // The first step's size from the initial state (Vaango: the constitutive
  // model's computeStableTimestep at initialization, c(F = I) and v_0).
  stable_dt_ = std::numeric_limits<double>::infinity();
  for (const MpmMaterial& m : setup_.materials) stable_dt_ = std::min(stable_dt_, material_stable_timestep(m));
  time_ = 0.0;
}

// Vaango's explicit rule (UCNH::computeStressTensor, called by SerialMPM's
// computeStressTensor task): the step size is a by-product of the stress
// update of step n, evaluated from the NEW stress state and the OLD particle
// velocity, and used (times timestep_multiplier) for step n+1:
//   dt = min_d h_d / max_p (c_p + |v_p,d|),
// c_p = c(F_{n+1}) the dilatational wave speed of the model, v_p = v_n the
// velocity the particle carried into step n (SerialMPM updates it only later,
// in interpolateToParticlesAndUpdate). Infinity when there are no particles.
double MpmComponent::material_stable_timestep(const MpmMaterial& m) const {
  double dt = std::numeric_limits<double>::infinity();
  const Particles& p = m.particles;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) dt = std::min(dt, setup_.grid.dx[d] / (p.wave_speed[i] + std::abs(p.v[i][d])));
  return dt;
}

// The step size computed by the last stress update (initialize() or advance()).
double MpmComponent::stable_timestep() const { return stable_dt_; }

void MpmComponent::fail_particle(const MpmMaterial& m, std::size_t i, int step, const std::string& phase,
                                 const std::string& what) const {
  const Particles& p = m.particles;
  std::ostringstream s;
  s.precision(17);
  s << "MPM step " << step << ", " << phase << ": material " << m.index << " particle id " << p.id[i]
    << " at (" << p.x[i][0] << ", " << p.x[i][1] << ", " << p.x[i][2] << "): " << what;
  throw NumericalFailure(s.str());
}

// Stencils + P2G + internal force (Alg. 5-6) on a reset grid.
void MpmComponent::project_to_grid(MpmMaterial& m, int step, const char* phase) {
  {
    PhaseTimers::Scope t(phase_timers(), "MPM: interpolate particles to grid");
    const long bad = compute_stencils(m.particles, m.grid, setup_.flags.interpolator, m.stencils);
    if (bad >= 0) fail_particle(m, std::size_t(bad), step, phase, "particle is outside the grid");
    m.grid.reset();
    particles_to_grid(m.particles, m.stencils, setup_.gravity, m.grid);
    m.bcs.apply(m.grid, m.grid.velocity);
  }
  {
    PhaseTimers::Scope t(phase_timers(), "MPM: compute internal force");
    compute_internal_force(m.particles, m.stencils, m.grid);
  }
}

// sigma_{n+1}, c, W, history from (F_n, F_{n+1}, l, sigma_n) (Alg. 11); V_{n+1} = J V0 (Alg. 9).
void MpmComponent::update_stress(MpmMaterial& m, int step, double dt) {
  PhaseTimers::Scope t(phase_timers(), "MPM: compute stress tensor");
  Particles& p = m.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double J = p.F[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) {
      std::ostringstream s;
      s << "Jacobian det F = " << J << " (must be > 0)";
      fail_particle(m, i, step, "compute deformation gradient", s.str());
    }
    p.volume[i] = J * p.volume0[i];
  }
  m.plastic_work.resize(p.size());
  m.heating.resize(p.size());
  std::vector<std::span<double>> history(p.history.begin(), p.history.end());
  SolidUpdateInput in;
  in.dt = dt;
  in.density0 = m.density;
  in.F_old = m.F_old;
  in.F_new = p.F;
  in.L = m.L;
  in.temperature = p.temperature;
  in.stress_old = p.stress;
  const SolidUpdateOutput out{p.stress, p.wave_speed, p.energy_density, m.plastic_work, m.heating, history};
  const long bad = m.model->update(in, out);
  if (bad >= 0) fail_particle(m, std::size_t(bad), step, "compute stress tensor",
                              "constitutive model '" + m.model->type() +
                                  "' rejected the state (non-finite stress or no real wave speed)");
}

// One explicit USL step of one material (Vaango theory manual §1.5, Alg. 2).
void MpmComponent::advance_material(MpmMaterial& m, double t, double dt, int step) {
  Particles& p = m.particles;
  if (m.mms) {
    PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
    apply_mms_body_force(*m.mms, t, p);  // f_ext,p = m_p b(X_p, t_n)  (Vaango: at the step's start time)
  }
  project_to_grid(m, step, "interpolate particles to grid");  // m_g, v_g (+BC), f_ext, f_int
  {
    PhaseTimers::Scope t(phase_timers(), "MPM: integrate grid acceleration");
    integrate_grid_velocity(m.grid, dt);                // a_g = f/m_g, v*_g = v_g + a_g dt
    m.bcs.apply(m.grid, m.grid.velocity_star);           // v*_g on Dirichlet / symmetry faces
    acceleration_from_velocities(m.grid, dt);           // a_g = (v*_g - v_g)/dt
  }
  {
    PhaseTimers::Scope t(phase_timers(), "MPM: compute deformation gradient");
    velocity_gradients(m.stencils, m.grid, m.L);        // l_p = sum v*_g grad S^T
    m.F_old = p.F;
    for (std::size_t i = 0; i < p.size(); ++i)
      p.F[i] = (Mat3::Identity() + dt * m.L[i]) * p.F[i];  // F_{n+1} = (I + dt l) F_n  (eq. 1.74-1.75)
    if (m.model->rigid()) std::fill(p.F.begin(), p.F.end(), Mat3::Identity());  // F = I (VT eq. 3.1)
  }
  update_stress(m, step, dt);
  // dt of the next step from c(F_{n+1}) and v_n (before the particle update).
  stable_dt_ = std::min(stable_dt_, material_stable_timestep(m));
  {
    PhaseTimers::Scope t(phase_timers(), "MPM: interpolate to particles and update");
    grid_to_particles(m.stencils, m.grid, dt, p);       // v_p += dt a, x_p += dt v*
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!p.v[i].allFinite()) fail_particle(m, i, step, "interpolate to particles", "non-finite velocity");
      for (int d = 0; d < 3; ++d) {
        const double xi = (p.x[i][d] - m.grid.origin[d]) / m.grid.h[d];
        if (!(xi >= 0.0 && xi < m.grid.n[d] - 1))
          fail_particle(m, i, step, "interpolate to particles", "particle left the grid");
      }
    }
  }
}

void MpmComponent::advance(double t, double dt, int step) {
  stable_dt_ = std::numeric_limits<double>::infinity();
  for (MpmMaterial& m : setup_.materials) advance_material(m, t, dt, step);
  time_ = t + dt;
}

double MpmComponent::mms_displacement_error() const {
  double e2 = 0.0;
  for (const MpmMaterial& m : setup_.materials)
    if (m.mms) e2 += std::pow(mms_displacement_error_l2(*m.mms, m.particles, time_), 2);
  return std::sqrt(e2);
}

std::vector<std::string> mpm_interpolators() { return {"linear", "gimp", "cpdi", "3rdorderBS"}; }
std::vector<std::string> mpm_contact_types() { return {"null"}; }

}  // namespace tephra
