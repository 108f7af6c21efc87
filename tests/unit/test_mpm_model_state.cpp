// The MPM driver's side of the solid-model interface: history columns (sized
// from the model's declaration, advanced by the model, saved as p.<name> and in
// checkpoints), F_n / sigma_n handed to incremental models, and rigid materials
// held at F = I.
#include <gtest/gtest.h>

#include <cmath>

#include "core/io/StateArchive.h"
#include "models/solid/HypoElastic.h"
#include "models/solid/RigidMaterial.h"
#include "core/geometry/Primitives.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

// A model that counts its steps in a scalar history column and carries a
// tensor column (initial I) scaled by 2 each step: the driver must size,
// keep and save both.
class CountingModel final : public ConstitutiveModel {
 public:
  std::string type() const override { return "counting"; }
  std::vector<HistoryVariable> history() const override {
    return {{"stepCount", 1, {0.0}, "steps taken"},
            {"doubling", 9, {1, 0, 0, 0, 1, 0, 0, 0, 1}, "2^steps I"}};
  }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override {
    for (std::size_t i = 0; i < in.F_new.size(); ++i) {
      out.stress[i].setZero();
      out.wave_speed[i] = 1.0;
      out.energy_density[i] = out.plastic_work[i] = out.heating[i] = 0.0;
      if (in.dt > 0) {
        out.history[0][i] += 1.0;
        for (int c = 0; c < 9; ++c) out.history[1][9 * i + c] *= 2.0;
      }
    }
    return -1;
  }
  double bulk_modulus() const override { return 1.0; }
  double shear_modulus() const override { return 1.0; }
};

MpmSetup block(ConstitutiveModelP model, const Vec3& velocity) {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(4);
  s.grid.dx = Vec3::Constant(0.25);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  MpmMaterial m;
  m.density = 1000.0;
  m.model = std::move(model);
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.75));
  src.res = IntVec3::Constant(2);
  src.velocity = velocity;
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

TEST(MpmModelState, HistoryColumnsAreSizedAdvancedSavedAndRestored) {
  MpmComponent c(block(std::make_shared<CountingModel>(), Vec3::Zero()));
  c.initialize();
  const Particles& p = c.materials()[0].particles;
  const std::size_t n = p.size();
  ASSERT_EQ(p.history.size(), 2u);
  ASSERT_EQ(p.history[0].size(), n);
  ASSERT_EQ(p.history[1].size(), 9 * n);
  EXPECT_EQ(p.history[1][4], 1.0);  // initial I, row-major (1,1) entry of particle 0
  for (int s = 1; s <= 3; ++s) c.advance(0.0, 1e-3, s);
  for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(p.history[0][i], 3.0);
  EXPECT_EQ(p.history[1][9 * (n - 1) + 8], 8.0);

  EXPECT_TRUE(c.known_labels().count("p.stepCount"));
  EXPECT_TRUE(c.known_labels().count("p.doubling"));
  OutputFrame frame;
  c.fill_output({"p.doubling"}, frame);
  ASSERT_EQ(frame.particles.size(), 1u);
  ASSERT_EQ(frame.particles[0].fields.size(), 1u);
  EXPECT_EQ(frame.particles[0].fields[0].components, 9);
  EXPECT_EQ(frame.particles[0].fields[0].values, p.history[1]);

  StateArchive a;
  c.save_state(a);
  MpmComponent d(block(std::make_shared<CountingModel>(), Vec3::Zero()));
  d.load_state(a);
  EXPECT_EQ(d.materials()[0].particles.history, p.history);
  // A history column of the wrong size is refused.
  std::vector<double> bad(a.doubles("mpm.m0.history.stepCount"));
  bad.pop_back();
  a.put("mpm.m0.history.stepCount", bad);
  EXPECT_THROW(d.load_state(a), RuntimeFailure);
}

TEST(MpmModelState, HypoElasticGetsTheStepsOldDeformationAndStress) {
  // Homogeneous velocity field v = L x: each step the driver must hand the model
  // F_n and sigma_n, so the stress equals the point function applied along the
  // particle's own F history (bit for bit).
  const HypoElasticParams hp{3.0e5, 8.0e5};
  MpmComponent c(block(std::make_shared<HypoElastic>(hp), Vec3::Zero()));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  Mat3 L;
  L << 0.1, 0.2, 0.0, -0.1, 0.05, 0.0, 0.0, 0.0, -0.1;
  std::vector<Mat3> F_prev(p.F), sigma_prev(p.stress);
  for (int s = 1; s <= 2; ++s) {
    for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = L * p.x[i];
    c.advance(0.0, 1e-3, s);
    for (std::size_t i = 0; i < p.size(); ++i) {
      EXPECT_EQ(p.stress[i], hypo_elastic_point(F_prev[i], p.F[i], sigma_prev[i], 1000.0, hp).stress) << i;
      EXPECT_NE(p.stress[i], Mat3::Zero());
    }
    F_prev = p.F;
    sigma_prev = p.stress;
  }
}

TEST(MpmModelState, RigidMaterialTranslatesWithFHeldAtIdentity) {
  // VT eq. 3.1: sigma = 0, F = I. A uniform velocity moves every particle by v dt per step.
  const Vec3 v(0.5, -0.25, 0.1);
  MpmComponent c(block(std::make_shared<RigidMaterial>(1e200, 1e200), v));
  c.initialize();
  const Particles& p = c.materials()[0].particles;
  const std::vector<Vec3> x0 = p.x;
  for (int s = 1; s <= 4; ++s) c.advance(0.0, 1e-2, s);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.F[i], Mat3::Identity());
    EXPECT_EQ(p.stress[i], Mat3::Zero());
    EXPECT_EQ(p.volume[i], p.volume0[i]);
    EXPECT_LE((p.x[i] - x0[i] - 4e-2 * v).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace tephra
