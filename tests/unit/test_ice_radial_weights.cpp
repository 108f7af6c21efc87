// Radial weights of axisymmetric ICE (ice/RadialWeights.h) against their
// closed forms, and the conservation identity of the weighted divergence:
//   lo_i = r_{i-1/2}/r_i, hi_i = r_{i+1/2}/r_i, hi_i - lo_i = dr/r_i,
//   sum_i r_i dq_i = r_{-1/2} F_{-1/2} - r_{N-1/2} F_{N-1/2} + (z boundary terms)
// for any face fluxes F (the r-face terms telescope), with flux_divergence.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "ice/IceAdvection.h"
#include "ice/RadialWeights.h"

namespace tephra {
namespace {

Grid grid(double r_lo, int nr, int nz) {
  std::ostringstream x;
  x.precision(17);
  x << "<Uintah_specification><Grid><Level><Box label=\"1\"><lower>[" << r_lo << ",0,0]</lower><upper>["
    << r_lo + 1.0 << ",1,0.1]</upper><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches><resolution>[" << nr
    << "," << nz << ",1]</resolution></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(x.str(), "grid.ups", ".");
  return make_grid(deck->root.require_child("Grid"));
}

TEST(IceRadialWeights, ClosedFormsOnTheAxisAndOnAnAnnulus) {
  for (double r_lo : {0.0, 0.3}) {
    const Grid g = grid(r_lo, 10, 1);
    const RadialWeights w = make_radial_weights(g);
    const double dr = g.dx[0];
    for (int i = 0; i < g.cells[0]; ++i) {
      const double rc = r_lo + (i + 0.5) * dr;
      EXPECT_DOUBLE_EQ(*w.r_row(i), rc);
      EXPECT_DOUBLE_EQ(*w.lo_row(i), (r_lo + i * dr) / rc);
      EXPECT_DOUBLE_EQ(*w.hi_row(i), (r_lo + (i + 1) * dr) / rc);
      EXPECT_NEAR(*w.hi_row(i) - *w.lo_row(i), dr / rc, 1e-15 * (1 + dr / rc));  // the hoop term's dr
      EXPECT_NEAR(*w.hi_row(i) + *w.lo_row(i), 2.0, 1e-15);                     // r_{i+-1/2} = r_i +- dr/2
    }
    if (r_lo == 0.0) {
      EXPECT_EQ(*w.lo_row(0), 0.0);  // the axis face has zero area
      EXPECT_EQ(*w.hi_row(0), 2.0);  // r_{1/2}/r_0 = dr/(dr/2)
      EXPECT_EQ(*w.lo_row(-1), 1.0); // an extra cell beyond the axis (r < 0) is not weighted
    }
  }
}

TEST(IceRadialWeights, WeightedDivergenceTelescopes) {
  const Grid g = grid(0.2, 12, 5);
  const RadialWeights w = make_radial_weights(g);
  FaceScalars F(g, 0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> U(-1, 1);
  for (int d = 0; d < 3; ++d) {
    GridArray<double>& a = F.at(d, 0);
    for (std::size_t c = 0; c < a.size(); ++c) a.data()[c] = d == 2 ? 0.0 : U(rng);
  }
  CellScalars dq(g, 0);
  flux_divergence(g, F, dq, &w);
  double sum = 0, boundary = 0;
  const double dr = g.dx[0];
  for (int j = 0; j < g.cells[1]; ++j) {
    for (int i = 0; i < g.cells[0]; ++i) sum += (0.2 + (i + 0.5) * dr) * dq[0](i, j, 0);
    boundary += 0.2 * F.x[0](0, j, 0) - (0.2 + g.cells[0] * dr) * F.x[0](g.cells[0], j, 0);
  }
  for (int i = 0; i < g.cells[0]; ++i)
    boundary += (0.2 + (i + 0.5) * dr) * (F.y[0](i, 0, 0) - F.y[0](i, g.cells[1], 0));
  EXPECT_NEAR(sum, boundary, 1e-13);
  // Without the weights the sum r_i dq_i does not telescope.
  CellScalars plain(g, 0);
  flux_divergence(g, F, plain);
  double plain_sum = 0;
  for (int j = 0; j < g.cells[1]; ++j)
    for (int i = 0; i < g.cells[0]; ++i) plain_sum += (0.2 + (i + 0.5) * dr) * plain[0](i, j, 0);
  EXPECT_GT(std::abs(plain_sum - boundary), 1e-3);
}

}  // namespace
}  // namespace tephra
