#include "ice/IceAdvection.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"
#include "ice/RowLoop.h"

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
    const int n = r.hi[0] - r.lo[0];
    for_each_row(r, [&](int j, int k) {
      const std::size_t off0 = q.offset(r.lo[0], j, k);
      for (int c = 0; c < n; ++c) compute(base + off0 + c, stride, s + 3 * (off0 + c));
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

// q on the donor's slab for the face normal to d whose index along d is
// face_d (the low face of cell R, at storage offset offR in q) with
// face-volume fraction phi (signed: > 0 flows toward +d, donor L = R - e_d);
// slopes is null for first order. periodic, cells_d: the grid along d.
template <class T>
inline T slab_value(bool periodic, int cells_d, const T* q, const Slopes<T>* slopes, int d, int face_d,
                    std::size_t offR, std::ptrdiff_t stride_d, double phi) {
  const bool from_low = phi > 0.0;
  const std::size_t offD = from_low ? offR - stride_d : offR;
  const T& qD = q[offD];
  if (!slopes) return qD;
  const int Dd = face_d - (from_low ? 1 : 0);
  if (!periodic && (Dd < 0 || Dd >= cells_d)) return qD;  // extra cell: no slope (periodic: ghosts wrap)
  const T dq = slopes->at_offset(offD)[d];
  const double s = from_low ? 1.0 : -1.0;
  return qD + dq * (s * 0.5 * (1.0 - std::abs(phi)));
}

}  // namespace

namespace {
// Fraction of cell (i, j, k) that flows out through its six faces in dt.
// Axisymmetric (radial): the r-face terms times r_f/r_i (ice/RadialWeights.h).
double exact_outflux(const Grid& g, const FaceScalars& u, std::size_t pi, double dt, int i, int j, int k,
                     const RadialWeights* radial) {
  double out = 0;
  for (int d = 0; d < 3; ++d) {
    const GridArray<double>& f = u.at(d, pi);
    const IntVec3 c(i, j, k), e = IntVec3::Unit(d);
    const double wl = radial && d == 0 ? *radial->lo_row(i) : 1.0, wh = radial && d == 0 ? *radial->hi_row(i) : 1.0;
    out += wl * (std::max(0.0, -f(c)) * dt / g.dx[d]) + wh * (std::max(0.0, f(IntVec3(c + e))) * dt / g.dx[d]);
  }
  return out;
}
}  // namespace

double check_outflux(const Grid& g, const FaceScalars& u, double dt, int step, const RadialWeights* radial) {
  double largest = 0.0;
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const Patch& p = g.patches[pi];
    const IndexRange r = p.cells();
    if (r.empty()) continue;
    const int i0 = r.lo[0], n = r.hi[0] - i0, ny = r.hi[1] - r.lo[1];
    const double rx = dt / g.dx[0], ry = dt / g.dx[1], rz = dt / g.dx[2];
    // Per row: the first cell (lowest i) that would lose more than its content, or -1.
    std::vector<int> failed(static_cast<std::size_t>(ny) * (r.hi[2] - r.lo[2]), -1);
    std::vector<double> row_max(failed.size(), 0.0);  // per row: the largest outflow fraction
    for_each_row(r, [&](int j, int k) {
      const double* ux = row_ptr(u.at(0, pi), i0, j, k);
      const double* uy0 = row_ptr(u.at(1, pi), i0, j, k);
      const double* uy1 = row_ptr(u.at(1, pi), i0, j + 1, k);
      const double* uz0 = row_ptr(u.at(2, pi), i0, j, k);
      const double* uz1 = row_ptr(u.at(2, pi), i0, j, k + 1);
      double most = 0.0;
      const double* wlo = radial ? radial->lo_row(i0) : nullptr;
      const double* whi = radial ? radial->hi_row(i0) : nullptr;
      for (int c = 0; c < n; ++c) {
        // Outflow fraction through the low and high face of each direction (x, y, z in this order).
        double out = 0;
        if (radial)
          out += wlo[c] * (std::max(0.0, -ux[c]) * rx) + whi[c] * (std::max(0.0, ux[c + 1]) * rx);
        else
          out += std::max(0.0, -ux[c]) * rx + std::max(0.0, ux[c + 1]) * rx;
        out += std::max(0.0, -uy0[c]) * ry + std::max(0.0, uy1[c]) * ry;
        out += std::max(0.0, -uz0[c]) * rz + std::max(0.0, uz1[c]) * rz;
        most = std::max(most, out);
        // The screen above multiplies by dt/dx; the decision uses the reference
        // form (a dt)/dx of every term, so a margin of 1e-12 hands the cells
        // near the bound to it.
        if (out > 1.0 - 1e-12 && exact_outflux(g, u, pi, dt, i0 + c, j, k, radial) > 1.0) {
          failed[static_cast<std::size_t>(k - r.lo[2]) * ny + (j - r.lo[1])] = i0 + c;
          return;
        }
      }
      row_max[static_cast<std::size_t>(k - r.lo[2]) * ny + (j - r.lo[1])] = most;
    });
    for (double v : row_max) largest = std::max(largest, v);
    for (std::size_t row = 0; row < failed.size(); ++row) {
      if (failed[row] < 0) continue;
      const int i = failed[row], j = r.lo[1] + int(row % ny), k = r.lo[2] + int(row / ny);
      const double out = exact_outflux(g, u, pi, dt, i, j, k, radial);
      std::ostringstream os;
      os << "ICE advection at step " << step << ": cell (" << i << "," << j << "," << k
         << ") would lose a fraction " << out << " > 1 of its content (face velocities too large for dt)";
      throw NumericalFailure(os.str());
    }
  }
  return largest;
}

