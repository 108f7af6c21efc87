// MpmComponent on hand-built grids and test-local geometry (no deck reader):
// uniform deformation, grid boundary conditions, restart and failures.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/LU>

#include "models/solid/CompNeoHookean.h"
#include "core/geometry/Primitives.h"
#include "mpm/MpmComponent.h"

namespace tephra {
namespace {

// Unit cube, 8^3 cells (h = 0.125), one comp_neo_hook material filling [0.25, 0.75]^3
// with 2x2x2 particles per cell (512 particles).
MpmSetup block_setup(const Vec3& velocity) {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(8);
  s.grid.dx = Vec3::Constant(0.125);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  MpmMaterial m;
  m.density = 1000.0;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{833.3, 384.6});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.75));
  src.res = IntVec3::Constant(2);
  src.velocity = velocity;
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

TEST(MpmComponent, SeedsSubCellCentresWithDensityTimesVolume) {
  MpmComponent c(block_setup(Vec3::Zero()));
  c.initialize();
  const Particles& p = c.materials()[0].particles;
  ASSERT_EQ(p.size(), 512u);  // (4 cells * 2)^3
  const double v0 = std::pow(0.125, 3) / 8;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.volume0[i], v0);
    EXPECT_EQ(p.mass[i], 1000.0 * v0);
    // Sub-cell centres: x / (h/2) - 1/2 is an integer.
    for (int d = 0; d < 3; ++d) {
      const double r = p.x[i][d] / 0.0625 - 0.5;
      EXPECT_NEAR(r, std::round(r), 1e-12);
    }
  }
  const auto red = c.reductions({"TotalMass"});
  EXPECT_NEAR(red.at("TotalMass")[0], 1000.0 * 0.125, 1e-12);  // rho * 0.5^3
}

// VT Alg. 9: the particle volume is V_p = det(F_p) V_p0 from the current F,
// not a product of per-step volume ratios (which accumulates round-off and
// drifts from det F). After 20 steps of a non-uniform motion every particle
// must hold exactly det(F) * volume0 (same expression, so bit-equal).
TEST(MpmComponent, VolumeIsDetFTimesInitialVolume) {
  Mat3 L;
  L << 0.3, -0.2, 0.05, 0.1, -0.2, 0.0, -0.05, 0.02, 0.25;
  MpmComponent c(block_setup(Vec3::Zero()));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = L * p.x[i] + 0.1 * p.x[i].cwiseProduct(p.x[i]);
  for (int n = 1; n <= 20; ++n) c.advance(0.0 + (n - 1) * 1e-3, 1e-3, n);
  double max_dev = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.volume[i], p.F[i].determinant() * p.volume0[i]);
    max_dev = std::max(max_dev, std::abs(p.F[i].determinant() - 1.0));
  }
  EXPECT_GT(max_dev, 1e-3);  // the motion did change the volumes
}

TEST(MpmComponent, HomogeneousVelocityFieldGivesExactVelocityGradient) {
  // v(x) = v0 + L x on the particles, stress-free, no BCs. P2G with linear
  // shapes gives v_g = v0 + L x_g exactly at every node whose support holds a
  // symmetric particle lattice (sum_p m_p S_gp (x_p - x_g) = 0), so for the
  // particles whose 8 nodes are such nodes (the block minus one cell layer)
  // l_p = sum_g v_g grad S_gp^T = L sum_g x_g grad S_gp^T = L, and after one
  // step F = I + dt L (eq. 1.74) to round-off.
  Mat3 L;
  L << 0.1, -0.2, 0.05, 0.3, -0.1, 0.0, -0.05, 0.02, 0.2;
  const Vec3 v0(0.01, -0.02, 0.03);
  MpmComponent c(block_setup(Vec3::Zero()));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = v0 + L * p.x[i];
  const double dt = 1e-3;
  c.advance(0.0, dt, 1);
  const std::vector<Vec3> x_new = p.x;
  int checked = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 x0 = p.x[i] - p.displacement[i];
    if (((x0.array() > 0.375) && (x0.array() < 0.625)).all()) {
      EXPECT_NEAR((c.materials()[0].L[i] - L).norm(), 0.0, 1e-13);
      EXPECT_NEAR((p.F[i] - (Mat3::Identity() + dt * L)).norm(), 0.0, 1e-15);
      // x moves with the grid velocity: x1 = x0 + dt (v0 + L x0).
      EXPECT_NEAR((p.x[i] - (x0 + dt * (v0 + L * x0))).norm(), 0.0, 1e-15);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 64);  // 2 cells * 2 particles per direction, cubed
  // Interior nodes carry the affine field exactly.
  const NodeGrid& g = c.materials()[0].grid;
  for (int k = 3; k <= 5; ++k)
    for (int j = 3; j <= 5; ++j)
      for (int i = 3; i <= 5; ++i)
        EXPECT_NEAR((g.velocity[g.index(i, j, k)] - (v0 + L * g.position(i, j, k))).norm(), 0.0, 1e-15);
}

