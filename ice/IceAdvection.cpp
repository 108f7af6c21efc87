#include "ice/IceAdvection.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"

namespace tephra {

namespace {

// The range of faces normal to d of the interior cells of patch p.
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }

// q on the donor's slab for the face (i,j,k) normal to d with face-volume
// fraction phi (signed: > 0 flows toward +d).
// Uintah's limited gradient (SecondOrderBase::limitedGradient), one
// component: central differences g_d = (q_{+d} - q_{-d})/2 (per cell), the
// extreme vertex values q +- sum_d |g_d|/2, the extremes of the six face
// neighbours, and one factor for all directions,
//   alpha = min(1, max(0, (q_max - q)/(v_max - q)), max(0, (q_min - q)/(v_min - q))).
// Returns alpha g_d (the limited difference per cell along d). In 1-D this is
// the monotonized-central limiter min((a+b)/2, 2a, 2b) for a b > 0.
double limited_difference(const double* qn, double q, int d) {
  // qn: the six neighbours (-x, +x, -y, +y, -z, +z).
  double gsum = 0, qmax = qn[0], qmin = qn[0];
  for (int k = 0; k < 3; ++k) gsum += std::abs(qn[2 * k + 1] - qn[2 * k]) * 0.25;
  for (int k = 1; k < 6; ++k) {
    qmax = std::max(qmax, qn[k]);
    qmin = std::min(qmin, qn[k]);
  }
  if (gsum == 0.0) return 0.0;
  const double a_max = std::max(0.0, (qmax - q) / gsum), a_min = std::max(0.0, (q - qmin) / gsum);
  const double alpha = std::min(1.0, std::min(a_max, a_min));
  return alpha * 0.5 * (qn[2 * d + 1] - qn[2 * d]);
}

double limited_difference(const GridArray<double>& q, const IntVec3& D, int d) {
  double qn[6];
  for (int k = 0; k < 3; ++k) {
    const IntVec3 e = IntVec3::Unit(k);
    qn[2 * k] = q(IntVec3(D - e));
    qn[2 * k + 1] = q(IntVec3(D + e));
  }
  return limited_difference(qn, q(D), d);
}

Vec3 limited_difference(const GridArray<Vec3>& q, const IntVec3& D, int d) {
  Vec3 out;
  for (int c = 0; c < 3; ++c) {
    double qn[6];
    for (int k = 0; k < 3; ++k) {
      const IntVec3 e = IntVec3::Unit(k);
      qn[2 * k] = q(IntVec3(D - e))[c];
      qn[2 * k + 1] = q(IntVec3(D + e))[c];
    }
    out[c] = limited_difference(qn, q(D)[c], d);
  }
  return out;
}

template <class T>
T slab_value(const Grid& g, AdvectionOrder order, const GridArray<T>& q, int d, const IntVec3& face, double phi) {
  const IntVec3 e = IntVec3::Unit(d);
  const IntVec3 D = phi > 0.0 ? IntVec3(face - e) : face;
  if (order == AdvectionOrder::First) return q(D);
  if (!g.periodic[d] && (D[d] < 0 || D[d] >= g.cells[d])) return q(D);  // extra cell: no slope (periodic: ghosts wrap)
  const T dq = limited_difference(q, D, d);
  const double s = phi > 0.0 ? 1.0 : -1.0;
  return q(D) + dq * (s * 0.5 * (1.0 - std::abs(phi)));
}

}  // namespace

void check_outflux(const Grid& g, const FaceScalars& u, double dt, int step) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& p = g.patches[pi];
    for_each_cell_serial(p.cells(), [&](int i, int j, int k) {
      double out = 0;
      for (int d = 0; d < 3; ++d) {
        const GridArray<double>& f = u.at(d, pi);
        const IntVec3 c(i, j, k), e = IntVec3::Unit(d);
        out += std::max(0.0, -f(c)) * dt / g.dx[d] + std::max(0.0, f(IntVec3(c + e))) * dt / g.dx[d];
      }
      if (out > 1.0) {
        std::ostringstream os;
        os << "ICE advection at step " << step << ": cell (" << i << "," << j << "," << k
           << ") would lose a fraction " << out << " > 1 of its content (face velocities too large for dt)";
        throw NumericalFailure(os.str());
      }
    });
  }
}

void density_fluxes(const Grid& g, AdvectionOrder order, const CellScalars& q, const FaceScalars& u, double dt,
                    FaceScalars& flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& uf = u.at(d, pi);
      GridArray<double>& F = flux.at(d, pi);
      const double r = dt / g.dx[d];
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const double phi = uf(i, j, k) * r;
        F(i, j, k) = phi == 0.0 ? 0.0 : phi * slab_value(g, order, q[pi], d, IntVec3(i, j, k), phi);
      });
    }
  }
}

template <class T>
void specific_fluxes(const Grid& g, AdvectionOrder order, const PatchFields<CellField<T>>& psi,
                     const FaceScalars& u, const FaceScalars& mass_flux, double dt, FaceData<T>& flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& uf = u.at(d, pi);
      const GridArray<double>& mf = mass_flux.at(d, pi);
      GridArray<T>& F = flux.at(d, pi);
      const double r = dt / g.dx[d];
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const double phi = uf(i, j, k) * r;
        if (phi == 0.0) {
          F(i, j, k) = T(psi[pi](i, j, k) * 0.0);
          return;
        }
        F(i, j, k) = mf(i, j, k) * slab_value(g, order, psi[pi], d, IntVec3(i, j, k), phi);
      });
    }
  }
}

template <class T>
void flux_divergence(const Grid& g, const FaceData<T>& flux, PatchFields<CellField<T>>& dq) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const GridArray<T>& fx = flux.at(0, pi);
    const GridArray<T>& fy = flux.at(1, pi);
    const GridArray<T>& fz = flux.at(2, pi);
    GridArray<T>& out = dq[pi];
    for_each_cell(g.patches[pi].cells(), [&](int i, int j, int k) {
      out(i, j, k) = T((fx(i, j, k) - fx(i + 1, j, k)) + (fy(i, j, k) - fy(i, j + 1, k)) + (fz(i, j, k) - fz(i, j, k + 1)));
    });
  }
}

template void specific_fluxes<double>(const Grid&, AdvectionOrder, const CellScalars&, const FaceScalars&,
                                      const FaceScalars&, double, FaceScalars&);
template void specific_fluxes<Vec3>(const Grid&, AdvectionOrder, const CellVectors&, const FaceScalars&,
                                    const FaceScalars&, double, FaceData<Vec3>&);
template void flux_divergence<double>(const Grid&, const FaceScalars&, CellScalars&);
template void flux_divergence<Vec3>(const Grid&, const FaceData<Vec3>&, CellVectors&);

}  // namespace tephra
