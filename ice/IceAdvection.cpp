#include "ice/IceAdvection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"

namespace tephra {

namespace {

// The range of faces normal to d of the interior cells of patch p.
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }

// Uintah's limited gradient (SecondOrderBase::limitedGradient), one
// component: central differences g_d = (q_{+d} - q_{-d})/2 (per cell), the
// extreme vertex values q +- sum_d |g_d|/2, the extremes of the six face
// neighbours, and one factor for all directions,
//   alpha = min(1, max(0, (q_max - q)/(v_max - q)), max(0, (q_min - q)/(v_min - q))),
// giving the limited differences alpha g_d per cell along d = 0, 1, 2. In
// 1-D this is the monotonized-central limiter min((a+b)/2, 2a, 2b) for a b > 0.
// Slopes holds them for every cell that can be a donor with a slope (the
// patch's cells grown by one, inside the domain in the non-periodic
// directions), computed once per cell rather than once per face (a cell is
// the donor of about three faces). Storage: a per-thread buffer indexed like q.
template <class T>
class Slopes {
 public:
  Slopes(const Grid& g, const Patch& patch, const GridArray<T>& q) : q_(q) {
    thread_local std::vector<T> buffer;
    if (buffer.size() < 3 * q.size()) buffer.resize(3 * q.size());
    s_ = buffer.data();
    IndexRange r = patch.cells().grown(1);
    for (int d = 0; d < 3; ++d)
      if (!g.periodic[d]) {
        r.lo[d] = std::max(r.lo[d], 0);
        r.hi[d] = std::min(r.hi[d], g.cells[d]);
      }
    if (r.empty()) return;
    T* s = s_;
    const T* base = q.data();
    // Strides of the neighbours along x, y, z in q's storage.
    const IntVec3 c0 = r.lo;
    const std::ptrdiff_t sx = 1, sy = std::ptrdiff_t(q.offset(c0[0], c0[1] + 1, c0[2]) - q.offset(c0[0], c0[1], c0[2])),
                         sz = std::ptrdiff_t(q.offset(c0[0], c0[1], c0[2] + 1) - q.offset(c0[0], c0[1], c0[2]));
    const std::ptrdiff_t stride[3] = {sx, sy, sz};
    for_each_cell(r, [&](int i, int j, int k) {
      const std::size_t off = q.offset(i, j, k);
      compute(base + off, stride, s + 3 * off);
    });
  }
  const T* at_offset(std::size_t off) const { return s_ + 3 * off; }

 private:
  static void compute(const double* q, const std::ptrdiff_t* stride, double* out) {
    double qn[6];
    for (int k = 0; k < 3; ++k) {
      qn[2 * k] = q[-stride[k]];
      qn[2 * k + 1] = q[stride[k]];
    }
    limited_differences(qn, *q, out);
  }
  static void compute(const Vec3* q, const std::ptrdiff_t* stride, Vec3* out) {
    for (int c = 0; c < 3; ++c) {
      double qn[6], o[3];
      for (int k = 0; k < 3; ++k) {
        qn[2 * k] = q[-stride[k]][c];
        qn[2 * k + 1] = q[stride[k]][c];
      }
      limited_differences(qn, (*q)[c], o);
      for (int d = 0; d < 3; ++d) out[d][c] = o[d];
    }
  }
  // qn: the six neighbours (-x, +x, -y, +y, -z, +z) of a cell with value q;
  // out: alpha g_d for d = 0, 1, 2.
  static void limited_differences(const double* qn, double q, double* out) {
    double gsum = 0, qmax = qn[0], qmin = qn[0];
    for (int k = 0; k < 3; ++k) gsum += std::abs(qn[2 * k + 1] - qn[2 * k]) * 0.25;
    for (int k = 1; k < 6; ++k) {
      qmax = std::max(qmax, qn[k]);
      qmin = std::min(qmin, qn[k]);
    }
    if (gsum == 0.0) {
      out[0] = out[1] = out[2] = 0.0;
      return;
    }
    const double a_max = std::max(0.0, (qmax - q) / gsum), a_min = std::max(0.0, (q - qmin) / gsum);
    const double alpha = std::min(1.0, std::min(a_max, a_min));
    for (int d = 0; d < 3; ++d) out[d] = alpha * 0.5 * (qn[2 * d + 1] - qn[2 * d]);
  }

