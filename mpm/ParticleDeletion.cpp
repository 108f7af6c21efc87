#include "mpm/ParticleDeletion.h"

#include <algorithm>
#include <limits>
#include <sstream>

namespace tephra {

namespace {

// Keeps the rows of `column` (components values per row) with keep[i] != 0.
template <class T>
void compact(std::vector<T>& column, const std::vector<char>& keep, std::size_t components = 1) {
  if (column.empty()) return;
  std::size_t out = 0;
  for (std::size_t i = 0; i < keep.size(); ++i) {
    if (!keep[i]) continue;
    if (out != i)
      for (std::size_t c = 0; c < components; ++c) column[out * components + c] = column[i * components + c];
    ++out;
  }
  column.resize(out * components);
}

}  // namespace

void remove_particles(Particles& p, const std::vector<char>& keep, std::vector<std::vector<double>*> extra_doubles,
                      std::vector<std::vector<Mat3>*> extra_mats) {
  const std::size_t n = p.size();
  compact(p.x, keep);
  compact(p.v, keep);
  compact(p.displacement, keep);
  compact(p.external_force, keep);
  compact(p.F, keep);
  compact(p.stress, keep);
  compact(p.psize, keep);
  compact(p.mass, keep);
  compact(p.volume, keep);
  compact(p.volume0, keep);
  compact(p.temperature, keep);
  compact(p.color, keep);
  compact(p.wave_speed, keep);
  compact(p.energy_density, keep);
  compact(p.q, keep);
  compact(p.id, keep);
  // History columns hold `components` values per particle.
  for (std::vector<double>& h : p.history) compact(h, keep, n ? h.size() / n : 1);
  for (std::vector<double>* c : extra_doubles)
    if (c->size() == n) compact(*c, keep);
  for (std::vector<Mat3>* c : extra_mats)
    if (c->size() == n) compact(*c, keep);
}

bool outside_domain(const Grid& domain, const Vec3& x, int* d_out) {
  for (int d = 0; d < 3; ++d)
    if (!domain.periodic[d] && (x[d] < domain.lower[d] || x[d] > domain.upper[d])) {
      if (d_out) *d_out = d;
      return true;
    }
  return false;
}

std::vector<char> apply_particle_limits(const ParticleLimits& limits, const std::vector<Vec3>& v_old,
                                        Particles& p, std::vector<DeletedParticle>& deleted) {
  std::vector<char> keep(p.size(), 1);
  // Threaded screen with the loop's own tests: almost always no particle is
  // touched, and the serial loop below (strings, a square root per particle)
  // was a part of the step that did not scale with threads.
  // The domain test as outside_domain's, with the bounds in locals (read
  // through the Grid at every particle it cost ~40 instructions per
  // particle-step): a periodic direction (or no domain) gets [-inf, +inf],
  // where x < lo and x > hi are false for every x, NaN included, as the
  // skipped test.
  const long np = long(p.size());
  const double inf = std::numeric_limits<double>::infinity();
  double lo[3] = {-inf, -inf, -inf}, hi[3] = {inf, inf, inf};
  if (limits.domain)
    for (int d = 0; d < 3; ++d)
      if (!limits.domain->periodic[d]) lo[d] = limits.domain->lower[d], hi[d] = limits.domain->upper[d];
  const double min_mass = limits.minimum_mass, max_speed = limits.maximum_speed;
  const double* mass = p.mass.data();
  const double* temperature = p.temperature.data();
  const Vec3* v = p.v.data();
  const Vec3* x = p.x.data();
  long first = np;  // the lowest particle the loop below acts on
#pragma omp parallel for schedule(static) reduction(min : first) if (np >= 4096)
  for (long i = 0; i < np; ++i) {
    const Vec3& xi = x[i];
    const bool outside = xi[0] < lo[0] || xi[0] > hi[0] || xi[1] < lo[1] || xi[1] > hi[1] || xi[2] < lo[2] ||
                         xi[2] > hi[2];
    if (mass[i] <= min_mass || temperature[i] < 0.0 || v[i].norm() > max_speed || outside) first = std::min(first, i);
  }
  for (std::size_t i = std::size_t(first); i < p.size(); ++i) {
    std::string reason;
    if (p.mass[i] <= limits.minimum_mass) {
      std::ostringstream s;
      s << "mass " << p.mass[i] << " kg <= minimum_particle_mass " << limits.minimum_mass;
      reason = s.str();
    } else if (p.temperature[i] < 0.0) {
      std::ostringstream s;
      s << "negative temperature " << p.temperature[i] << " K";
      reason = s.str();
    }
    int d_out = -1;
    if (reason.empty() && limits.domain && outside_domain(*limits.domain, p.x[i], &d_out)) {
      const bool high = p.x[i][d_out] > limits.domain->upper[d_out];
      std::ostringstream s;
      s.precision(17);
      s << "left the domain through its " << "xyz"[d_out] << (high ? "+" : "-") << " face (x = (" << p.x[i][0] << ", "
        << p.x[i][1] << ", " << p.x[i][2] << "); Uintah's relocation deletes a particle outside every patch)";
      reason = s.str();
    }
    const double speed = p.v[i].norm();
    if (reason.empty() && speed > limits.maximum_speed) {
      if (limits.delete_rogue) {
        std::ostringstream s;
        s << "speed " << speed << " m/s > maximum_particle_velocity " << limits.maximum_speed;
        reason = s.str();
      } else if (speed >= v_old[i].norm()) {
        p.v[i] *= 0.9 * limits.maximum_speed / speed;
      }
    }
    if (!reason.empty()) {
      keep[i] = 0;
      deleted.push_back({p.id[i], p.mass[i], reason});
    }
  }
  return keep;
}

}  // namespace tephra
