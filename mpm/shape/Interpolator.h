#pragma once
// The MPM interpolator of a run (<MPM><interpolator>, <cpdi_lcrit>) and the
// per-particle stencils it produces.
//
// A stencil is stored flat: particle p owns the entries [p W, (p+1) W) of
// node / w / grad, W = width(kind) (8 linear, 27 gimp and 3rdorderBS, 32
// cpti, 64 cpdi, cpgimp and 4thorderBS). Unused entries have w = 0, grad = 0 and a valid node, so the
// transfers (mpm/Transfers.h) loop over W entries without branches. The
// interpolator is chosen once per material per step; the shape-function code
// inside the loop is a template instance (no per-particle dispatch).
#include <cstddef>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "mpm/shape/ScatterOrder.h"

namespace tephra {

struct Particles;
struct NodeGrid;

// CpGimp: contiguous-particle GIMP (theory manual §1.6.3, eq. 1.93), the
// GIMP convolution with the half-lengths of the cuboid circumscribing the
// deformed domain F size (l_d = l0_d F_dd for diagonal F; ShapeGimp.h
// gimp_axis_any). Not a Vaango interpolator and not yet selectable from a
// deck (MpmFlags accepts Vaango's names only); it is the candidate fix of
// the uGIMP stall on AxisAligned (docs/mpm-convergence.md).
// Cpti: one tetrahedron per particle (ShapeCpti.h). CubicBspline: Vaango's
// 4thorderBS with its boundary-modified splines (ShapeBsplineCubic.h).
enum class InterpolatorKind { Linear, Gimp, Cpdi, QuadraticBspline, CpGimp, Cpti, CubicBspline };

struct InterpolatorSpec {
  InterpolatorKind kind = InterpolatorKind::Linear;
  double cpdi_lcrit = 1e10;  // <cpdi_lcrit>, node-index units (Vaango's default: no limit)
};

// Entries per particle.
int stencil_width(InterpolatorKind k);
// Vaango's name ("linear", "gimp", "cpdi", "cpti", "3rdorderBS", "4thorderBS";
// Tephra's "cpgimp").
std::string interpolator_name(InterpolatorKind k);

struct Stencils {
  int width = 8;
  // Flat form (axis_nodes == 0): entry k of particle p at p W + k.
  std::vector<std::size_t> node;  // flat node index (NodeGrid::index)
  std::vector<double> w;          // S_gp
  std::vector<Vec3> grad;         // grad S_gp [1/m]
  // Axisymmetric stencils (mpm/Axisymmetric.h): grad[2] is the hoop factor
  // T_gp (S / r_p for most interpolators) of v_r / r and sigma_thth / r, not
  // a derivative; gradients of scalars (temperature, mass) use grad[0..1].
  bool hoop_factor = false;
  // Per-axis form of the tensor-product interpolators (axis_nodes = N > 0,
  // node / w / grad empty; mpm/shape/AxisStencils.h forms the entries):
  // particle p stores the flat index of its lowest support node and, per
  // axis d, the N 1-D factors S_d[a] and G_d[a] = (dS_d/dxi)[a] / h_d, so
  //   S_gp = S_x[a] S_y[b] S_z[c],
  //   grad S_gp = (G_x[a] S_y[b] S_z[c], S_x[a] G_y[b] S_z[c], S_x[a] S_y[b] G_z[c]),
  // node = base + a + stride_y b + stride_z c (x fastest, as the flat form).
  int axis_nodes = 0;
  std::size_t stride_y = 0, stride_z = 0;  // NodeGrid index steps in y and z
  std::vector<std::size_t> base;           // per particle
  std::vector<double> factors;             // per particle 6 N: S_x, S_y, S_z, G_x, G_y, G_z
  // The particle order of the threaded scatters (ScatterOrder.h), built by
  // compute_stencils / compute_axis_stencils / order_scatter for these stencils.
  ScatterOrder order;
  std::size_t particles() const {
    return axis_nodes ? base.size() : width ? w.size() / width : 0;
  }
};

// Stencils of every particle of `p` on `g`. Returns the index of the first
// particle whose support leaves the node grid (or whose CPDI domain is
// degenerate), or -1 when all are fine.
long compute_stencils(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s);

// The per-axis form (above) for linear, gimp and 3rdorderBS, when every
// particle's support lies inside the node grid: returns true and fills `s`
// (node / w / grad emptied). Returns false, `s` unspecified, for any other
// interpolator or when some particle's support leaves the grid (the caller
// then uses compute_stencils, which also names the failing particle). The
// weights are the bits compute_stencils gives; the gradients differ by
// round-off (1/h applied to the 1-D factor instead of the product).
bool compute_axis_stencils(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s);

// Builds s.order (ScatterOrder.h) from the stencils' node rows: the blocks of
// the lowest y and z node row of each particle, the widths from the largest
// footprint. compute_stencils and compute_axis_stencils call it on success;
// call it after any other code that fills s (e.g. the axisymmetric stencils).
void order_scatter(const NodeGrid& g, Stencils& s);

}  // namespace tephra
