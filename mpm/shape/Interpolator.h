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
  std::vector<std::size_t> node;  // flat node index (NodeGrid::index)
  std::vector<double> w;          // S_gp
  std::vector<Vec3> grad;         // grad S_gp [1/m]
  std::size_t particles() const { return width ? w.size() / width : 0; }
};

// Stencils of every particle of `p` on `g`. Returns the index of the first
// particle whose support leaves the node grid (or whose CPDI domain is
// degenerate), or -1 when all are fine.
long compute_stencils(const Particles& p, const NodeGrid& g, const InterpolatorSpec& spec, Stencils& s);

}  // namespace tephra
