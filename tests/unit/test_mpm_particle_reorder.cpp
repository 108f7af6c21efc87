// The particle columns kept in scatter order (mpm/ParticleReorder.h). Claims:
//   * permute_particles moves EVERY column by the same permutation: after it,
//     each particle's full state (all columns, every history component) is
//     found exactly once, under its id, equal bit for bit to the state before
//     (also above kReorderMinParticles, where the copy is threaded, 1 and 2 threads);
//   * a run that reorders (4608 particles, above kReorderMinParticles) gives,
//     particle by particle (matched by id), the state of a run that does not, to round-off: only the order of the node
//     sums changes (measured after 60 steps: x 2.8e-16, v 8.5e-15, F 1.7e-15,
//     stress 2.6e-14 of each field's largest value; bound 1e-12);
//   * the reordering run leaves the columns in scatter order (few displaced),
//     writes its output in ascending id (the same layout as the unordered run),
//     and gives the same bits for 1, 2 and 3 threads.
#include <gtest/gtest.h>

#include <map>
#include <numeric>
#include <random>

#include "core/deck/DeckLoader.h"
#include "core/grid/Loop.h"
#include "core/io/OutputFrame.h"
#include "mpm/MpmComponent.h"
#include "mpm/ParticleReorder.h"
#include "mpm/shape/ScatterOrder.h"
#include "tests/support/ThreadCountScope.h"

namespace tephra {
namespace {

// Every value of particle i, in a fixed column order.
std::vector<double> state_of(const Particles& p, std::size_t i) {
  std::vector<double> s;
  auto put = [&](const auto& m) { s.insert(s.end(), m.data(), m.data() + m.size()); };
  put(p.x[i]), put(p.v[i]), put(p.displacement[i]), put(p.external_force[i]);
  put(p.F[i]), put(p.stress[i]), put(p.psize[i]);
  for (const std::vector<double>* c : {&p.mass, &p.volume, &p.volume0, &p.temperature, &p.color, &p.wave_speed,
                                       &p.energy_density, &p.q})
    s.push_back((*c)[i]);
  for (const std::vector<double>& h : p.history) {
    const std::size_t per = h.size() / p.size();
    s.insert(s.end(), h.begin() + long(i * per), h.begin() + long((i + 1) * per));
  }
  return s;
}

// n below and above kReorderMinParticles (the copy is threaded from there on),
// with 1 and 2 threads.
void check_permutation(std::size_t n, int threads) {
  const ThreadCountScope use(threads);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Particles p;
  for (std::size_t i = 0; i < n; ++i) {
    p.add(Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)), u(rng), u(rng), u(rng), u(rng),
          1000 + long(i), Mat3::Random());
    p.displacement.back() = Vec3::Random();
    p.external_force.back() = Vec3::Random();
    p.F.back() = Mat3::Random();
    p.stress.back() = Mat3::Random();
    p.wave_speed.back() = u(rng);
    p.energy_density.back() = u(rng);
    p.q.back() = u(rng);
  }
  // History columns of 1, 6 and 12 components per particle (12 > 72 B: the own-buffer path).
  for (std::size_t per : {1u, 6u, 12u}) {
    std::vector<double> h(n * per);
    for (double& v : h) v = u(rng);
    p.history.push_back(std::move(h));
  }
  std::map<long long, std::vector<double>> before;
  for (std::size_t i = 0; i < n; ++i) before[p.id[i]] = state_of(p, i);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), rng);
  const std::vector<long long> ids = p.id;
  std::vector<Mat3> scratch;  // empty: permute_particles sizes it
  permute_particles(p, order, scratch);
  ASSERT_EQ(p.size(), n);
  std::map<long long, int> found;
  for (std::size_t j = 0; j < n; ++j) {
    EXPECT_EQ(p.id[j], ids[order[j]]) << j;  // column[j] = old column[order[j]]
    ++found[p.id[j]];
    EXPECT_EQ(state_of(p, j), before.at(p.id[j])) << "id " << p.id[j];
  }
  EXPECT_EQ(found.size(), n);
  for (const auto& [id, k] : found) EXPECT_EQ(k, 1) << "id " << id;
}

TEST(MpmParticleReorder, PermutesEveryColumnTogether) {
  for (std::size_t n : {3000u, 9001u})
    for (int threads : {1, 2}) {
      SCOPED_TRACE("n = " + std::to_string(n) + ", threads = " + std::to_string(threads));
      check_permutation(n, threads);
    }
}

// The rule: reorder when more than np / 16 particles are displaced, and only
// from 4096 particles on (ParticleReorder.h).
TEST(MpmParticleReorder, WhenToReorder) {
  ScatterOrder o;
  for (std::size_t np : {1000u, 4095u, 4096u, 8000u}) {
    o.particles = np;
    o.index.assign(np, 0u);
    o.displaced = np / 16;  // exactly the line: not above it
    EXPECT_FALSE(reorder_worthwhile(o, np)) << np;
    o.displaced = np / 16 + 1;
    EXPECT_EQ(reorder_worthwhile(o, np), np >= 4096) << np;
    EXPECT_FALSE(reorder_worthwhile(o, np + 1)) << np;  // an order built for another count
  }
}

