#pragma once
// A hand-built output frame whose every value is a closed-form function of
// its index, so tests can check what was written and extracted against the
// formula rather than against stored numbers.
#include <cstring>
#include <vector>

#include <gtest/gtest.h>

#include "core/io/OutputFrame.h"
#include "core/io/StateArchive.h"

namespace tephra::test {

// An anisotropic grid so that any axis mix-up (x/z order) shows.
inline Grid sample_grid() {
  Grid g;
  g.lower = Vec3(-1.0, 0.5, 2.0);
  g.dx = Vec3(0.25, 0.5, 0.125);
  g.cells = IntVec3(3, 2, 4);
  g.extra_cells = IntVec3(1, 1, 1);
  g.upper = g.lower + g.dx.cwiseProduct(g.cells.cast<double>());
  return g;
}

// Cell value of press_CC: 1e5 + i + 10 j + 100 k + 1/3 + step (1/3 is not
// representable, so every bit of the mantissa matters in round trips).
inline double press(int i, int j, int k, int step) { return 1e5 + i + 10 * j + 100 * k + 1.0 / 3.0 + step; }
// vel_CC component c: (i + 1)/(c + 3) - j * k / 7.
inline double vel(int i, int j, int k, int c) { return (i + 1.0) / (c + 3.0) - j * k / 7.0; }
// temp_CC over interior + extra cells (i may be -1): 300 + i + 10 j + 100 k.
inline double temp(int i, int j, int k) { return 300.0 + i + 10 * j + 100 * k; }
// g.mass at node (i,j,k): 0.1 * (1 + i + 4 j + 12 k).
inline double gmass(int i, int j, int k) { return 0.1 * (1 + i + 4 * j + 12 * k); }
// Particle p of material 0: x = (0.1 p, 0.2 + p/9, -p), id 1000 + p,
// mass 1/(p+1), velocity (p, -p, p/3), stress component c: 10 p + c + 0.5.
inline Vec3 ppos(int p) { return Vec3(0.1 * p, 0.2 + p / 9.0, -1.0 * p); }
inline double pmass(int p) { return 1.0 / (p + 1.0); }
inline double pstress(int p, int c) { return 10.0 * p + c + 0.5; }

inline FieldArray field(const std::string& label, int material, int components) {
  FieldArray f;
  f.label = label;
  f.material = material;
  f.components = components;
  return f;
}

// Frame at `step`, time = step * 1e-3. `grid` must outlive the frame.
inline OutputFrame sample_frame(const Grid& grid, int step) {
  OutputFrame fr;
  fr.step = step;
  fr.time = step * 1e-3;
  fr.grid = &grid;
  const IntVec3 n = grid.cells, e = grid.extra_cells;

  GridFieldArray p{field("press_CC", 0, 1), GridLocation::Cell};
  GridFieldArray v{field("vel_CC", 0, 3), GridLocation::Cell};
  GridFieldArray p1{field("press_CC", 1, 1), GridLocation::Cell};
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        p.data.values.push_back(press(i, j, k, step));
        p1.data.values.push_back(-press(i, j, k, step));
        for (int c = 0; c < 3; ++c) v.data.values.push_back(vel(i, j, k, c));
      }
  GridFieldArray t{field("temp_CC", 0, 1), GridLocation::Cell};
  for (int k = -e[2]; k < n[2] + e[2]; ++k)
    for (int j = -e[1]; j < n[1] + e[1]; ++j)
      for (int i = -e[0]; i < n[0] + e[0]; ++i) t.data.values.push_back(temp(i, j, k));
  GridFieldArray m{field("g.mass", 0, 1), GridLocation::Node};
  for (int k = 0; k <= n[2]; ++k)
    for (int j = 0; j <= n[1]; ++j)
      for (int i = 0; i <= n[0]; ++i) m.data.values.push_back(gmass(i, j, k));
  fr.grid_fields = {p, v, p1, t, m};

  ParticleBlock b0;
  b0.material = 0;
  FieldArray mass = field("p.mass", 0, 1), velo = field("p.velocity", 0, 3),
             stress = field("p.stress", 0, 9);
  for (int q = 0; q < 5; ++q) {
    b0.position.push_back(ppos(q));
    b0.id.push_back(1000 + q);
    mass.values.push_back(pmass(q));
    velo.values.insert(velo.values.end(), {1.0 * q, -1.0 * q, q / 3.0});
    for (int c = 0; c < 9; ++c) stress.values.push_back(pstress(q, c));
  }
  b0.fields = {mass, velo, stress};
  ParticleBlock b1;  // a second material with a different particle count
  b1.material = 1;
  FieldArray mass1 = field("p.mass", 1, 1);
  for (int q = 0; q < 2; ++q) {
    b1.position.push_back(Vec3(q, q, q));
    b1.id.push_back(2000 + q);
    mass1.values.push_back(7.0 + q);
  }
  b1.fields = {mass1};
  ParticleBlock b2;  // an empty material: written, but not indexed in XDMF
  b2.material = 2;
  b2.fields = {field("p.mass", 2, 1)};
  fr.particles = {b0, b1, b2};
  return fr;
}

// Bit-for-bit equality of two double arrays (NaN payloads and -0 included).
inline bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() &&
         (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Two archives with the same arrays, equal bit for bit.
inline void expect_same_archive(const StateArchive& a, const StateArchive& b) {
  ASSERT_EQ(a.all_doubles().size(), b.all_doubles().size());
  ASSERT_EQ(a.all_ints().size(), b.all_ints().size());
  for (const auto& [name, v] : a.all_doubles()) {
    ASSERT_TRUE(b.has(name)) << name;
    EXPECT_TRUE(same_bits(v, b.doubles(name))) << name;
  }
  for (const auto& [name, v] : a.all_ints()) EXPECT_EQ(v, b.ints(name)) << name;
}

}  // namespace tephra::test
