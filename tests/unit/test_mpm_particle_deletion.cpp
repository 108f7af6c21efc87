// Particle deletion (mpm/ParticleDeletion.h): row removal from every SoA
// column including the model's history, Vaango's deletion criteria
// (minimum_particle_mass, negative temperature, maximum_particle_velocity with
// and without delete_rogue_particles), and the component's end-of-step pass.
#include <gtest/gtest.h>

#include <cmath>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "core/geometry/Primitives.h"
#include "models/solid/CompNeoHookean.h"
#include "mpm/MpmComponent.h"
#include "mpm/ParticleDeletion.h"

namespace tephra {
namespace {

// n particles whose every column holds values derived from the row index, and
// a scalar and a 9-component history column.
Particles numbered(int n) {
  Particles p;
  for (int i = 0; i < n; ++i) {
    p.add(Vec3(i, 2 * i, 3 * i), Vec3(-i, 0.5 * i, 1), 0.25 * (i + 1), 0.125 * (i + 1), 300 + i, i % 3, 100 + i,
          Mat3::Identity() * (i + 1));
    p.displacement.back() = Vec3(i, i, i);
    p.external_force.back() = Vec3(0, 0, i);
    p.F.back() = Mat3::Identity() * (1 + 0.01 * i);
    p.stress.back() = Mat3::Constant(i);
    p.volume.back() = 0.5 * (i + 1);
    p.wave_speed.back() = 10 + i;
    p.energy_density.back() = 20 + i;
    p.q.back() = 30 + i;
  }
  p.history.resize(2);
  for (int i = 0; i < n; ++i) {
    p.history[0].push_back(1000 + i);
    for (int c = 0; c < 9; ++c) p.history[1].push_back(10 * i + c);
  }
  return p;
}

TEST(ParticleDeletion, RemovesRowsFromEveryColumnAndKeepsTheRest) {
  const Particles before = numbered(6);
  Particles p = before;
  std::vector<double> scratch = {0, 1, 2, 3, 4, 5};
  std::vector<Mat3> scratch_mat(6);
  for (int i = 0; i < 6; ++i) scratch_mat[i] = Mat3::Constant(i);
  remove_particles(p, {1, 0, 1, 1, 0, 1}, {&scratch}, {&scratch_mat});
  const int kept[4] = {0, 2, 3, 5};
  ASSERT_EQ(p.size(), 4u);
  for (int j = 0; j < 4; ++j) {
    const int i = kept[j];
    EXPECT_EQ(p.x[j], before.x[i]);
    EXPECT_EQ(p.v[j], before.v[i]);
    EXPECT_EQ(p.displacement[j], before.displacement[i]);
    EXPECT_EQ(p.external_force[j], before.external_force[i]);
    EXPECT_EQ(p.F[j], before.F[i]);
    EXPECT_EQ(p.stress[j], before.stress[i]);
    EXPECT_EQ(p.psize[j], before.psize[i]);
    EXPECT_EQ(p.mass[j], before.mass[i]);
    EXPECT_EQ(p.volume[j], before.volume[i]);
    EXPECT_EQ(p.volume0[j], before.volume0[i]);
    EXPECT_EQ(p.temperature[j], before.temperature[i]);
    EXPECT_EQ(p.color[j], before.color[i]);
    EXPECT_EQ(p.wave_speed[j], before.wave_speed[i]);
    EXPECT_EQ(p.energy_density[j], before.energy_density[i]);
    EXPECT_EQ(p.q[j], before.q[i]);
    EXPECT_EQ(p.id[j], before.id[i]);
    EXPECT_EQ(p.history[0][j], before.history[0][i]);
    for (int c = 0; c < 9; ++c) EXPECT_EQ(p.history[1][9 * j + c], before.history[1][9 * i + c]);
    EXPECT_EQ(scratch[j], double(i));
    EXPECT_EQ(scratch_mat[j], Mat3::Constant(i));
  }
  EXPECT_EQ(p.history[1].size(), 36u);
}

TEST(ParticleDeletion, VaangoCriteria) {
  Particles p = numbered(5);
  const std::vector<Vec3> v_old(5, Vec3(1, 0, 0));
  p.mass[1] = 1e-16;                 // <= 3e-15: deleted
  p.temperature[2] = -1.0;           // T < 0: deleted
  p.v[3] = Vec3(0, 0, 50.0);         // faster than 10, grew: clamped to 9 along z
  p.v[4] = Vec3(0, -20.0, 0);        // faster than 10, grew: clamped
  ParticleLimits limits;
  limits.maximum_speed = 10.0;
  std::vector<DeletedParticle> deleted;
  std::vector<char> keep = apply_particle_limits(limits, v_old, p, deleted);
  EXPECT_EQ(keep, (std::vector<char>{1, 0, 0, 1, 1}));
  ASSERT_EQ(deleted.size(), 2u);
  EXPECT_EQ(deleted[0].id, 101);
  EXPECT_EQ(deleted[0].mass, 1e-16);
  EXPECT_EQ(deleted[1].id, 102);
  EXPECT_NEAR((p.v[3] - Vec3(0, 0, 9.0)).norm(), 0.0, 1e-14);
  EXPECT_NEAR((p.v[4] - Vec3(0, -9.0, 0)).norm(), 0.0, 1e-14);
  // A rogue particle that is slowing down keeps its velocity (Vaango clamps only a growing speed).
  Particles q = numbered(1);
  q.v[0] = Vec3(20, 0, 0);
  deleted.clear();
  apply_particle_limits(limits, {Vec3(30, 0, 0)}, q, deleted);
  EXPECT_EQ(q.v[0], Vec3(20, 0, 0));
  // With delete_rogue_particles the fast ones are deleted instead.
  Particles r = numbered(2);
  r.v[1] = Vec3(11, 0, 0);
  limits.delete_rogue = true;
  deleted.clear();
  EXPECT_EQ(apply_particle_limits(limits, std::vector<Vec3>(2, Vec3::Zero()), r, deleted), (std::vector<char>{1, 0}));
  EXPECT_EQ(deleted.size(), 1u);
}

MpmSetup free_block() {
  MpmSetup s;
  s.grid.lower = Vec3::Zero();
  s.grid.upper = Vec3::Ones();
  s.grid.cells = IntVec3::Constant(4);
  s.grid.dx = Vec3::Constant(0.25);
  s.grid.patches.push_back(Patch{0, IntVec3::Zero(), s.grid.cells});
  MpmMaterial m;
  m.density = 1024.0;  // particle mass 1024 * (1/8)^3 = 2 kg: dyadic, sums exact
  m.specific_heat = 1.0;
  m.model = std::make_shared<CompNeoHookean>(CompNeoHookeanParams{1e5, 1e5});
  ParticleSource src;
  src.piece = std::make_shared<BoxPiece>(Vec3::Constant(0.25), Vec3::Constant(0.75));
  src.res = IntVec3::Constant(2);
  src.velocity = Vec3(0.1, 0, 0);
  src.temperature = 300.0;
  m.sources.push_back(src);
  s.materials.push_back(std::move(m));
  return s;
}

TEST(ParticleDeletion, ComponentDeletesALightParticleAndItsMassLeavesTotalMassExactly) {
  MpmComponent c(free_block());
  c.initialize();
  Particles& p = c.materials()[0].particles;
  const std::size_t n = p.size();
  const double M0 = c.reductions({"TotalMass"}).at("TotalMass")[0];
  EXPECT_EQ(M0, 2.0 * double(n));
  // A particle of zero mass is an exact zero in every grid sum: the run with
  // it deleted equals the run without it, column by column.
  const long long victim = p.id[5];
  p.mass[5] = 0.0;
  MpmComponent ref(free_block());
  ref.initialize();
  Particles& pr = ref.materials()[0].particles;
  remove_particles(pr, [&] {
    std::vector<char> k(n, 1);
    k[5] = 0;
    return k;
  }());
  c.advance(0.0, 1e-4, 1);
  ref.advance(0.0, 1e-4, 1);
  ASSERT_EQ(p.size(), n - 1);
  for (long long id : p.id) EXPECT_NE(id, victim);
  EXPECT_EQ(c.deleted_mass(), 0.0);
  EXPECT_EQ(c.reductions({"TotalMass"}).at("TotalMass")[0], 2.0 * double(n - 1));
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.id[i], pr.id[i]);
    EXPECT_EQ(p.x[i], pr.x[i]);
    EXPECT_EQ(p.v[i], pr.v[i]);
    EXPECT_EQ(p.F[i], pr.F[i]);
    EXPECT_EQ(p.stress[i], pr.stress[i]);
  }
}

