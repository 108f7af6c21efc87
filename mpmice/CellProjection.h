#pragma once
// Node -> cell weights of the coupled step's projection of a solid to the
// cells (Vaango theory manual sec. 26.1.3 step 1; MpmIceTransfers.cpp): a
// cell's value is the weighted sum of its 8 corner nodes with weight 1/8,
// doubled per symmetry plane the node lies on (the plane's mirror particles
// give the node as much again).
#include <array>
#include <cmath>

#include "core/grid/Grid.h"
#include "mpm/GridBoundaryConditions.h"
#include "mpm/NodeGrid.h"
#include "mpmice/AxisymmetricShare.h"

namespace tephra {

// The node index offset of cell c's lower corner: node = c + offset.
inline IntVec3 node_offset(const Grid& g, const NodeGrid& ng) {
  IntVec3 o;
  for (int d = 0; d < 3; ++d) o[d] = int(std::lround((g.lower[d] - ng.origin[d]) / ng.h[d]));
  return o;
}

// Which of the six faces (x-, x+, y-, ...) are symmetry planes for the solid.
inline std::array<bool, 6> symmetry_faces(const GridBoundaryConditions& bcs) {
  std::array<bool, 6> s{};
  for (int fc = 0; fc < 6; ++fc) s[fc] = bcs.face[fc].kind == FaceVelocityBC::Kind::Symmetry;
  return s;
}

// The weight of node `node` in the value of a cell it bounds: 1/8 x 2 per
// symmetry plane through the node. `on_plane[d]` (if given) is set when the
// node lies on a symmetry plane normal to d.
inline double node_cell_weight(const NodeGrid& ng, const std::array<bool, 6>& symmetric, const IntVec3& node,
                               bool* on_plane = nullptr) {
  double w = 0.125;
  for (int d = 0; d < 3; ++d) {
    const bool on = (symmetric[2 * d] && node[d] == ng.extra[d]) ||
                    (symmetric[2 * d + 1] && node[d] == ng.n[d] - 1 - ng.extra[d]);
    if (on) w *= 2;
    if (on_plane) on_plane[d] = on;
  }
  return w;
}

// Axisymmetric runs (x = r, per-radian masses; ice/RadialWeights.h): along
// r a node's mass is split between its two cells by where it came from,
//   share_above = m_g^+ / m_g,  m_g^+ = sum_p a_pg m_p S_gp,
// a_pg = 1 for r_p >= r_g, 0 below, except where the particle's domain
// straddles the node (session 24: then the overlap share of
// mpmice/AxisymmetricShare.h, continuous in r_p),
// and the cell below gets 1 - share_above (y and z keep the Cartesian 1/2
// per node and the symmetry doubling). By the partition of unity in r, a
// particle's mass then lands in the r-range of the cell that holds it (the
// y, z smoothing unchanged), so M_c / (r_c dx dy) is the solid's density for
// a uniform distribution: the particles' mass A_p sum r_p is exact for the
// midpoint-placed particles, while the Cartesian 1/8 rule gives cell 0 on the
// axis 1.75 rho (2 ppc: nodes 3/16 h^2 x 2 and h^2 x 1/2 for r_0 h = h^2/2) and
// the exact-integral split 1/2 +- h/(6 r_g) 1.042 rho (its 4 % excess is the
// particles' midpoint rule on the quadratic N r near the axis; the
// axisymmetric quiescent block then rises to 47 MPa).
// w: node_cell_weight (x part 1/2, or 1 on an x symmetry plane); share: the
// share of the node's mass on the cell's side of the node.
inline double axisymmetric_node_cell_weight(double w, bool on_x_plane, double share) {
  return (on_x_plane ? w : 2.0 * w) * share;
}

// m_above[g] = sum_p a_pg m_p S_gp, a_pg the particle's share above node g
// (axisymmetric_share_above, mpmice/AxisymmetricShare.h: 1 or 0 by the side
// of r_g the particle lies on, the overlap of its domain where the domain
// straddles the node): the m_g^+ above, over the nodes of ng. `scatter(fn)`
// calls fn(particle, node gi, S_gp) for every stencil entry; psize: the
// particles' domains in cells (half-length 0.5 psize_xx along r).
template <class Scatter>
void node_mass_above(const NodeGrid& ng, InterpolatorKind kind, const std::vector<double>& mass,
                     const std::vector<Vec3>& x, const std::vector<Mat3>& psize, Scatter&& scatter,
                     std::vector<double>& m_above) {
  m_above.assign(ng.count(), 0.0);
  const std::size_t nx = std::size_t(ng.n[0]);
  scatter([&](std::size_t p, std::size_t gi, double S) {
    const double r_g = ng.origin[0] + double(gi % nx) * ng.h[0];
    m_above[gi] += axisymmetric_share_above(kind, (x[p][0] - r_g) / ng.h[0], 0.5 * psize[p](0, 0)) * (mass[p] * S);
  });
}

}  // namespace tephra
