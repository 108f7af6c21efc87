#pragma once
// MPMICE's particle scatters in patch order (issue 7; docs/parallel.md
// "MPMICE on ranks", session 21): the node sums of the coupled step (T_g,
// the pressure force, the burn's node and cell sums, the solid mass
// projections of the volume fluxes) formed as MPM forms its P2G sums
// (mpm/PatchBand.h): at a node that the reach boxes of two or more patches
// hold, per patch, then added in ascending patch id; elsewhere straight into
// the array. Each patch's particles are visited in the scatter order
// (colour, block, id; mpm/shape/ScatterOrder.h), which depends on the
// positions and ids only, so one process and any number of MPI ranks form
// every sum with the same additions in the same order: the same bits.
//
// A cell-centred sum (the burn's cell shares) is kept at the cell's lower
// corner node, one node below the particle's stencil at most: the band of
// MpmComponent::coupling_band(1) is one node wider than MPM's own, which
// covers it.
//
// Without a band (one patch, periodic, axisymmetric: MpmComponent
// ::coupling_band returns null) the particles are visited in storage order,
// as before session 21 (the one-process bits of single-patch decks unchanged).
#include <cstddef>
#include <limits>

#include "mpm/BandTag.h"
#include "mpm/PatchBand.h"
#include "mpm/shape/ScatterOrder.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// body(i) for every particle i < np: with a band, serially in the scatter
// order of st (the same order at every node for any thread count); without,
// in storage order.
template <class Body>
void for_each_coupling_particle(const Stencils& st, std::size_t np, const PatchBand* band, Body&& body) {
  if (band && st.order.built_for(np)) {
    for_each_scatter_particle(st.order, np, body, std::numeric_limits<std::size_t>::max());
    return;
  }
  for (std::size_t i = 0; i < np; ++i) body(i);
}

// The patch tag of a particle at x (PatchBand::tag; -1: an interior particle
// or no band): its terms at band nodes go to the partials of its patch.
inline int coupling_tag(const PatchBand* band, const Vec3& x) { return band ? band->tag(x) : -1; }

// The band of a scatter that writes only the nodes of each particle's own
// stencil (T_g, the pressure force, the burn's unfolded node masses), with
// the node-box answers of st's per-axis size prepared (serial code).
inline PatchBand* stencil_coupling_band(PatchBand* band, const Stencils& st) {
  if (band) band->boxes(st.axis_nodes);
  return band;
}

// The tag of particle i for such a scatter: MPM's band_tag (mpm/BandTag.h:
// -1 without tag()'s divisions when its stencil's node box holds no band
// node; it then writes every node directly on either path, the same bits).
// Not for the burn's cell shares, which go to a node below the stencil.
template <class View>
int stencil_coupling_tag(const PatchBand* band, const View& view, std::size_t i, const Vec3& x) {
  return band ? band_tag(*band, view, i, x) : -1;
}

// Where a term of a particle with tag P at node gi goes: column `col` of the
// partial (band node of gi, P) when gi is a band node, else `direct` (the
// node array's entry).
inline double* band_target(PatchBand* band, int P, std::size_t gi, int col, double* direct) {
  if (P >= 0) {
    const int k = band->slot(gi);
    if (k >= 0) return band->partial(k, P) + col;
  }
  return direct;
}

}  // namespace tephra