TEST(ParticleDeletion, ComponentReportsTheDeletedMass) {
  MpmSetup s = free_block();
  s.flags.minimum_particle_mass = 1.5;  // below every particle but the one we lighten
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  const std::size_t n = p.size();
  p.mass[0] = 1.0;  // 1 kg <= 1.5 kg: deleted at the end of the step
  c.advance(0.0, 1e-4, 1);
  EXPECT_EQ(p.size(), n - 1);
  EXPECT_EQ(c.deleted_mass(), 1.0);
  EXPECT_EQ(c.reductions({"TotalMass"}).at("TotalMass")[0], 2.0 * double(n - 1));
}


// Uintah's relocation rule (Schedulers/Relocate.cc): a particle found in no
// patch after its position update is deleted. Interior box [0,1]^3, y periodic.
TEST(ParticleDeletion, ParticleOutsideTheDomainIsDeletedNamingTheFace) {
  Grid g;
  g.lower = Vec3::Zero();
  g.upper = Vec3::Ones();
  g.periodic = IntVec3(0, 1, 0);
  Particles p = numbered(4);
  p.x[0] = Vec3(0.5, 0.5, 0.5);   // inside
  p.x[1] = Vec3(1.01, 0.5, 0.5);  // beyond x+: deleted
  p.x[2] = Vec3(0.5, 1.7, 0.5);   // y is periodic: not a face (wrapped elsewhere)
  p.x[3] = Vec3(0.5, 0.5, 0.0);   // on the z- face: inside
  ParticleLimits limits;
  limits.domain = &g;
  std::vector<DeletedParticle> deleted;
  EXPECT_EQ(apply_particle_limits(limits, std::vector<Vec3>(4, Vec3::Zero()), p, deleted),
            (std::vector<char>{1, 0, 1, 1}));
  ASSERT_EQ(deleted.size(), 1u);
  EXPECT_EQ(deleted[0].id, 101);
  EXPECT_NE(deleted[0].reason.find("left the domain through its x+ face"), std::string::npos) << deleted[0].reason;
  int d = -1;
  EXPECT_TRUE(outside_domain(g, Vec3(0.5, 0.5, -1e-12), &d));
  EXPECT_EQ(d, 2);
  EXPECT_FALSE(outside_domain(g, Vec3(0.5, -3.0, 1.0)));
}

