#pragma once
// Runs the AxisAligned manufactured solution (shared/decks/inputs/MPM/AA.ups)
// in-process with a chosen interpolator, cells per side, particles per cell
// direction and end time, with the deck's time-step rule (timestep_multiplier
// x stable dt, capped by delt_max, last step landing on end_time) or another
// multiplier, and returns the L2 displacement error at the end and the wall
// time. Used by tests/verification/test_mpm_mms.cpp and
// tests/bench/bench_mms_work_precision.cpp.
#include <string>
#include <vector>

#include "core/base/Types.h"

namespace tephra::test {

struct MmsRunOptions {
  // Another manufactured-solution deck (absolute path), with the same
  // elements as AA.ups; empty: AA.ups. `planar`: one cell and one particle
  // in z (resolution [cells, cells, 1], res [ppc, ppc, 1]), for the
  // plane-strain decks such as inputs/mpm/expanding_ring_mms.ups.
  std::string deck;
  bool planar = false;
  std::string interpolator = "gimp";
  int cells = 16;               // cells per side of the unit cube
  double end_time = 0.02;       // the deck's maxTime
  int particles_per_cell_dir = 2;  // the deck's res [2,2,2]
  double timestep_multiplier = 0.0;  // 0: the deck's (0.2)
  // planar decks: make the z cell as thick as an x cell (the deck's upper z
  // set to (upper x - lower x) / cells), so that the cells stay cubes.
  bool cubic_z = false;
  // Ring decks (inputs/mpm/expanding_ring_mms.ups): the rms displacement
  // error of the particles by their distance (in x cells) to the curved
  // faces R = ring_inner, ring_outer: [0,1), [1,2), [2,3), >= 3 cells.
  double ring_inner = 0.0, ring_outer = 0.0;
  // Ring decks: replace the deck's seeding (particles on the grid-aligned
  // lattice inside the ring, a staircase along the curved faces) by one
  // conforming to the faces: n_r = (ring_outer - ring_inner) / delta layers
  // in R, delta = h / ppc, and in each layer round((pi/2) R_i / delta)
  // sectors in theta over the quarter ring; each particle an annular sector
  // of volume R_i dR dtheta h_z (so the particles fill the quarter ring
  // exactly, R = ring_inner and ring_outer are particle faces) with the
  // CPDI domain spanned by dR e_R and R_i dtheta e_theta (same volume).
  bool conforming_ring = false;
  // AxisAligned only: the mirror-extended problem without boundaries. The
  // body and grid become [-1, 1]^3, periodic in all directions (no extra
  // cells, no BCs), with 2 cells per cell of the unit cube: u_i = A sin(pi X_i)
  // is odd about X_i = 0 and 1, so this is the problem the symmetry faces
  // stand for, with no face at all.
  bool periodic_mirror = false;
  // AxisAligned only: the amplitude A [m] of u_i = A sin(pi X_i) sin(...);
  // 0: Vaango's 0.05 (the deck). |F_ii - 1| <= A pi.
  double amplitude = 0.0;
  // Fill MmsRunResult::particle_errors (u_p - u(X_p, t) at the end, by particle id).
  bool keep_particle_errors = false;
};

struct MmsRunResult {
  double error = 0.0;    // MMSDisplacementErrorL2 at end_time
  double seconds = 0.0;  // wall time of initialize + steps
  long particles = 0;
  int steps = 0;
  double band_rms[4] = {0, 0, 0, 0};  // with ring_outer > 0: see MmsRunOptions
  long band_count[4] = {0, 0, 0, 0};
  double volume0 = 0.0;  // sum of the particles' reference volumes V0 [m^3]
  // With MmsRunOptions::keep_particle_errors: the end error u_p - u(X_p, t)
  // and the reference position X_p = x_p - u_p, indexed by particle id (the
  // seeding gives ids 0..n-1 in the same order for every amplitude and
  // interpolator, so two runs' errors can be subtracted particle by particle).
  std::vector<Vec3> particle_errors, particle_X;
};

MmsRunResult run_axis_aligned(const MmsRunOptions& options);

}  // namespace tephra::test