// Two hypo-elastic blocks moving into each other across several cells (GIMP).
std::string deck() {
  return "<Uintah_specification><MPM><interpolator>gimp</interpolator></MPM>"
         "<MaterialProperties><MPM><material><density>1000</density>"
         "<constitutive_model type='hypo_elastic'><G>1e6</G><K>2e6</K></constitutive_model>"
         "<thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
         "<geom_object><box><min>[0.05,0.1,0.1]</min><max>[0.2,0.3,0.25]</max></box><res>[2,2,2]</res>"
         "<velocity>[4,1,0.5]</velocity><temperature>300</temperature></geom_object>"
         "<geom_object><box><min>[0.25,0.12,0.12]</min><max>[0.4,0.32,0.27]</max></box><res>[2,2,2]</res>"
         "<velocity>[-4,-1,-0.5]</velocity><temperature>300</temperature></geom_object>"
         "</material></MPM></MaterialProperties>"
         "<Grid><Level><Box><lower>[0,0,0]</lower><upper>[0.45,0.45,0.4]</upper>"
         "<resolution>[18,18,16]</resolution><extraCells>[1,1,1]</extraCells><patches>[1,1,1]</patches></Box>"
         "</Level></Grid></Uintah_specification>";
}

struct DeckRun {
  std::unique_ptr<MpmComponent> c;
  DeckRun(bool reorder, int steps) {
    auto d = load_deck_from_string(deck(), "reorder.ups", ".");
    c = make_mpm_component(*d);
    c->set_particle_reordering(reorder);
    c->initialize();
    const double dt = 2e-4;  // c = sqrt((K + 4G/3)/rho) = 57.7 m/s, h = 0.025 m: CFL 0.5
    for (int k = 0; k < steps; ++k) c->advance(k * dt, dt, k + 1);
  }
  const Particles& p() const { return c->materials().front().particles; }
};

constexpr int kSteps = 60;  // 0.012 s: the blocks move 0.048 m = 2 cells in x and meet

TEST(MpmParticleReorder, SameStatesByIdAsTheUnorderedRun) {
  const DeckRun plain(false, kSteps), ordered(true, kSteps);
  const Particles &a = plain.p(), &b = ordered.p();
  ASSERT_EQ(a.size(), b.size());
  ASSERT_GE(a.size(), kReorderMinParticles);  // large enough to be reordered
  EXPECT_TRUE(std::is_sorted(a.id.begin(), a.id.end()));    // never reordered
  EXPECT_FALSE(std::is_sorted(b.id.begin(), b.id.end()));   // reordered
  std::map<long long, std::size_t> where;
  for (std::size_t j = 0; j < b.size(); ++j) where[b.id[j]] = j;
  ASSERT_EQ(where.size(), b.size());
  double max_x = 0, max_v = 0, max_F = 0, max_s = 0, dx = 0, dv = 0, dF = 0, ds = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = where.at(a.id[i]);
    max_x = std::max(max_x, a.x[i].cwiseAbs().maxCoeff());
    max_v = std::max(max_v, a.v[i].cwiseAbs().maxCoeff());
    max_F = std::max(max_F, a.F[i].cwiseAbs().maxCoeff());
    max_s = std::max(max_s, a.stress[i].cwiseAbs().maxCoeff());
    dx = std::max(dx, (a.x[i] - b.x[j]).cwiseAbs().maxCoeff());
    dv = std::max(dv, (a.v[i] - b.v[j]).cwiseAbs().maxCoeff());
    dF = std::max(dF, (a.F[i] - b.F[j]).cwiseAbs().maxCoeff());
    ds = std::max(ds, (a.stress[i] - b.stress[j]).cwiseAbs().maxCoeff());
    EXPECT_EQ(a.mass[i], b.mass[j]);
    EXPECT_EQ(a.volume0[i], b.volume0[j]);
  }
  ASSERT_GT(max_s, 1.0);  // the blocks are stressed (Pa): the comparison covers the stress update
  std::printf("reorder vs none, relative: x %.2e v %.2e F %.2e stress %.2e\n", dx / max_x, dv / max_v, dF / max_F,
              ds / max_s);
  EXPECT_LE(dx, 1e-12 * max_x);
  EXPECT_LE(dv, 1e-12 * max_v);
  EXPECT_LE(dF, 1e-12 * max_F);
  EXPECT_LE(ds, 1e-12 * max_s);
  // The columns are in (nearly) the scatter order of the last step's stencils.
  const ScatterOrder& o = ordered.c->materials().front().stencils.order;
  EXPECT_LE(o.displaced * kReorderFraction, b.size());
  // Output in ascending id: the same ids and positions layout as the unordered run.
  OutputFrame fa, fb;
  plain.c->fill_output({"p.stress", "p.velocity"}, fa);
  ordered.c->fill_output({"p.stress", "p.velocity"}, fb);
  ASSERT_EQ(fa.particles.size(), 1u);
  ASSERT_EQ(fb.particles.size(), 1u);
  EXPECT_EQ(fa.particles[0].id, fb.particles[0].id);
  const FieldArray* stress = nullptr;
  for (const FieldArray& f : fb.particles[0].fields)
    if (f.label == "p.stress") stress = &f;
  ASSERT_NE(stress, nullptr);
  ASSERT_EQ(stress->values.size(), 9 * a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::size_t j = where.at(fb.particles[0].id[i]);
    EXPECT_EQ(fb.particles[0].position[i], b.x[j]);
    for (int k = 0; k < 9; ++k) ASSERT_EQ(stress->values[9 * i + k], b.stress[j](k / 3, k % 3)) << i;  // row-major
  }
}

TEST(MpmParticleReorder, SameBitsForAnyThreadCount) {
  std::vector<Vec3> x1;
  std::vector<long long> id1;
  for (int threads : {1, 2, 3}) {
    ThreadCountScope t(threads);
    const DeckRun r(true, kSteps);
    if (threads == 1) {
      x1 = r.p().x, id1 = r.p().id;
      continue;
    }
    EXPECT_EQ(r.p().id, id1) << threads << " threads";  // the same storage order
    EXPECT_EQ(r.p().x, x1) << threads << " threads";    // bit for bit
  }
}

}  // namespace
}  // namespace tephra
