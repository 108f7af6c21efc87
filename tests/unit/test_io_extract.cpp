// extract_csv: headers and values for cell/node/particle/reduction labels,
// scalar/vector/tensor columns, step/time/all-times selection and errors.
// Oracle: the closed-form values of tests/unit/test_io_sample.h, printed with
// %.17g, and the positions x = lower + (i + 1/2) dx (cells), lower + i dx
// (nodes) of Grid.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "core/base/Errors.h"
#include "core/io/Extract.h"
#include "core/io/OutputWriter.h"
#include "tests/support/TestPaths.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;
using When = ExtractRequest::When;

namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

// Momentum reduction at time t: (t, 2t, -t); kinetic energy 0.5 + t.
double ke(double t) { return 0.5 + t; }

const Grid& grid() {
  static const Grid g = test::sample_grid();
  return g;
}

// A run with frames at steps 0, 10, 20 (time = step * 1e-3) and reductions
// at the same times.
std::string run_dir() {
  static const std::string dir = [] {
    // One folder per test case: ctest may run the cases as parallel processes.
    std::string d = test::scratch_dir(
        std::string("io_extract_") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    OutputWriter w(d, false);
    for (int s : {0, 10, 20}) {
      w.write_frame(test::sample_frame(grid(), s));
      const double t = s * 1e-3;
      w.append_reductions(t, {{"KineticEnergy", {ke(t)}}, {"TotalMomentum", {t, 2 * t, -t}}});
    }
    return d;
  }();
  return dir;
}

std::vector<std::vector<std::string>> csv(const ExtractRequest& r) {
  std::ostringstream out;
  extract_csv(r, out);
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::istringstream l(line);
    for (std::string c; std::getline(l, c, ',');) cells.push_back(c);
    rows.push_back(cells);
  }
  return rows;
}

ExtractRequest request(const std::string& label, std::optional<int> material = std::nullopt,
                       When when = When::Last) {
  ExtractRequest r;
  r.dir = run_dir();
  r.label = label;
  r.material = material;
  r.when = when;
  return r;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> v;
  std::istringstream l(s);
  for (std::string c; std::getline(l, c, ',');) v.push_back(c);
  return v;
}

// The expected row prefix of a cell or node (i,j,k) at `time`.
std::vector<std::string> grid_prefix(double time, int i, int j, int k, bool node) {
  const Vec3 x = node ? grid().node_position(i, j, k) : grid().cell_center(i, j, k);
  return {num(time), std::to_string(i), std::to_string(j), std::to_string(k),
          num(x[0]), num(x[1]), num(x[2])};
}