  const GridArray<T>& q_;
  T* s_ = nullptr;
};

// Strides of a field's storage along x, y, z.
template <class T>
std::array<std::ptrdiff_t, 3> strides_of(const GridArray<T>& q) {
  const IntVec3 c = q.with_ghosts().lo;
  const std::size_t o = q.offset(c[0], c[1], c[2]);
  return {1, std::ptrdiff_t(q.offset(c[0], c[1] + 1, c[2]) - o), std::ptrdiff_t(q.offset(c[0], c[1], c[2] + 1) - o)};
}

// q on the donor's slab for the face (i,j,k) normal to d (the low face of
// cell R = (i,j,k), at storage offset offR in q) with face-volume fraction
// phi (signed: > 0 flows toward +d, donor L = R - e_d); slopes is null for
// first order.
template <class T>
T slab_value(const Grid& g, const GridArray<T>& q, const Slopes<T>* slopes, int d, const IntVec3& face,
             std::size_t offR, std::ptrdiff_t stride_d, double phi) {
  const bool from_low = phi > 0.0;
  const std::size_t offD = from_low ? offR - stride_d : offR;
  const T& qD = q.data()[offD];
  if (!slopes) return qD;
  const int Dd = face[d] - (from_low ? 1 : 0);
  if (!g.periodic[d] && (Dd < 0 || Dd >= g.cells[d])) return qD;  // extra cell: no slope (periodic: ghosts wrap)
  const T dq = slopes->at_offset(offD)[d];
  const double s = from_low ? 1.0 : -1.0;
  return qD + dq * (s * 0.5 * (1.0 - std::abs(phi)));
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
    std::optional<Slopes<double>> slopes;
    if (order != AdvectionOrder::First) slopes.emplace(g, g.patches[pi], q[pi]);
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& uf = u.at(d, pi);
      GridArray<double>& F = flux.at(d, pi);
      const double r = dt / g.dx[d];
      const std::ptrdiff_t stride_d = strides_of(q[pi])[d];
      const GridArray<double>& qp = q[pi];
      const Slopes<double>* sl = slopes ? &*slopes : nullptr;
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const double phi = uf(i, j, k) * r;
        F(i, j, k) =
            phi == 0.0 ? 0.0 : phi * slab_value(g, qp, sl, d, IntVec3(i, j, k), qp.offset(i, j, k), stride_d, phi);
      });
    }
  }
}

template <class T>
void specific_fluxes(const Grid& g, AdvectionOrder order, const PatchFields<CellField<T>>& psi,
                     const FaceScalars& u, const FaceScalars& mass_flux, double dt, FaceData<T>& flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    std::optional<Slopes<T>> slopes;
    if (order != AdvectionOrder::First) slopes.emplace(g, g.patches[pi], psi[pi]);
    for (int d = 0; d < 3; ++d) {
      const GridArray<double>& uf = u.at(d, pi);
      const GridArray<double>& mf = mass_flux.at(d, pi);
      GridArray<T>& F = flux.at(d, pi);
      const double r = dt / g.dx[d];
      const std::ptrdiff_t stride_d = strides_of(psi[pi])[d];
      const GridArray<T>& qp = psi[pi];
      const Slopes<T>* sl = slopes ? &*slopes : nullptr;
      for_each_cell(faces_of(g.patches[pi], d), [&](int i, int j, int k) {
        const double phi = uf(i, j, k) * r;
        const std::size_t offR = qp.offset(i, j, k);
        if (phi == 0.0) {
          F(i, j, k) = T(qp.data()[offR] * 0.0);
          return;
        }
        F(i, j, k) = mf(i, j, k) * slab_value(g, qp, sl, d, IntVec3(i, j, k), offR, stride_d, phi);
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
