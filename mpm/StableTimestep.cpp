#include "mpm/StableTimestep.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tephra {

double particle_stable_timestep_by_quotients(const Particles& p, const Vec3& h) {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int d = 0; d < 3; ++d) dt = std::min(dt, h[d] / (p.wave_speed[i] + std::abs(p.v[i][d])));
  return dt;
}

// Why the bits are those of the quotients: with s = c_p + |v_p,d| > 0 and
// h_d > 0, the rounded quotient fl(h_d / s) does not increase as s grows
// (IEEE division is correctly rounded, and rounding is monotone), so
//   min_p fl(h_d / s_p) = fl(h_d / max_p s_p)
// exactly. The other cases: a NaN s gives a NaN quotient, which std::min(dt, q)
// never takes (q < dt is false), and which fails the s > max test below;
// s = +0 gives h / +0 = +inf in both (the max starts at +0, so h / +0 when no
// s > 0); s = +inf gives +0 in both. A negative s (no model gives a negative
// wave speed) would make its quotient negative and the minimum: then the
// quotient loop runs.
double particle_stable_timestep(const Particles& p, const Vec3& h) {
  const long np = static_cast<long>(p.size());
  double s0 = 0.0, s1 = 0.0, s2 = 0.0;  // max_p s_p,d over s > 0
  int negative = 0;
  // max is exact and independent of the order: the same value for any thread count.
#pragma omp parallel for schedule(static) reduction(max : s0, s1, s2) reduction(| : negative) if (np >= 4096)
  for (long i = 0; i < np; ++i) {
    const double c = p.wave_speed[std::size_t(i)];
    const Vec3& v = p.v[std::size_t(i)];
    const double a = c + std::abs(v[0]), b = c + std::abs(v[1]), e = c + std::abs(v[2]);
    s0 = a > s0 ? a : s0;
    s1 = b > s1 ? b : s1;
    s2 = e > s2 ? e : s2;
    negative |= int(a < 0.0) | int(b < 0.0) | int(e < 0.0);
  }
  if (negative) return particle_stable_timestep_by_quotients(p, h);
  double dt = std::numeric_limits<double>::infinity();
  dt = std::min(dt, h[0] / s0);
  dt = std::min(dt, h[1] / s1);
  dt = std::min(dt, h[2] / s2);
  return dt;
}

}  // namespace tephra
