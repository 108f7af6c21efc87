// The prescribed deformation history (mpm/PrescribedDeformation.h): the file
// rows, F*(t) (linear stretch, superposed rotations over each segment), the
// discrete velocity gradient, and the errors at file:line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <sstream>

#include <Eigen/LU>

#include "core/base/Errors.h"
#include "mpm/PrescribedDeformation.h"

namespace tephra {
namespace {

PrescribedDeformation parse(const std::string& text) {
  std::istringstream in(text);
  return parse_prescribed_deformation(in, "p.txt");
}

Mat3 rot_z(double deg) {
  const double a = deg * std::numbers::pi / 180.0;
  Mat3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

TEST(MpmPrescribedDeformation, StretchIsInterpolatedLinearlyAndHeld) {
  const auto d = parse("# t F theta axis\n"
                       "0 1 0 0 0 1 0 0 0 1 0 0 0 0\n"
                       "\n"
                       "1 2 0 0 0 1 0 0 0 1 0 0 0 1\n"
                       "3 2 1 0 0 1 0 0 0 1 0 0 0 1\n");
  ASSERT_EQ(d.rows.size(), 3u);
  EXPECT_NEAR((d.at(0.25) - Vec3(1.25, 1, 1).asDiagonal().toDenseMatrix()).norm(), 0, 1e-15);
  Mat3 F = Vec3(2, 1, 1).asDiagonal();
  F(0, 1) = 0.5;  // halfway along [1, 3]
  EXPECT_NEAR((d.at(2.0) - F).norm(), 0, 1e-15);
  F(0, 1) = 1.0;
  EXPECT_NEAR((d.at(7.0) - F).norm(), 0, 1e-15);   // held after the last row
  EXPECT_NEAR((d.at(-1.0) - Mat3::Identity()).norm(), 0, 1e-15);
  // l = (F*(t+dt) F*(t)^{-1} - I)/dt; for the uniaxial segment F11 = 1 + t:
  // l11 = ((1 + t + dt)/(1 + t) - 1)/dt = 1/(1 + t), exactly for any dt.
  EXPECT_NEAR(d.step_velocity_gradient(0.25, 0.5)(0, 0), 1.0 / 1.25, 1e-14);
  EXPECT_NEAR(d.step_velocity_gradient(0.25, 0.5)(1, 1), 0.0, 1e-14);
}

// Rotations are per segment and accumulate: 90 deg about z over [0, 1],
// then 90 deg more over [1, 2]: F*(1.5) = R_z(135) F, F*(2) = R_z(180) F.
TEST(MpmPrescribedDeformation, RotationsAccumulateOverSegments) {
  const auto d = parse("0 1.5 0 0 0 1 0 0 0 1 0 0 0 1\n"
                       "1 1.5 0 0 0 1 0 0 0 1 90 0 0 2\n"
                       "2 1.5 0 0 0 1 0 0 0 1 90 0 0 1\n");
  const Mat3 U = Vec3(1.5, 1, 1).asDiagonal();
  EXPECT_NEAR((d.at(0.5) - rot_z(45) * U).norm(), 0, 1e-14);
  EXPECT_NEAR((d.at(1.0) - rot_z(90) * U).norm(), 0, 1e-14);
  EXPECT_NEAR((d.at(1.5) - rot_z(135) * U).norm(), 0, 1e-14);
  EXPECT_NEAR((d.at(2.0) - rot_z(180) * U).norm(), 0, 1e-14);
}

TEST(MpmPrescribedDeformation, BadRowsAreDeckErrorsAtTheLine) {
  auto expect_error_at = [](const std::string& text, const std::string& where) {
    try {
      parse(text);
      ADD_FAILURE() << "no error for\n" << text;
    } catch (const DeckError& e) {
      EXPECT_NE(std::string(e.what()).find(where), std::string::npos) << e.what();
    }
  };
  const std::string row0 = "0 1 0 0 0 1 0 0 0 1 0 0 0 0\n";
  expect_error_at(row0 + "1 1 0 0 0 1 0 0 0 1 0 0 0\n", "p.txt:2");         // 13 numbers
  expect_error_at(row0 + "1 1 0 0 0 1 0 0 0 1 0 0 0 1 7\n", "p.txt:2");     // 15
  expect_error_at(row0 + "1 1 0 0 0 1 0 0 0 x 0 0 0 1\n", "p.txt:2");       // not a number
  expect_error_at(row0 + "0 1 0 0 0 1 0 0 0 1 0 0 0 1\n", "p.txt:2");       // time not increasing
  expect_error_at(row0 + "1 -1 0 0 0 1 0 0 0 1 0 0 0 1\n", "p.txt:2");      // det F < 0
  expect_error_at(row0 + "1 1 0 0 0 1 0 0 0 1 30 0 0 0\n", "p.txt:2");      // angle without an axis
  expect_error_at("0 1 0 0 0 1 0 0 0 1 10 0 0 1\n1 1 0 0 0 1 0 0 0 1 0 0 0 1\n", "p.txt:1");  // first angle
  expect_error_at(row0, "two rows");
}

}  // namespace
}  // namespace tephra
