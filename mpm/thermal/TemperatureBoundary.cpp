#include "mpm/thermal/TemperatureBoundary.h"

namespace tephra {

namespace {

// fn(node index, face temperature, face f, face-plane node index) for every node of every Dirichlet face.
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
        for (c[a] = lo_a; c[a] < hi_a; ++c[a]) {
          IntVec3 on_face = c;
          on_face[d] = face_plane;
          fn(g.index(c), value, f, on_face);
        }
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
  for_each_face_node(bcs, g, [&](std::size_t i, double value, int, const IntVec3&) { T[i] = value; });
}

void face_temperature_rates(const GridBoundaryConditions& bcs, const NodeGrid& g, const std::vector<double>& T,
                            const std::vector<double>& T_free, const std::vector<Vec3>& xbar, double dt,
                            std::vector<double>& rate) {
  for_each_face_node(bcs, g, [&](std::size_t i, double T_bc, int f, const IntVec3& on_face) {
    if (!(g.mass[i] > 0.0)) return;
    const int d = f / 2, inward = (f % 2 == 0) ? 1 : -1;
    IntVec3 in = on_face;
    in[d] += inward;
    const double x_face = g.origin[d] + on_face[d] * g.h[d];
    // dT/dx_d from the face to the first interior node; the centroid offset along d.
    const double slope = (T[g.index(in)] - T_bc) / (inward * g.h[d]);
    const double expected = T_bc + slope * (xbar[i][d] - x_face);
    rate[i] = (expected - T_free[i]) / dt;
  });
}

}  // namespace tephra
