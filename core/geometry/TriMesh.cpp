// Triangulated closed surfaces as solids: file reading, closedness check and
// the ray-parity inside test (see TriMesh.h).
#include "core/geometry/TriMesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

#include "core/base/Errors.h"

namespace tephra {

namespace {

// Barycentric tolerance: a hit closer than this (relative) to an edge or
// vertex of a triangle is degenerate for the parity count.
constexpr double kBaryTol = 1e-10;

// Reads the whitespace-separated tokens of every non-blank line.
std::vector<std::pair<int, std::vector<std::string>>> read_lines(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open tri mesh file '" + path + "'");
  std::vector<std::pair<int, std::vector<std::string>>> out;
  std::string line;
  for (int n = 1; std::getline(in, line); ++n) {
    std::istringstream ls(line);
    std::vector<std::string> tokens;
    for (std::string t; ls >> t;) tokens.push_back(t);
    if (!tokens.empty()) out.emplace_back(n, std::move(tokens));
  }
  return out;
}

double cross2(double ux, double uy, double vx, double vy) { return ux * vy - uy * vx; }

// Distance from point q to the segment [a, b] in 2-D.
double segment_distance(double qx, double qy, double ax, double ay, double bx, double by) {
  const double ex = bx - ax, ey = by - ay, len2 = ex * ex + ey * ey;
  double t = len2 > 0 ? ((qx - ax) * ex + (qy - ay) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(qx - ax - t * ex, qy - ay - t * ey);
}

}  // namespace

TriMeshData read_tri_files(const std::string& prefix) {
  TriMeshData mesh;
  const std::string pts = prefix + ".pts", tri = prefix + ".tri";
  for (const auto& [n, tok] : read_lines(pts)) {
    Vec3 v;
    bool ok = tok.size() == 3;
    for (int i = 0; ok && i < 3; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(tok[i].c_str(), &end);
      ok = *end == '\0' && std::isfinite(v[i]);
    }
    if (!ok) throw std::runtime_error(pts + ":" + std::to_string(n) + ": expected three numbers 'x y z'");
    mesh.vertices.push_back(v);
  }
  for (const auto& [n, tok] : read_lines(tri)) {
    std::array<int, 3> t{};
    bool ok = tok.size() == 3;
    for (int i = 0; ok && i < 3; ++i) {
      char* end = nullptr;
      const long v = std::strtol(tok[i].c_str(), &end, 10);
      ok = *end == '\0' && v >= 0 && v < static_cast<long>(mesh.vertices.size());
      t[i] = static_cast<int>(v);
    }
    if (!ok)
      throw std::runtime_error(tri + ":" + std::to_string(n) +
                               ": expected three 0-based vertex indices below " +
                               std::to_string(mesh.vertices.size()));
    mesh.triangles.push_back(t);
  }
  if (mesh.triangles.empty()) throw std::runtime_error(tri + ": no triangles");
  return mesh;
}

std::string closed_surface_problem(const TriMeshData& mesh) {
  if (mesh.triangles.empty()) return "no triangles";
  const int nv = static_cast<int>(mesh.vertices.size());
  std::map<std::pair<int, int>, int> edge_use;
  for (size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& t = mesh.triangles[k];
    for (int i = 0; i < 3; ++i) {
      if (t[i] < 0 || t[i] >= nv)
        return "triangle " + std::to_string(k) + " has vertex index " + std::to_string(t[i]) +
               " outside [0, " + std::to_string(nv) + ")";
      const int a = t[i], b = t[(i + 1) % 3];
      if (a == b) return "triangle " + std::to_string(k) + " repeats vertex " + std::to_string(a);
      ++edge_use[{std::min(a, b), std::max(a, b)}];
    }
  }
  // A closed surface uses every edge an even number of times (twice for a
  // manifold); an odd count is a boundary edge, i.e. a hole.
  for (const auto& [e, n] : edge_use)
    if (n % 2)
      return "edge (" + std::to_string(e.first) + ", " + std::to_string(e.second) + ") is used by " +
             std::to_string(n) + " triangle(s): the surface is not closed";
  return "";
}

TriMeshPiece::TriMeshPiece(TriMeshData mesh) {
  const std::string problem = closed_surface_problem(mesh);
  if (!problem.empty()) throw std::invalid_argument("tri mesh: " + problem);
  box_ = {mesh.vertices.front(), mesh.vertices.front()};
  for (const auto& v : mesh.vertices) box_ = {box_.lo.cwiseMin(v), box_.hi.cwiseMax(v)};
  eps_ = 1e-12 * (box_.hi - box_.lo).norm();
  for (const auto& t : mesh.triangles)
    tris_.push_back({mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]});

