#pragma once
// A block on a held slab under gravity, with frictional contact between the
// two (tests/verification/test_mpm_friction_coulomb.cpp and
// tests/bench/bench_friction_slide.cpp).
//
// Scene (plane strain in x-z: one cell in y with symmetry faces on y- and
// y+), cell size h = 0.025 / refine:
//   slab  (material 0): x in [0, 0.4], z in [0, 0.025], rho = 1e4,
//         K = 1e8, G = 5e7, held by zero velocity on the z- face nodes;
//   block (material 1): x in [x0, x0 + 0.1], z in [0.025, 0.075], rho = 1e3,
//         K = 1e7, G = 5e6, initial velocity (u0, 0, 0);
//   gravity g (sin theta, 0, -cos theta), g = 10: the slab's surface is the
//   plane z = 0.025 of an incline of angle theta; 2x2x2 particles per cell.
// The block is a rigid body on average: its mass-weighted velocity u(t)
// along x obeys M du/dt = M g sin(theta) - F_t, and Coulomb's law with the
// normal force N = M g cos(theta) gives, while it slides towards +x (u > 0),
//   F_t = mu N:  du/dt = g (sin(theta) - mu cos(theta))   (flat: -mu g),
// and from rest it sticks (u = 0) when mu >= tan(theta).
#include <string>
#include <vector>

namespace tephra {

struct FrictionScene {
  std::string contact = "friction";    // <contact><type>
  double mu = 0.3;
  double theta = 0.0;                  // incline angle [rad]
  double u0 = 0.0;                     // block's initial velocity along x [m/s]
  int refine = 1;                      // h = 0.025 / refine
  std::string interpolator = "linear";
  int extra_cells = 0;                 // <extraCells> in every direction (gimp, B-splines)
  bool heating = false;                // <do_contact_friction_heating>
  double end_time = 0.05;
};

struct FrictionRun {
  std::vector<double> t, u, w;  // time, block's mean x and z velocity after each step
  double mass = 0.0;            // block mass [kg]
  double distance = 0.0;        // block's mass-weighted x displacement [m]
  double heat = 0.0;            // thermal energy gained, both bodies [J]
  double ke_lost = 0.0;         // block's kinetic energy lost [J]
  // Least-squares slope of u(t) over t >= t_from (the block's deceleration or
  // acceleration, averaged over the elastic bounce of the normal force).
  double slope(double t_from = 0.0) const;
};

constexpr double kFrictionSceneG = 10.0;

FrictionRun run_friction_scene(const FrictionScene& s);

}  // namespace tephra
