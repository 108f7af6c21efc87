#include "ice/IceAdvection.h"

#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"

namespace tephra {

namespace {

double van_leer(double a, double b) { return a * b > 0.0 ? 2.0 * a * b / (a + b) : 0.0; }
Vec3 van_leer(const Vec3& a, const Vec3& b) { return {van_leer(a[0], b[0]), van_leer(a[1], b[1]), van_leer(a[2], b[2])}; }

// The range of faces normal to d of the interior cells of patch p.
IndexRange faces_of(const Patch& p, int d) { return {p.lo, p.hi + IntVec3::Unit(d)}; }

// q on the donor's slab for the face (i,j,k) normal to d with face-volume
// fraction phi (signed: > 0 flows toward +d).
template <class T>
T slab_value(const Grid& g, AdvectionOrder order, const GridArray<T>& q, int d, const IntVec3& face, double phi) {
  const IntVec3 e = IntVec3::Unit(d);
  const IntVec3 D = phi > 0.0 ? IntVec3(face - e) : face;
  if (order == AdvectionOrder::First) return q(D);
  if (!g.periodic[d] && (D[d] < 0 || D[d] >= g.cells[d])) return q(D);  // extra cell: no slope (periodic: ghosts wrap)
  const T dq = van_leer(T(q(D) - q(D - e)), T(q(D + e) - q(D)));
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