std::vector<std::string> concat(std::vector<std::string> a, const std::vector<std::string>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

std::string usage_error(const ExtractRequest& r) {
  try {
    std::ostringstream out;
    extract_csv(r, out);
  } catch (const UsageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "expected a UsageError for " << r.label;
  return "";
}

}  // namespace

TEST(IoExtract, CellScalarLastFrame) {
  auto rows = csv(request("press_CC", 0));
  ASSERT_EQ(rows.size(), 1u + 24u);  // header + 3*2*4 cells
  EXPECT_EQ(rows[0], split("time,i,j,k,x,y,z,press_CC"));
  // Rows run i fastest: (i,j,k) = (2,1,3) is row 1 + 2 + 3*(1 + 2*3).
  EXPECT_EQ(rows[1 + 2 + 3 * (1 + 2 * 3)],
            concat(grid_prefix(20e-3, 2, 1, 3, false), {num(test::press(2, 1, 3, 20))}));
}

TEST(IoExtract, MaterialColumnWhenSeveralMaterials) {
  auto rows = csv(request("press_CC"));
  ASSERT_EQ(rows.size(), 1u + 48u);
  EXPECT_EQ(rows[0], split("time,material,i,j,k,x,y,z,press_CC"));
  // Material 1 holds -press: its first row is cell (0,0,0).
  auto expect = grid_prefix(20e-3, 0, 0, 0, false);
  expect.insert(expect.begin() + 1, "1");
  expect.push_back(num(-test::press(0, 0, 0, 20)));
  EXPECT_EQ(rows[1 + 24], expect);
}

TEST(IoExtract, CellVectorNodeScalarAndExtraCells) {
  auto v = csv(request("vel_CC"));
  EXPECT_EQ(v[0], split("time,i,j,k,x,y,z,vel_CC_x,vel_CC_y,vel_CC_z"));
  EXPECT_EQ(v[1 + 1 + 3 * (0 + 2 * 2)],
            concat(grid_prefix(20e-3, 1, 0, 2, false),
                   {num(test::vel(1, 0, 2, 0)), num(test::vel(1, 0, 2, 1)), num(test::vel(1, 0, 2, 2))}));

  auto m = csv(request("g.mass"));
  ASSERT_EQ(m.size(), 1u + 4 * 3 * 5);  // nodes 0..cells
  EXPECT_EQ(m[0], split("time,i,j,k,x,y,z,g.mass"));
  EXPECT_EQ(m.back(), concat(grid_prefix(20e-3, 3, 2, 4, true), {num(test::gmass(3, 2, 4))}));

  auto t = csv(request("temp_CC"));
  ASSERT_EQ(t.size(), 1u + 5 * 4 * 6);  // interior + one extra cell per side
  EXPECT_EQ(t[1], concat(grid_prefix(20e-3, -1, -1, -1, false), {num(test::temp(-1, -1, -1))}));
  EXPECT_EQ(t.back(), concat(grid_prefix(20e-3, 3, 2, 4, false), {num(test::temp(3, 2, 4))}));
}

TEST(IoExtract, ParticleTensorScalarAndPosition) {
  auto s = csv(request("p.stress", 0));
  ASSERT_EQ(s.size(), 1u + 5);
  EXPECT_EQ(s[0], split("time,particle_id,x,y,z,p.stress_xx,p.stress_xy,p.stress_xz,p.stress_yx,"
                        "p.stress_yy,p.stress_yz,p.stress_zx,p.stress_zy,p.stress_zz"));
  const int q = 3;
  std::vector<std::string> row = {num(20e-3), std::to_string(1000 + q), num(test::ppos(q)[0]),
                                  num(test::ppos(q)[1]), num(test::ppos(q)[2])};
  for (int c = 0; c < 9; ++c) row.push_back(num(test::pstress(q, c)));
  EXPECT_EQ(s[1 + q], row);

  auto m = csv(request("p.mass"));  // materials 0 (5), 1 (2), 2 (0 particles)
  ASSERT_EQ(m.size(), 1u + 7);
  EXPECT_EQ(m[0], split("time,material,particle_id,x,y,z,p.mass"));
  EXPECT_EQ(m[6], split(num(20e-3) + ",1,2000,0,0,0,7"));

  auto x = csv(request("p.x", 1));
  EXPECT_EQ(x[0], split("time,particle_id,x,y,z,p.x_x,p.x_y,p.x_z"));
  EXPECT_EQ(x[2], split(num(20e-3) + ",2001,1,1,1,1,1,1"));
}

TEST(IoExtract, StepTimeAndAllTimes) {
  ExtractRequest r = request("press_CC", 0, When::Step);
  r.step = 10;
  auto rows = csv(r);
  EXPECT_EQ(rows[1], concat(grid_prefix(10e-3, 0, 0, 0, false), {num(test::press(0, 0, 0, 10))}));

  r.when = When::Time;
  r.time = 0.012;  // nearest saved: 0.010
  EXPECT_EQ(csv(r)[1][0], num(10e-3));
  r.time = 0.016;  // nearest saved: 0.020
  EXPECT_EQ(csv(r)[1][0], num(20e-3));
  r.time = -5.0;
  EXPECT_EQ(csv(r)[1][0], num(0.0));

  r.when = When::AllTimes;
  rows = csv(r);
  ASSERT_EQ(rows.size(), 1u + 3 * 24);
  for (int f = 0; f < 3; ++f)
    EXPECT_EQ(rows[1 + 24 * f][0], num(f * 10e-3)) << f;
  EXPECT_EQ(rows.back().back(), num(test::press(2, 1, 3, 20)));
}

TEST(IoExtract, Reductions) {
  auto k = csv(request("KineticEnergy"));
  ASSERT_EQ(k.size(), 2u);
  EXPECT_EQ(k[0], split("time,KineticEnergy"));
  EXPECT_EQ(k[1], split(num(20e-3) + "," + num(ke(20e-3))));

  ExtractRequest r = request("TotalMomentum", std::nullopt, When::AllTimes);
  auto m = csv(r);
  ASSERT_EQ(m.size(), 4u);
  EXPECT_EQ(m[0], split("time,TotalMomentum_x,TotalMomentum_y,TotalMomentum_z"));
  const double t = 10e-3;
  EXPECT_EQ(m[2], split(num(t) + "," + num(t) + "," + num(2 * t) + "," + num(-t)));
  r.when = When::Time;
  r.time = 0.004;  // nearest: 0
  EXPECT_EQ(csv(r)[1][0], "0");
}

TEST(IoExtract, ErrorsListWhatIsSaved) {
  const std::string unknown = usage_error(request("press_XX"));
  for (const char* saved : {"press_CC", "g.mass", "p.stress", "p.x", "KineticEnergy", "TotalMomentum"})
    EXPECT_NE(unknown.find(saved), std::string::npos) << saved << " missing from: " << unknown;

  EXPECT_NE(usage_error(request("vel_CC", 1)).find("material(s): 0"), std::string::npos);
  ExtractRequest step = request("press_CC", 0, When::Step);
  step.step = 5;
  EXPECT_NE(usage_error(step).find("0, 10, 20"), std::string::npos);
  usage_error(request("KineticEnergy", 0));
  usage_error(request("KineticEnergy", std::nullopt, When::Step));
  ExtractRequest nodir = request("press_CC");
  nodir.dir = run_dir() + "/no_such_dir";
  usage_error(nodir);
}

TEST(IoExtract, UnreadableFrameIsARuntimeFailure) {
  const std::string dir = test::scratch_dir("io_extract_corrupt");
  {
    OutputWriter w(dir, false);
    w.write_frame(test::sample_frame(grid(), 1));
  }
  std::ofstream(dir + "/frames/t00002.h5") << "garbage";
  ExtractRequest r;
  r.dir = dir;
  r.label = "press_CC";
  std::ostringstream out;
  try {
    extract_csv(r, out);
    FAIL() << "expected RuntimeFailure";
  } catch (const RuntimeFailure& e) {
    EXPECT_NE(std::string(e.what()).find("t00002.h5"), std::string::npos) << e.what();
  }
}
