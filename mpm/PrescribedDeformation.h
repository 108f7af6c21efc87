#pragma once
// <MPM><use_prescribed_deformation>true + <prescribed_deformation_file>:
// every particle's deformation gradient follows a prescribed history F*(t),
// whatever the stresses (Vaango's SerialMPM::setPrescribedMotion). This is
// the material-point driver: one cell of particles taken through any
// deformation path by the real MPM step (the constitutive model sees F_n,
// F_{n+1}, l exactly as in a run).
//
// The file (Vaango's format): one row per time, whitespace separated,
//   t  F11 F12 F13 F21 F22 F23 F31 F32 F33  theta  a1 a2 a3
// t strictly increasing, at least two rows; theta [degrees] and the axis a
// give a rigid rotation superposed over the segment that ENDS at this row
// (so the first row's theta must be 0). F* is
//   F*(t) = Q_s(t) P_s U(t),   t_s <= t <= t_{s+1},
//   U(t)   = F_s + (t - t_s)/(t_{s+1} - t_s) (F_{s+1} - F_s)   (rows' F, linear)
//   Q_s(t) = R(theta_{s+1} (t - t_s)/(t_{s+1} - t_s), a_{s+1})  (Rodrigues:
//            R(th, a) = cos th (I - a a) + sin th [a]_x + a a, a normalised)
//   P_s    = R(theta_s, a_s) ... R(theta_1, a_1)               (the completed rotations)
// and F*(t) is held after the last row (before the first: the first row).
// Particles start with F = I, so a file should start with F = I at t_0.
//
// How F follows: after the grid boundary conditions of a step [t, t + dt],
// every node gets v*_g = l x_g with the discrete velocity gradient
//   l = (F*(t + dt) F*(t)^{-1} - I) / dt,
// x_g the node position (the map is homogeneous about the origin). A linear
// velocity field is reproduced exactly by every interpolator (sum_g x_g
// grad S_gp^T = I), so each particle gets l_p = l and the first-order update
// F_{n+1} = (I + dt l) F_n = F*(t+dt) F*(t)^{-1} F_n follows F* to round-off,
// and x_{n+1} = F*(t+dt) F*(t)^{-1} x_n. Vaango sets v*_g = Fdot* F*^{-1} x_g
// with the rates at t (a first-order error in F); with <exact_deformation>
// it uses the same increment as here. Tephra always takes the exact
// increment, so <exact_deformation> is accepted with either value.
// The other <deformation_gradient> algorithms (series of exp(dt l)) would need
// l = log(F*(t+dt) F*(t)^{-1})/dt: a MissingFeature with a prescribed history.
#include <iosfwd>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"

namespace tephra {

class DeckNode;

struct PrescribedRow {
  double t = 0.0;
  Mat3 F = Mat3::Identity();
  double angle_deg = 0.0;      // rotation over the segment ending at this row
  Vec3 axis = Vec3::UnitZ();   // its axis (normalised when read)
};

struct PrescribedDeformation {
  std::vector<PrescribedRow> rows;

  // F*(t), the formula above.
  Mat3 at(double t) const;
  // l = (F*(t + dt) F*(t)^{-1} - I) / dt.
  Mat3 step_velocity_gradient(double t, double dt) const;
};

// Parses the rows of `in`; `name` (the file) is used in errors, which are
// DeckError at name:line (bad or missing numbers, times not increasing, a
// zero axis with a nonzero angle, a nonzero first angle, fewer than two rows).
PrescribedDeformation parse_prescribed_deformation(std::istream& in, const std::string& name);

// Reads <prescribed_deformation_file> of <MPM> (`file_node`): the path is
// taken relative to the deck file's folder, then to the working directory.
PrescribedDeformation read_prescribed_deformation(const DeckNode& file_node);

// v*_g = l x_g on every node, a_g = (v*_g - v_g)/dt.
void set_prescribed_grid_velocity(const Mat3& l, double dt, NodeGrid& g);

}  // namespace tephra