  // Bin grid over (y, z) with about one triangle per bin row and column.
  const int n = std::clamp(static_cast<int>(std::sqrt(static_cast<double>(tris_.size()))), 1, 256);
  ny_ = nz_ = n;
  y0_ = box_.lo.y() - eps_;
  z0_ = box_.lo.z() - eps_;
  dy_ = std::max((box_.hi.y() - box_.lo.y() + 2 * eps_) / n, 1e-300);
  dz_ = std::max((box_.hi.z() - box_.lo.z() + 2 * eps_) / n, 1e-300);
  bins_.assign(static_cast<size_t>(ny_) * nz_, {});
  for (size_t k = 0; k < tris_.size(); ++k) {
    const Tri& t = tris_[k];
    const double ylo = std::min({t.a.y(), t.b.y(), t.c.y()}) - eps_;
    const double yhi = std::max({t.a.y(), t.b.y(), t.c.y()}) + eps_;
    const double zlo = std::min({t.a.z(), t.b.z(), t.c.z()}) - eps_;
    const double zhi = std::max({t.a.z(), t.b.z(), t.c.z()}) + eps_;
    const int j0 = std::clamp(static_cast<int>(std::floor((ylo - y0_) / dy_)), 0, ny_ - 1);
    const int j1 = std::clamp(static_cast<int>(std::floor((yhi - y0_) / dy_)), 0, ny_ - 1);
    const int k0 = std::clamp(static_cast<int>(std::floor((zlo - z0_) / dz_)), 0, nz_ - 1);
    const int k1 = std::clamp(static_cast<int>(std::floor((zhi - z0_) / dz_)), 0, nz_ - 1);
    for (int j = j0; j <= j1; ++j)
      for (int kk = k0; kk <= k1; ++kk) bins_[static_cast<size_t>(j) * nz_ + kk].push_back(static_cast<int>(k));
  }
}

int TriMeshPiece::bin_index(double y, double z) const {
  const int j = std::clamp(static_cast<int>(std::floor((y - y0_) / dy_)), 0, ny_ - 1);
  const int k = std::clamp(static_cast<int>(std::floor((z - z0_) / dz_)), 0, nz_ - 1);
  return j * nz_ + k;
}

// Ray p + t e_x, t >= 0, against the triangles of p's (y, z) bin, in the
// (y, z) projection: barycentrics l_i = (signed sub-areas) / (signed area).
TriMeshPiece::Cast TriMeshPiece::cast_along_x(const Vec3& p) const {
  int crossings = 0;
  for (int k : bins_[bin_index(p.y(), p.z())]) {
    const Tri& t = tris_[k];
    const double area = cross2(t.b.y() - t.a.y(), t.b.z() - t.a.z(), t.c.y() - t.a.y(),
                               t.c.z() - t.a.z());
    const double edge_scale = (t.b - t.a).norm() * (t.c - t.a).norm();
    if (std::abs(area) <= 1e-12 * edge_scale) {
      // Triangle parallel to the ray: the ray lies in its plane if p's (y, z)
      // is on its projected outline; then the count is undefined.
      const double d = std::min({segment_distance(p.y(), p.z(), t.a.y(), t.a.z(), t.b.y(), t.b.z()),
                                 segment_distance(p.y(), p.z(), t.b.y(), t.b.z(), t.c.y(), t.c.z()),
                                 segment_distance(p.y(), p.z(), t.c.y(), t.c.z(), t.a.y(), t.a.z())});
      if (d <= eps_ && std::max({t.a.x(), t.b.x(), t.c.x()}) >= p.x() - eps_) return Cast::Degenerate;
      continue;
    }
    const double l0 = cross2(t.b.y() - p.y(), t.b.z() - p.z(), t.c.y() - p.y(), t.c.z() - p.z()) / area;
    const double l1 = cross2(t.c.y() - p.y(), t.c.z() - p.z(), t.a.y() - p.y(), t.a.z() - p.z()) / area;
    const double l2 = 1.0 - l0 - l1;
    if (std::min({l0, l1, l2}) < -kBaryTol) continue;
    const double x_hit = l0 * t.a.x() + l1 * t.b.x() + l2 * t.c.x();
    if (std::abs(x_hit - p.x()) <= eps_) return Cast::Inside;  // p on the surface
    if (x_hit < p.x()) continue;
    if (std::min({l0, l1, l2}) <= kBaryTol) return Cast::Degenerate;
    ++crossings;
  }
  return crossings % 2 ? Cast::Inside : Cast::Outside;
}

// Ray p + t d (|d| = 1) against every triangle (Moller-Trumbore:
// p + t d = a + u (b-a) + v (c-a)).
TriMeshPiece::Cast TriMeshPiece::cast_generic(const Vec3& p, const Vec3& d) const {
  int crossings = 0;
  for (const Tri& t : tris_) {
    const Vec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const Vec3 h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) <= 1e-12 * e1.norm() * e2.norm()) {
      const Vec3 nrm = e1.cross(e2);
      if (nrm.norm() > 0 && std::abs(nrm.normalized().dot(p - t.a)) <= eps_) return Cast::Degenerate;
      continue;
    }
    const Vec3 s = p - t.a;
    const double u = s.dot(h) / det;
    const Vec3 q = s.cross(e1);
    const double v = d.dot(q) / det;
    const double w = 1.0 - u - v;
    if (std::min({u, v, w}) < -kBaryTol) continue;
    const double tt = e2.dot(q) / det;
    if (std::abs(tt) <= eps_) return Cast::Inside;  // p on the surface
    if (tt < 0) continue;
    if (std::min({u, v, w}) <= kBaryTol) return Cast::Degenerate;
    ++crossings;
  }
  return crossings % 2 ? Cast::Inside : Cast::Outside;
}

