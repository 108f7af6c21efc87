#pragma once
// Which scatter path a particle takes with a PatchBand (mpm/PatchBand.h),
// for the scatter kernels (Transfers.cpp, UpdatedGridVelocity.cpp).
//
// band_tag(band, view, i, x) is -1 when particle i writes every node of its
// stencil directly (the plain path), else its patch id (the band path):
//  - per-axis stencils: -1 when the node box of the stencil (n x n x n nodes
//    from its lowest node s.base[i]) holds no band node (PatchBand::boxes),
//    else PatchBand::tag(x). A particle of the first kind would find
//    slot() < 0 at every node on the band path as well and add the same
//    expressions there, so the node sums have the same bits either way; the
//    test is a byte load instead of tag()'s three divisions and floors;
//  - flat stencils: PatchBand::tag(x) (-1 when the particle's reach cube
//    holds no band node).
#include <cstddef>

#include "core/base/Types.h"
#include "mpm/PatchBand.h"
#include "mpm/shape/AxisStencils.h"

namespace tephra {

// The band a scatter uses (nullptr when there is none or it is inactive),
// with the box answers of s's per-axis size prepared. Serial code only.
inline PatchBand* band_for_scatter(PatchBand* band, const Stencils& s) {
  if (!band || !band->active()) return nullptr;
  band->boxes(s.axis_nodes);
  return band;
}

template <int N>
[[gnu::always_inline]] inline int band_tag(const PatchBand& band, const AxisStencilView<N>& view, std::size_t i,
                                           const Vec3& x) {
  return band.box_clear(view.s.base[i]) ? -1 : band.tag(x);
}

[[gnu::always_inline]] inline int band_tag(const PatchBand& band, const FlatStencilView&, std::size_t,
                                           const Vec3& x) {
  return band.tag(x);
}

}  // namespace tephra
