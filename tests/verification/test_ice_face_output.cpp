// Face-centred ICE labels (uvel_FC, vvel_FC, wvel_FC and the _FCME forms)
// written and read back through the executable on advect.ups (decks A10:
// uniform air at (1, 1, 1) m/s in a 5^3 box of 1 m cells, Neumann BCs). The
// face velocity of a uniform state is exactly the cell velocity (eq. 26.1:
// equal densities, no pressure gradient), so every saved face value is 1 to
// round-off; the faces normal to d number cells + 1 along d, and extract
// places face (i, j, k) normal to x at x = i dx, y = (j + 1/2) dy, z = (k + 1/2) dz.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

TEST(IceFaceOutput, FaceVelocitiesOfAUniformFlowAreWrittenOnTheFaces) {
  const std::string dir = test::scratch_dir("ice_face_output");
  std::string out;
  ASSERT_EQ(test::run_tephra(test::shared_dir() + "/decks/inputs/ICE/advect.ups --quiet --threads 1 --output " + dir,
                             &out), 0) << out;
  const char* labels[6] = {"uvel_FC", "vvel_FC", "wvel_FC", "uvel_FCME", "vvel_FCME", "wvel_FCME"};
  for (int l = 0; l < 6; ++l) {
    const int d = l % 3;
    std::string csv;
    ASSERT_EQ(test::run_tephra("extract " + dir + " --var " + labels[l] + " --step last", &csv), 0) << csv;
    std::istringstream in(csv);
    std::string line;
    std::getline(in, line);  // header
    int rows = 0;
    double worst_value = 0, worst_position = 0;
    while (std::getline(in, line)) {
      std::vector<double> v;
      std::stringstream ls(line);
      for (std::string item; std::getline(ls, item, ',');) v.push_back(std::stod(item));
      ASSERT_EQ(v.size(), 8u) << line;
      ++rows;
      worst_value = std::max(worst_value, std::abs(v[7] - 1.0));
      for (int a = 0; a < 3; ++a) {
        const double expected = v[1 + a] + (a == d ? 0.0 : 0.5);  // dx = 1
        worst_position = std::max(worst_position, std::abs(v[4 + a] - expected));
      }
    }
    EXPECT_EQ(rows, 6 * 5 * 5) << labels[l];
    EXPECT_LT(worst_value, 1e-12) << labels[l];
    EXPECT_LT(worst_position, 1e-12) << labels[l];
  }
}

}  // namespace
}  // namespace tephra
