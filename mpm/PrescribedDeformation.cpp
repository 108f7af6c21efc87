#include "mpm/PrescribedDeformation.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <Eigen/LU>

#include "core/base/Errors.h"
#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

// Rodrigues: R = cos th (I - a a^T) + sin th [a]_x + a a^T, |a| = 1.
Mat3 rotation(double angle_deg, const Vec3& a) {
  const double th = angle_deg * std::numbers::pi / 180.0;
  Mat3 K;
  K << 0, -a[2], a[1], a[2], 0, -a[0], -a[1], a[0], 0;
  const Mat3 aa = a * a.transpose();
  return std::cos(th) * (Mat3::Identity() - aa) + std::sin(th) * K + aa;
}

}  // namespace

Mat3 PrescribedDeformation::at(double t) const {
  const std::size_t n = rows.size();
  if (t <= rows.front().t) return rows.front().F;
  // The segment [t_s, t_{s+1}] holding t (the last one, at its end, after the last row).
  std::size_t s = 0;
  while (s + 2 < n && t > rows[s + 1].t) ++s;
  const PrescribedRow &a = rows[s], &b = rows[s + 1];
  const double f = std::min(1.0, (t - a.t) / (b.t - a.t));
  Mat3 previous = Mat3::Identity();  // P_s = R_s ... R_1
  for (std::size_t j = 1; j <= s; ++j) previous = rotation(rows[j].angle_deg, rows[j].axis) * previous;
  const Mat3 U = a.F + f * (b.F - a.F);
  return rotation(f * b.angle_deg, b.axis) * previous * U;
}

Mat3 PrescribedDeformation::step_velocity_gradient(double t, double dt) const {
  return (at(t + dt) * at(t).inverse() - Mat3::Identity()) / dt;
}

PrescribedDeformation parse_prescribed_deformation(std::istream& in, const std::string& name) {
  PrescribedDeformation d;
  std::string line;
  int number = 0;
  auto fail = [&](const std::string& what) -> void { throw DeckError(SourceLocation{name, number, ""}, what); };
  while (std::getline(in, line)) {
    ++number;
    const auto first = line.find_first_not_of(" \t\r");
    if (first == std::string::npos || line[first] == '#') continue;  // blank lines and comments
    std::istringstream words(line);
    double v[14];
    int k = 0;
    while (k < 14 && words >> v[k]) ++k;
    std::string rest;
    if (k < 14 || (words.clear(), words >> rest))
      fail("a prescribed deformation row is 14 numbers: t F11 F12 F13 F21 F22 F23 F31 F32 F33 theta a1 a2 a3");
    PrescribedRow r;
    r.t = v[0];
    for (int i = 0; i < 9; ++i) r.F(i / 3, i % 3) = v[1 + i];
    r.angle_deg = v[10];
    const Vec3 axis(v[11], v[12], v[13]);
    for (double x : v)
      if (!std::isfinite(x)) fail("non-finite number in a prescribed deformation row");
    if (!d.rows.empty() && !(r.t > d.rows.back().t)) fail("prescribed deformation times must increase strictly");
    if (!(r.F.determinant() > 0.0)) fail("the row's F has det F <= 0");
    if (r.angle_deg != 0.0) {
      if (!(axis.norm() > 0.0)) fail("a nonzero rotation angle needs a nonzero axis");
      if (d.rows.empty())
        fail("the first row's rotation would act before the first time (Vaango ignores it); set its angle to 0");
      r.axis = axis.normalized();
    }
    d.rows.push_back(r);
  }
  if (d.rows.size() < 2) {
    number = 0;
    fail("a prescribed deformation file needs at least two rows");
  }
  return d;
}

PrescribedDeformation read_prescribed_deformation(const DeckNode& file_node) {
  namespace fs = std::filesystem;
  const std::string& text = file_node.text;
  fs::path path(text);
  if (path.is_relative()) {
    const fs::path beside = fs::path(file_node.file).parent_path() / path;
    if (fs::exists(beside)) path = beside;
  }
  std::ifstream in(path);
  if (!in) file_node.fail("cannot open prescribed_deformation_file '" + text + "' (looked beside the deck and in the working directory)");
  return parse_prescribed_deformation(in, path.string());
}

void set_prescribed_grid_velocity(const Mat3& l, double dt, NodeGrid& g) {
  for (int k = 0; k < g.n[2]; ++k)
    for (int j = 0; j < g.n[1]; ++j)
      for (int i = 0; i < g.n[0]; ++i) {
        const std::size_t gi = g.index(i, j, k);
        g.velocity_star[gi] = l * g.position(i, j, k);
        g.acceleration[gi] = (g.velocity_star[gi] - g.velocity[gi]) / dt;
      }
}

}  // namespace tephra
