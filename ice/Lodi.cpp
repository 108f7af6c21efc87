#include "ice/Lodi.h"

#include <algorithm>
#include <cmath>

namespace tephra {

namespace {

constexpr double kSmall = 1e-100;  // Uintah's d_SMALL_NUM in L2/u, L3/u, L4/u

struct Gradients {
  double rho = 0, p = 0, T_factor = 0;  // T_n = T * T_factor
  Vec3 vel = Vec3::Zero();
};

// The amplitudes at one inner cell and the normal gradients they imply (see Lodi.h).
Gradients lodi_gradients(const LodiSettings& s, int d, bool upper, double max_mach, double domain_length,
                         double g_n, double gamma, double rho, double p, const Vec3& vel, double c,
                         double drho, double dp, const Vec3& dvel) {
  const int t1 = (d + 1) % 3, t2 = (d + 2) % 3;
  const double u = vel[d];
  const double mach = vel.norm() / c;
  const double A = rho * c * dvel[d];
  double L1 = 0.5 * (u - c) * (dp - A);
  double L2 = u * (drho - dp / (c * c));
  double L3 = u * dvel[t1];
  double L4 = u * dvel[t2];
  double L5 = 0.5 * (u + c) * (dp + A);
  // Body-force sources (Sutherland & Kennedy table 4, normal gravity only).
  const double s1 = -0.5 * rho * c * g_n, s5 = 0.5 * rho * c * g_n;
  const bool inflow = upper ? u <= 0.0 : u >= 0.0;
  if (inflow && mach < 1.0) {
    if (upper) L1 = s1;
    else L5 = s5;
    L2 = L3 = L4 = 0.0;
  } else if (!inflow && mach < 1.0) {
    const double K = s.sigma * c * (1.0 - max_mach * max_mach);
    const double relax = 0.5 * K * (p - s.press_infinity) / domain_length;
    if (upper) L1 = relax + s1;
    else L5 = relax + s5;
  } else if (inflow) {  // supersonic inflow: everything imposed
    L1 = s1;
    L5 = s5;
    L2 = L3 = L4 = 0.0;
  }  // supersonic outflow: every wave leaves, nothing replaced
  L1 *= s.li_scale;
  L2 *= s.li_scale;
  L3 *= s.li_scale;
  L4 *= s.li_scale;
  L5 *= s.li_scale;
  const double a5 = L5 / (u + c), a1 = L1 / (u - c);
  Gradients out;
  out.p = a5 + a1;
  out.rho = L2 / (u + kSmall) + (a5 + a1) / (c * c);
  out.vel[d] = (a5 - a1) / (rho * c);
  out.vel[t1] = L3 / (u + kSmall);
  out.vel[t2] = L4 / (u + kSmall);
  out.T_factor = (-L2 / (u + kSmall) + (gamma - 1.0) * (a5 + a1)) / (rho * c * c);
  return out;
}

}  // namespace

void apply_lodi_face(const Grid& g, const Patch& p, GridFace f, const LodiSettings& s, const Vec3& gravity,
                     const LodiState& in, const LodiTargets& out) {
  const int d = face_axis(f);
  const bool upper = face_is_upper(f);
  if (upper ? p.extra_hi[d] <= p.hi[d] : p.extra_lo[d] >= p.lo[d]) return;
  const IntVec3 n = upper ? IntVec3(IntVec3::Unit(d)) : IntVec3(-IntVec3::Unit(d));
  const double dx = g.dx[d], sign = upper ? 1.0 : -1.0;
  const double domain_length = g.cells[d] * g.dx[d];
  // The extra cells on the face proper: tangential range = the patch's interior.
  IntVec3 lo = p.lo, hi = p.hi;
  lo[d] = upper ? g.cells[d] : -1;
  hi[d] = lo[d] + 1;
  const GridArray<double>& rho = *in.rho;
  const GridArray<double>& press = *in.press;
  const GridArray<Vec3>& vel = *in.vel;
  const GridArray<double>& cs = *in.speed_sound;
  double max_mach = 0;
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        const IntVec3 c = IntVec3(i, j, k) - n;
        max_mach = std::max(max_mach, vel(c).norm() / cs(c));
      }
  for (int k = lo[2]; k < hi[2]; ++k)
    for (int j = lo[1]; j < hi[1]; ++j)
      for (int i = lo[0]; i < hi[0]; ++i) {
        const IntVec3 e(i, j, k), c = e - n;
        // One-sided differences along +d between the inner cell and its inner neighbour.
        const IntVec3 r = upper ? c : IntVec3(c + IntVec3::Unit(d));
        const IntVec3 l = upper ? IntVec3(c - IntVec3::Unit(d)) : c;
        const Gradients gr = lodi_gradients(s, d, upper, max_mach, domain_length, gravity[d], in.gamma, rho(c), press(c),
                                            vel(c), cs(c), (rho(r) - rho(l)) / dx, (press(r) - press(l)) / dx,
                                            (vel(r) - vel(l)) / dx);
        if (out.temp) (*out.temp)(e) = (*out.temp)(c) + sign * dx * (*out.temp)(c) * gr.T_factor;
        if (out.rho) (*out.rho)(e) = rho(c) + sign * dx * gr.rho;
        if (out.press) (*out.press)(e) = press(c) + sign * dx * gr.p;
        if (out.vel) (*out.vel)(e) = vel(c) + sign * dx * gr.vel;
      }
  // Edges and corners of the face: the nearest extra cell of the face proper.
  IntVec3 elo = p.extra_lo, ehi = p.extra_hi;
  elo[d] = lo[d];
  ehi[d] = hi[d];
  for (int k = elo[2]; k < ehi[2]; ++k)
    for (int j = elo[1]; j < ehi[1]; ++j)
      for (int i = elo[0]; i < ehi[0]; ++i) {
        const IntVec3 e(i, j, k);
        IntVec3 src = e;
        for (int t = 0; t < 3; ++t) src[t] = std::clamp(src[t], lo[t], hi[t] - 1);
        if (src == e) continue;
        if (out.temp) (*out.temp)(e) = (*out.temp)(src);
        if (out.rho) (*out.rho)(e) = (*out.rho)(src);
        if (out.press) (*out.press)(e) = (*out.press)(src);
        if (out.vel) (*out.vel)(e) = (*out.vel)(src);
      }
}

}  // namespace tephra