// A block moving at 100 m/s towards x+ (interior [0,1], h = 0.25, no extra
// cells): every particle that crosses the face is deleted at the end of its
// step, its mass counted in deleted_mass(); the run goes on (Uintah and Vaango
// run such decks to their end, e.g. JWLppCuRS2d's copper at its x+ face).
TEST(ParticleDeletion, ParticlesLeavingThroughAFaceAreDeletedAndTheRunGoesOn) {
  MpmSetup s = free_block();
  s.materials[0].sources[0].velocity = Vec3(100.0, 0, 0);
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  const std::size_t n = p.size();
  const double dt = 1e-3;  // 0.1 m per step, less than a cell
  double t = 0.0;
  for (int step = 1; step <= 6 && p.size() > 0; ++step, t += dt) ASSERT_NO_THROW(c.advance(t, dt, step));
  EXPECT_LT(p.size(), n);  // the leading layers (x = 0.6875, 0.5625 + 0.1 k) have crossed x = 1
  for (const Vec3& x : p.x) EXPECT_LE(x[0], 1.0);
  EXPECT_EQ(c.deleted_mass(), 2.0 * double(n - p.size()));  // 2 kg each (free_block)
  EXPECT_EQ(c.reductions({"TotalMass"}).at("TotalMass")[0], 2.0 * double(p.size()));
}

// <test_for_neg_temps_mpm> (default true, mpm/MpmFlags.h): a particle at
// T < 0 K after the step's temperature update stops the run with a
// NumericalFailure (exit 4) naming the particle id, its material and the step;
// with the check off the deletion rule removes it instead.
TEST(ParticleDeletion, NegativeTemperatureStopsTheRunNamingParticleMaterialAndStep) {
  MpmComponent c(free_block());
  c.initialize();
  Particles& p = c.materials()[0].particles;
  c.advance(0.0, 1e-4, 1);  // all at 300 K: no failure
  p.temperature[3] = -2.5;  // no conduction (k = 0): it stays negative through the step
  const long long id = p.id[3];
  try {
    c.advance(1e-4, 1e-4, 2);
    ADD_FAILURE() << "no NumericalFailure";
  } catch (const NumericalFailure& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("MPM step 2"), std::string::npos) << what;
    EXPECT_NE(what.find("material 0 particle id " + std::to_string(id)), std::string::npos) << what;
    EXPECT_NE(what.find("negative temperature T = -2.5 K"), std::string::npos) << what;
    EXPECT_EQ(e.code(), ExitCode::NumericalFailure);
  }
}

TEST(ParticleDeletion, NegativeTemperatureIsDeletedWhenTheCheckIsOff) {
  MpmSetup s = free_block();
  s.flags.test_for_negative_temperatures = false;
  MpmComponent c(std::move(s));
  c.initialize();
  Particles& p = c.materials()[0].particles;
  const std::size_t n = p.size();
  p.temperature[3] = -2.5;
  EXPECT_NO_THROW(c.advance(0.0, 1e-4, 1));
  EXPECT_EQ(p.size(), n - 1);
  EXPECT_EQ(c.deleted_mass(), 2.0);
}

TEST(ParticleDeletion, NegativeTemperatureFlagSpellings) {
  auto flags = [](const std::string& mpm) {
    auto d = load_deck_from_string("<Uintah_specification><MPM>" + mpm + "</MPM></Uintah_specification>", "t.ups", ".");
    return parse_mpm_flags(d->root.child("MPM")).test_for_negative_temperatures;
  };
  EXPECT_TRUE(flags(""));  // Vaango's default
  EXPECT_FALSE(flags("<test_for_neg_temps_mpm>false</test_for_neg_temps_mpm>"));
  EXPECT_FALSE(flags("<testForNegTemps_mpm>false</testForNegTemps_mpm>"));
  EXPECT_TRUE(flags("<testForNegTemps_mpm>true</testForNegTemps_mpm>"));
  EXPECT_THROW(flags("<test_for_neg_temps_mpm>maybe</test_for_neg_temps_mpm>"), DeckError);
}

}  // namespace
}  // namespace tephra
