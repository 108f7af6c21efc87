// Erosion of flagged particles (mpm/Erosion.h) and pressure stabilisation
// (mpm/PressureStabilization.h, theory manual eqs. 1.82-1.84).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"
#include "mpm/PressureStabilization.h"

namespace tephra {
namespace {

// ---- erosion on a stress with mean p = (1 - 2 + 4)/3 = 1 (tension) and shear
Mat3 sample_stress(double sign) {
  Mat3 s;
  s << 1, 0.5, 0, 0.5, -2, 0.25, 0, 0.25, 4;
  return sign * s;
}

TEST(Erosion, AlgorithmsOnFlaggedParticlesOnly) {
  const std::vector<double> localized = {0.0, 1.0, 1.0};
  auto run = [&](ErosionAlgorithm a) {
    std::vector<Mat3> s = {sample_stress(1), sample_stress(1), sample_stress(-1)};
    std::vector<double> c = {9e6, 9e6, 9e6};
    erode_failed_particles(a, localized, s, c, 5000.0);
    return s;
  };
  // Particle 0 is not flagged: unchanged by every algorithm.
  for (ErosionAlgorithm a : {ErosionAlgorithm::ZeroStress, ErosionAlgorithm::AllowNoTension,
                             ErosionAlgorithm::AllowNoShear, ErosionAlgorithm::KeepStress})
    EXPECT_EQ(run(a)[0], sample_stress(1));
  auto z = run(ErosionAlgorithm::ZeroStress);
  EXPECT_EQ(z[1], Mat3::Zero());
  EXPECT_EQ(z[2], Mat3::Zero());
  // AllowNoTension: mean stress +1 (tension) -> 0; mean -1 (compression) -> -1 I.
  auto t = run(ErosionAlgorithm::AllowNoTension);
  EXPECT_EQ(t[1], Mat3::Zero());
  EXPECT_NEAR((t[2] - (-1.0) * Mat3::Identity()).norm(), 0.0, 1e-15);
  // AllowNoShear: the mean stress only, +1 I and -1 I.
  auto sh = run(ErosionAlgorithm::AllowNoShear);
  EXPECT_NEAR((sh[1] - Mat3::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((sh[2] + Mat3::Identity()).norm(), 0.0, 1e-15);
  auto k = run(ErosionAlgorithm::KeepStress);
  EXPECT_EQ(k[1], sample_stress(1));
}

// ZeroStress also bounds a flagged particle's wave speed by the material's
// at rest (a failed particle crushed near its EOS limit reported 9.3e6 m/s in
// the cookoff run and set the time step); unflagged particles and the other
// algorithms (which keep a pressure) leave it.
TEST(Erosion, ZeroStressBoundsTheWaveSpeedOfFlaggedParticles) {
  const std::vector<double> localized = {0.0, 1.0, 1.0};
  for (ErosionAlgorithm a : {ErosionAlgorithm::ZeroStress, ErosionAlgorithm::AllowNoTension,
                             ErosionAlgorithm::AllowNoShear, ErosionAlgorithm::KeepStress, ErosionAlgorithm::None}) {
    std::vector<Mat3> s = {sample_stress(1), sample_stress(1), sample_stress(-1)};
    std::vector<double> c = {9e6, 9e6, 3000.0};
    erode_failed_particles(a, localized, s, c, 5000.0);
    EXPECT_EQ(c[0], 9e6);
    EXPECT_EQ(c[1], a == ErosionAlgorithm::ZeroStress ? 5000.0 : 9e6);
    EXPECT_EQ(c[2], 3000.0);  // slower than at rest: kept
  }
}

TEST(Erosion, NamesOfTheSchema) {
  ErosionAlgorithm a;
  EXPECT_TRUE(erosion_algorithm_from_name("ZeroStress", a));
  EXPECT_EQ(a, ErosionAlgorithm::ZeroStress);
  EXPECT_TRUE(erosion_algorithm_from_name("AllowNoTension", a));
  EXPECT_TRUE(erosion_algorithm_from_name("AllowNoShear", a));
  EXPECT_TRUE(erosion_algorithm_from_name("none", a));
  EXPECT_EQ(a, ErosionAlgorithm::None);
  EXPECT_FALSE(erosion_algorithm_from_name("BrittleDamage", a));
  EXPECT_FALSE(erosion_algorithm_from_name("RemoveMass", a));
}

// comp_neo_hook with a "localized" history column that nothing updates: a
// stand-in for a damage model, the flag set by hand.
class FlaggedNeoHookean final : public ConstitutiveModel {
 public:
  FlaggedNeoHookean() : inner_(CompNeoHookeanParams{1e6, 5e5}) {}
  std::string type() const override { return "flagged_test_model"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override {
    return inner_.update(in, out);
  }
  std::vector<HistoryVariable> history() const override { return {{"localized", 1, {0.0}, "failed flag"}}; }
  double bulk_modulus() const override { return inner_.bulk_modulus(); }
  double shear_modulus() const override { return inner_.shear_modulus(); }

 private:
  CompNeoHookean inner_;
};

MpmSetup compressed_block(ErosionAlgorithm erosion) {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(4);
  s.grid.dx = Vec3::Constant(0.25);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  s.flags.erosion = erosion;
  MpmMaterial m;
  m.density = 1000.0;
  m.specific_heat = 1.0;
  m.model = std::make_shared<FlaggedNeoHookean>();
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.75));
  src.res = IntVec3::Constant(2);
  src.velocity = Vec3::Zero();
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

TEST(Erosion, ComponentZeroesTheStressOfTheFlaggedParticleOnly) {
  // A block squeezed and sheared, v = -r + 0.3 r_y e_x (r from the centre):
  // every particle has pressure and shear stress after one step; the
  // algorithm changes the flagged particle only.
  for (ErosionAlgorithm a : {ErosionAlgorithm::None, ErosionAlgorithm::ZeroStress, ErosionAlgorithm::AllowNoShear}) {
    MpmComponent c(compressed_block(a));
    c.initialize();
    Particles& p = c.materials()[0].particles;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Vec3 r = p.x[i] - Vec3::Constant(0.5);
      p.v[i] = -r + Vec3(0.3 * r[1], 0, 0);  // compression and shear
    }
    p.history[0][7] = 1.0;
    c.advance(0.0, 1e-3, 1);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (i != 7) {
        EXPECT_GT(p.stress[i].norm(), 0.0);
        continue;
      }
      const Mat3 dev = p.stress[i] - p.stress[i].trace() / 3.0 * Mat3::Identity();
      if (a == ErosionAlgorithm::None) EXPECT_GT(dev.norm(), 1e-3 * p.stress[i].norm());
      if (a == ErosionAlgorithm::ZeroStress) EXPECT_EQ(p.stress[i], Mat3::Zero());
      if (a == ErosionAlgorithm::AllowNoShear) {
        const double mean = p.stress[i].trace() / 3.0;
        EXPECT_LT(mean, 0.0);  // compressed
        EXPECT_NEAR((p.stress[i] - mean * Mat3::Identity()).norm(), 0.0, 1e-12 * std::abs(mean));
      }
    }
  }
}

// ---- pressure stabilisation on a 2x2x2-cell grid with 2x2x2 particles per cell
Particles cell_lattice(const NodeGrid& g) {
  Particles p;
  long long id = 0;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 4; ++i)
        p.add(g.origin + Vec3((i + 0.5) * 0.5 * g.h[0], (j + 0.5) * 0.5 * g.h[1], (k + 0.5) * 0.5 * g.h[2]),
              Vec3::Zero(), 1.0, 0.125 * g.h.prod(), 300, 0, id++);
  return p;
}

NodeGrid two_cells() {
  NodeGrid g;
  g.h = Vec3::Constant(0.5);
  g.n = IntVec3::Constant(3);
  return g;
}

TEST(PressureStabilization, UniformDeformationIsUnchanged) {
  const NodeGrid g = two_cells();
  Particles p = cell_lattice(g);
  Mat3 F;
  F << 1.1, 0.2, 0.0, -0.05, 0.95, 0.1, 0.0, 0.03, 1.02;
  for (Mat3& f : p.F) f = F;
  stabilize_pressure(g, p);
  for (const Mat3& f : p.F) EXPECT_NEAR((f - F).norm(), 0.0, 1e-15);
}

TEST(PressureStabilization, CheckerboardDilatationIsReplacedByTheCellMean) {
  // J_p = 1 + eps s_p with s_p = +-1 alternating between neighbouring
  // particles (a checkerboard: four of each sign in every cell), times a
  // per-cell isochoric shear R_c. The cell mean of J is 1 in every cell, so
  // afterwards det F_p = 1 (the checkerboard pressure K (J - 1) is gone) and
  // F_p / det(F_p)^{1/3} (the isochoric part) is unchanged.
  const NodeGrid g = two_cells();
  Particles p = cell_lattice(g);
  const double eps = 0.05;
  Mat3 shear = Mat3::Identity();
  shear(0, 1) = 0.1;  // det = 1
  std::vector<Mat3> iso(p.size());
  for (std::size_t n = 0; n < p.size(); ++n) {
    const int i = int(p.x[n][0] / 0.25), j = int(p.x[n][1] / 0.25), k = int(p.x[n][2] / 0.25);
    const double s = ((i + j + k) % 2 == 0) ? 1.0 : -1.0;
    p.F[n] = std::cbrt(1.0 + eps * s) * shear;
    iso[n] = shear;
  }
  stabilize_pressure(g, p);
  for (std::size_t n = 0; n < p.size(); ++n) {
    EXPECT_NEAR(p.F[n].determinant(), 1.0, 1e-14);
    EXPECT_NEAR((p.F[n] - iso[n]).norm(), 0.0, 1e-14);
  }
}

TEST(PressureStabilization, CellVolumeIsConservedAndEveryParticleTakesTheCellJ) {
  // Theory manual oracle: after the correction det F_p = J_c = V_c / V_c0 for
  // every particle of the cell, J_c computed before the correction.
  const NodeGrid g = two_cells();
  Particles p = cell_lattice(g);
  std::vector<double> J(p.size());
  for (std::size_t n = 0; n < p.size(); ++n) {
    J[n] = 1.0 + 0.01 * double(n % 7);
    p.F[n] = std::cbrt(J[n]) * Mat3::Identity();
  }
  // Cell 0: particles with all coordinates < 0.5.
  double V = 0, V0 = 0;
  for (std::size_t n = 0; n < p.size(); ++n)
    if ((p.x[n].array() < 0.5).all()) {
      V += J[n] * p.volume0[n];
      V0 += p.volume0[n];
    }
  stabilize_pressure(g, p);
  for (std::size_t n = 0; n < p.size(); ++n)
    if ((p.x[n].array() < 0.5).all()) EXPECT_NEAR(p.F[n].determinant(), V / V0, 1e-14);
}

}  // namespace
}  // namespace tephra
