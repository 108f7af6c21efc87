#pragma once
// The contact normal of a disk in a block against the exact radius
// (tests/unit/test_mpm_contact_normals.cpp, tests/bench/bench_disk_normals.cpp).
//
// Scene: unit square in x-y, one cell thick in z (symmetry faces z- and z+),
// `cells` x `cells` cells, h = 1/cells; material 0 the disk of radius
// R = 0.25 about (0.5, 0.5), material 1 the rest of the square, both
// rho = 1000, `res` x `res` x 2 particles per cell (Vaango's fill: a particle
// belongs to the disk when its centre is inside: a staircase of spacing h/res).
// After one step of 1e-12 s (the stencils of the step) the body-averaged
// (collinear) mass-gradient normals at the nodes where both bodies have mass
// are compared with the radial direction (x_g - c)/|x_g - c|, in plane.
#include <string>

namespace tephra {

struct DiskNormalError {
  int nodes = 0;         // nodes where both bodies have mass
  double mean = 0.0;     // angle [rad] to the radius, mean weighted by min(m_disk, m_block)
  double largest = 0.0;  // largest angle [rad]
  // The normal averaged over arcs of fixed length: the weighted sum of the
  // unit normals of the nodes in each of 16 sectors of the circle against
  // the same sum of the exact radial unit vectors; mean angle over sectors.
  double arc_mean = 0.0;
};

DiskNormalError disk_normal_error(int cells, int res, const std::string& interpolator = "linear");

}  // namespace tephra