TEST(MpmComponent, GridBoundaryConditionsSetFaceNodes) {
  // Dirichlet velocity on x- sets every node of plane i = 0 to the value;
  // symmetry on z+ zeroes the z component on plane k = n_z - 1; others untouched.
  NodeGrid g;
  g.n = IntVec3(4, 3, 2);
  g.reset();
  for (auto& v : g.velocity) v = Vec3(1, 2, 3);
  GridBoundaryConditions bc;
  bc.face[0] = {FaceVelocityBC::Kind::Velocity, Vec3(0.5, 0, 0)};
  bc.face[5] = {FaceVelocityBC::Kind::Symmetry, Vec3::Zero()};
  bc.apply(g, g.velocity);
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 4; ++i) {
        Vec3 expect = i == 0 ? Vec3(0.5, 0, 0) : Vec3(1, 2, 3);
        if (k == 1) expect[2] = 0;  // symmetry applied after Dirichlet (as Vaango)
        EXPECT_EQ(g.velocity[g.index(i, j, k)], expect);
      }
}

TEST(MpmComponent, RestartIsBitForBit) {
  // Run 4 steps, checkpoint, run 4 more; a fresh component loaded from the
  // checkpoint must reproduce the last 4 steps exactly (==, not near).
  auto run = [](MpmComponent& c, int from, int steps) {
    for (int s = from; s < from + steps; ++s) c.advance(0.0, 0.2 * c.stable_timestep(), s);
  };
  MpmComponent a(block_setup(Vec3(0.3, -0.1, 0.2)));
  a.initialize();
  Particles& pa = a.materials()[0].particles;
  for (std::size_t i = 0; i < pa.size(); ++i) pa.v[i] += Vec3(-0.5 * (pa.x[i][0] - 0.5), 0.0, 0.0);
  run(a, 1, 4);
  StateArchive ar;
  a.save_state(ar);
  run(a, 5, 4);
  MpmComponent b(block_setup(Vec3::Zero()));
  b.load_state(ar);
  run(b, 5, 4);
  const Particles& pb = b.materials()[0].particles;
  ASSERT_EQ(pa.size(), pb.size());
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa.x[i], pb.x[i]);
    EXPECT_EQ(pa.v[i], pb.v[i]);
    EXPECT_EQ(pa.F[i], pb.F[i]);
    EXPECT_EQ(pa.stress[i], pb.stress[i]);
    EXPECT_EQ(pa.id[i], pb.id[i]);
  }
  EXPECT_EQ(a.stable_timestep(), b.stable_timestep());
  EXPECT_NE(pa.stress[0], Mat3::Zero());  // the run did deform the block
}

TEST(MpmComponent, StableTimestepIsVaangoRule) {
  // dt = min_p min_d h_d / (c + |v_d|), c = sqrt((K + 4G/3)/rho0) at F = I.
  MpmComponent c(block_setup(Vec3(0.3, -0.5, 0.1)));
  c.initialize();
  const double cw = std::sqrt((833.3 + 4 * 384.6 / 3) / 1000.0);
  EXPECT_NEAR(c.stable_timestep(), 0.125 / (cw + 0.5), 1e-15);
}

TEST(MpmComponent, ParticleLeavingTheGridIsANumericalFailure) {
  // 800 m/s * 1e-3 s = 0.8 m: the front particles reach x = 1.52, more than a
  // cell (0.125) beyond the x+ face in one step, which the CFL limit excludes:
  // a blow-up (within one cell they would be deleted, mpm/ParticleDeletion.h).
  MpmComponent c(block_setup(Vec3(800.0, 0.0, 0.0)));
  c.initialize();
  try {
    c.advance(0.0, 1e-3, 7);
    FAIL() << "expected NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("step 7"), std::string::npos) << m;
    EXPECT_NE(m.find("particle id"), std::string::npos) << m;
    EXPECT_NE(m.find("left the grid"), std::string::npos) << m;
  }
}

TEST(MpmComponent, InvertedParticleIsANumericalFailure) {
  MpmComponent c(block_setup(Vec3::Zero()));
  c.initialize();
  c.materials()[0].particles.F[5](1, 1) = -1.0;  // det F < 0 carried into F_{n+1}
  try {
    c.advance(0.0, 1e-3, 3);
    FAIL() << "expected NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("Jacobian"), std::string::npos) << m;
    EXPECT_NE(m.find("particle id 5"), std::string::npos) << m;
  }
}

TEST(MpmComponent, OutputCarriesRequestedLabels) {
  MpmComponent c(block_setup(Vec3(0.1, 0, 0)));
  c.initialize();
  OutputFrame f;
  c.fill_output({"p.x", "p.stress", "p.velocity", "g.mass"}, f);
  ASSERT_EQ(f.particles.size(), 1u);
  EXPECT_EQ(f.particles[0].position.size(), 512u);
  ASSERT_EQ(f.particles[0].fields.size(), 2u);
  ASSERT_EQ(f.grid_fields.size(), 1u);
  EXPECT_EQ(f.grid_fields[0].data.values.size(), 9u * 9 * 9);  // nodes 0..8 per direction
  double mg = 0;
  for (double m : f.grid_fields[0].data.values) mg += m;
  EXPECT_NEAR(mg, 125.0, 1e-11);
  for (const auto& l : {"p.x", "p.stress", "g.mass", "KineticEnergy", "StrainEnergy", "TotalMomentum"})
    EXPECT_TRUE(c.known_labels().count(l)) << l;
}

}  // namespace
}  // namespace tephra
