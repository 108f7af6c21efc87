#pragma once
// ICE decks in (r, z) for the axisymmetric verification tests (x = r, y = z,
// one cell in the third direction): an ideal gas (gamma 1.4, cv 717.5) with a
// uniform background state and an optional second state in the box
// x < x_split, y < y_split (a cylinder r < x_split of height y_split).
#include <string>

namespace tephra::test {

struct AxisymDeck {
  bool axisymmetric = true;
  int nr = 16, nz = 8;
  double r_lo = 0, r_hi = 1, z_hi = 1;
  bool periodic_z = false;        // periodic along y (z); else Symmetric walls
  std::string advection = "SecondOrder";
  double cfl = 0.25;
  double max_time = 1e-3;
  double rho = 1.1768292682926831, temp = 300, u_r = 0, u_z = 0;  // background
  bool inner = false;             // the second state inside x < x_split, y < y_split
  double x_split = 0.5, y_split = 1e9;
  double rho_in = 1.1768292682926831, temp_in = 300, u_z_in = 0;
  std::string x_plus = "Symmetric";  // "Symmetric" (wall) or "Neumann" (outflow)
  std::string x_minus = "Symmetric"; // the axis face (tests of the deck check: "Neumann")
};

// The deck text (a Uintah_specification with <MPM><axisymmetric> when axisymmetric).
std::string axisym_deck_text(const AxisymDeck& d);

}  // namespace tephra::test