namespace {

// The faces normal to d of patch pi, one row at a time: face(j, k, i0, n, c,
// offR, face_d, phi) for the n faces of the row, c = 0..n-1 the position in
// the row (i = i0 + c), offR the storage offset in q of the face's high cell
// R, face_d the face's index along d and phi = u_f dt/dx_d.
template <class T, class Face>
void for_each_face_row(const Grid& g, const Patch& patch, int d, const GridArray<T>& q, const GridArray<double>& uf,
                       double dt, Face&& face) {
  const IndexRange fr = faces_of(patch, d);
  const int i0 = fr.lo[0], n = fr.hi[0] - i0;
  const double r = dt / g.dx[d];
  for_each_row(fr, [&](int j, int k) {
    const double* u = row_ptr(uf, i0, j, k);
    const std::size_t offR0 = q.offset(i0, j, k);
    face(j, k, u, r, offR0, n);
  });
}

}  // namespace

void density_fluxes(const Grid& g, AdvectionOrder order, const CellScalars& q, const FaceScalars& u, double dt,
                    FaceScalars& flux) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    std::optional<Slopes<double>> slopes;
    if (order != AdvectionOrder::First) slopes.emplace(g, g.patches[pi], q[pi]);
    for (int d = 0; d < 3; ++d) {
      GridArray<double>& F = flux.at(d, pi);
      const std::ptrdiff_t stride_d = strides_of(q[pi])[d];
      const double* qb = q[pi].data();
      const Slopes<double>* sl = slopes ? &*slopes : nullptr;
      const bool periodic = g.periodic[d];
      const int cells_d = g.cells[d];
      for_each_face_row(g, g.patches[pi], d, q[pi], u.at(d, pi), dt,
                        [&](int j, int k, const double* uf, double r, std::size_t offR0, int n) {
                          const int i0 = g.patches[pi].lo[0];
                          double* out = row_ptr(F, i0, j, k);
                          const int fd = d == 1 ? j : k;
                          for (int c = 0; c < n; ++c) {
                            const double phi = uf[c] * r;
                            out[c] = phi == 0.0 ? 0.0
                                                : phi * slab_value(periodic, cells_d, qb, sl, d, d == 0 ? i0 + c : fd,
                                                                   offR0 + c, stride_d, phi);
                          }
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
      const GridArray<double>& mf = mass_flux.at(d, pi);
      GridArray<T>& F = flux.at(d, pi);
      const std::ptrdiff_t stride_d = strides_of(psi[pi])[d];
      const T* qb = psi[pi].data();
      const Slopes<T>* sl = slopes ? &*slopes : nullptr;
      const bool periodic = g.periodic[d];
      const int cells_d = g.cells[d];
      for_each_face_row(g, g.patches[pi], d, psi[pi], u.at(d, pi), dt,
                        [&](int j, int k, const double* uf, double r, std::size_t offR0, int n) {
                          const int i0 = g.patches[pi].lo[0];
                          T* out = row_ptr(F, i0, j, k);
                          const double* m = row_ptr(mf, i0, j, k);
                          const int fd = d == 1 ? j : k;
                          for (int c = 0; c < n; ++c) {
                            const double phi = uf[c] * r;
                            if (phi == 0.0) {
                              out[c] = T(qb[offR0 + c] * 0.0);
                              continue;
                            }
                            out[c] = m[c] * slab_value(periodic, cells_d, qb, sl, d, d == 0 ? i0 + c : fd, offR0 + c,
                                                       stride_d, phi);
                          }
                        });
    }
  }
}

template <class T>
void flux_divergence(const Grid& g, const FaceData<T>& flux, PatchFields<CellField<T>>& dq, const RadialWeights* radial) {
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    const GridArray<T>& fx = flux.at(0, pi);
    const GridArray<T>& fy = flux.at(1, pi);
    const GridArray<T>& fz = flux.at(2, pi);
    GridArray<T>& out = dq[pi];
    const IndexRange r = g.patches[pi].cells();
    const int i0 = r.lo[0], n = r.hi[0] - i0;
    for_each_row(r, [&](int j, int k) {
      const T* x = row_ptr(fx, i0, j, k);
      const T *y0 = row_ptr(fy, i0, j, k), *y1 = row_ptr(fy, i0, j + 1, k);
      const T *z0 = row_ptr(fz, i0, j, k), *z1 = row_ptr(fz, i0, j, k + 1);
      T* o = row_ptr(out, i0, j, k);
      if (radial) {  // r-faces weighted by r_f/r_i (ice/RadialWeights.h)
        const double *wlo = radial->lo_row(i0), *whi = radial->hi_row(i0);
        for (int c = 0; c < n; ++c) o[c] = T((wlo[c] * x[c] - whi[c] * x[c + 1]) + (y0[c] - y1[c]) + (z0[c] - z1[c]));
        return;
      }
      for (int c = 0; c < n; ++c) o[c] = T((x[c] - x[c + 1]) + (y0[c] - y1[c]) + (z0[c] - z1[c]));
    });
  }
}

template void specific_fluxes<double>(const Grid&, AdvectionOrder, const CellScalars&, const FaceScalars&,
                                      const FaceScalars&, double, FaceScalars&);
template void specific_fluxes<Vec3>(const Grid&, AdvectionOrder, const CellVectors&, const FaceScalars&,
                                    const FaceScalars&, double, FaceData<Vec3>&);
template void flux_divergence<double>(const Grid&, const FaceScalars&, CellScalars&, const RadialWeights*);
template void flux_divergence<Vec3>(const Grid&, const FaceData<Vec3>&, CellVectors&, const RadialWeights*);

}  // namespace tephra