bool TriMeshPiece::inside(const Vec3& x) const {
  if ((x.array() < box_.lo.array() - eps_).any() || (x.array() > box_.hi.array() + eps_).any())
    return false;
  Cast c = cast_along_x(x);
  if (c != Cast::Degenerate) return c == Cast::Inside;
  // Fixed directions with irrational-looking components: a mesh from a deck
  // is very unlikely to have edges or faces aligned with them.
  static const Vec3 dirs[] = {Vec3(0.5772156649, 0.3183098862, 0.7390851332).normalized(),
                              Vec3(-0.2718281828, 0.8414709848, 0.1414213562).normalized(),
                              Vec3(0.6180339887, -0.4142135624, -0.5403023059).normalized(),
                              Vec3(-0.7071067812, -0.2236067977, 0.6931471806).normalized()};
  for (const Vec3& d : dirs) {
    c = cast_generic(x, d);
    if (c != Cast::Degenerate) return c == Cast::Inside;
  }
  throw NumericalFailure("tri mesh: every ray from point (" + std::to_string(x.x()) + ", " +
                         std::to_string(x.y()) + ", " + std::to_string(x.z()) +
                         ") grazes an edge; cannot decide inside/outside");
}

double TriMeshPiece::enclosed_volume() const {
  double six_v = 0;
  for (const Tri& t : tris_) six_v += t.a.dot(t.b.cross(t.c));
  return std::abs(six_v) / 6.0;
}

}  // namespace tephra
