#include "mpm/thermal/TemperatureBoundary.h"

namespace tephra {

namespace {

// fn(node index, face temperature) for every node of every Dirichlet face.
template <class Fn>
void for_each_face_node(const GridBoundaryConditions& bcs, const NodeGrid& g, Fn&& fn) {
  for (int f = 0; f < 6; ++f) {
    if (!bcs.temperature[f]) continue;
    const double value = *bcs.temperature[f];
    const int d = f / 2, a = (d + 1) % 3, b = (d + 2) % 3;
    const int face_plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
    const int outward = (f % 2 == 0) ? -1 : 1;
    const int layers = bcs.set_extra_nodes ? g.extra[d] : 0;
    for (int k = 0; k <= layers; ++k) {
      IntVec3 c;
      c[d] = face_plane + outward * k;
      // The face plane over the domain's nodes; the extra layers over all nodes.
      const int lo_a = k == 0 ? g.extra[a] : 0, hi_a = k == 0 ? g.n[a] - g.extra[a] : g.n[a];
      const int lo_b = k == 0 ? g.extra[b] : 0, hi_b = k == 0 ? g.n[b] - g.extra[b] : g.n[b];
      for (c[b] = lo_b; c[b] < hi_b; ++c[b])
        for (c[a] = lo_a; c[a] < hi_a; ++c[a]) fn(g.index(c), value);
    }
  }
}

}  // namespace

bool has_temperature_bcs(const GridBoundaryConditions& bcs) {
  for (const auto& t : bcs.temperature)
    if (t) return true;
  return false;
}

void apply_temperature_bcs(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& T) {
  for_each_face_node(bcs, g, [&](std::size_t i, double value) { T[i] = value; });
}

void hold_temperature_faces(const GridBoundaryConditions& bcs, const NodeGrid& g, std::vector<double>& rate) {
  for_each_face_node(bcs, g, [&](std::size_t i, double) { rate[i] = 0.0; });
}

}  // namespace tephra
