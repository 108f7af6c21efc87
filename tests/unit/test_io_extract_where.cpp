// extract at a point and along a line. Oracle: the sample frame of
// tests/unit/test_io_sample.h, whose values are closed-form functions of
// (i,j,k), on the grid lower = (-1, 0.5, 2), dx = (0.25, 0.5, 0.125),
// cells = (3, 2, 4): the cell holding x is floor((x - lower)/dx).
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>

#include "core/base/Errors.h"
#include "core/io/Extract.h"
#include "core/io/OutputWriter.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;

namespace {

const Grid& grid() {
  static const Grid g = test::sample_grid();
  return g;
}

std::string run_dir() {
  static const std::string dir = [] {
    // One folder per test: ctest runs each test in its own process, in
    // parallel, and scratch_dir() empties the folder it returns.
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string d = test::scratch_dir(std::string("io_extract_where_") + (info ? info->name() : "main"));
    OutputWriter w(d, false);
    w.write_frame(test::sample_frame(grid(), 0));
    w.append_reductions(0.0, {{"KineticEnergy", {1.0}}});
    return d;
  }();
  return dir;
}

std::vector<std::string> lines(const ExtractRequest& r) {
  std::ostringstream out;
  extract_csv(r, out);
  std::vector<std::string> v;
  std::istringstream in(out.str());
  for (std::string l; std::getline(in, l);) v.push_back(l);
  return v;
}

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

}  // namespace

TEST(IoExtractWhere, PointSelectsTheCellHoldingIt) {
  ExtractRequest r;
  r.dir = run_dir();
  r.label = "press_CC";
  r.material = 0;
  // x = (-0.6, 1.2, 2.3): i = floor(0.4/0.25) = 1, j = floor(0.7/0.5) = 1, k = floor(0.3/0.125) = 2.
  r.point = Vec3(-0.6, 1.2, 2.3);
  auto v = lines(r);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1].substr(0, v[1].find(",-")), "0,1,1,2");
  EXPECT_NE(v[1].find(num(test::press(1, 1, 2, 0))), std::string::npos) << v[1];
}

TEST(IoExtractWhere, LineVisitsEveryCellItCrossesInOrder) {
  ExtractRequest r;
  r.dir = run_dir();
  r.label = "press_CC";
  r.material = 0;
  // Along x through the centres of cells (i, 0, 0), i = 0..2, and beyond the domain.
  const Vec3 a(-1.0 + 0.125, 0.75, 2.0625), b(0.5, 0.75, 2.0625);
  r.line = std::make_pair(a, b);
  auto v = lines(r);
  ASSERT_EQ(v.size(), 4u);  // header + 3 cells; points outside the grid are skipped
  for (int i = 0; i < 3; ++i)
    EXPECT_EQ(v[1 + i].substr(0, 8), "0," + std::to_string(i) + ",0,0,") << v[1 + i];
}

TEST(IoExtractWhere, PointOnParticlesPicksTheNearest) {
  ExtractRequest r;
  r.dir = run_dir();
  r.label = "p.mass";
  r.material = 0;
  r.point = test::ppos(3) + Vec3(0.01, 0, 0);  // nearest is particle 3 (id 1003)
  auto v = lines(r);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1].substr(0, 7), "0,1003,") << v[1];
  EXPECT_NE(v[1].find(num(test::pmass(3))), std::string::npos) << v[1];
}

TEST(IoExtractWhere, ReductionsRejectPointAndLine) {
  ExtractRequest r;
  r.dir = run_dir();
  r.label = "KineticEnergy";
  r.point = Vec3::Zero();
  std::ostringstream out;
  EXPECT_THROW(extract_csv(r, out), UsageError);
}
