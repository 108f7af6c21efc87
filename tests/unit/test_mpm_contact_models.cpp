// Contact models on synthetic node data (mpm/contact/).
//
// Oracles:
//  * Momentum: every model but specified corrects the velocities of two or more
//    bodies at a node so that sum_a m_a v_a is unchanged (equal and opposite
//    exchanges with one normal per body pair). Checked on random data with
//    2-4 materials, random masses (some zero), velocities, stresses and
//    gradients, at both stages, to round-off: |Delta P| <= 1e-13 sum m |v|.
//  * single_velocity: every body with mass at a contact node ends with
//    v_cm = sum m v / sum m (VT eq. 1.109).
//  * Coulomb (VT eqs. 1.113-1.115): stick when |dv_t| <= mu |dv_n| (both
//    bodies end with v_cm); slip otherwise: normal relative velocity removed and
//    the tangential impulse equals mu times the normal impulse.
//  * approach acts only on approaching pairs (dv_n > 0).
//  * specified: master gets the prescribed velocity, the other bodies the
//    components selected by <direction>; profile interpolated linearly in t.
#include <gtest/gtest.h>

#include <fstream>
#include <random>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

struct RandomNodes {
  std::vector<NodeGrid> grids;
  std::vector<std::vector<Vec3>> gradient, position;
  ContactNodes nodes;

  RandomNodes(int materials, unsigned seed, ContactStage stage) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    grids.resize(materials);
    gradient.resize(materials);
    position.resize(materials);
    for (int m = 0; m < materials; ++m) {
      NodeGrid& g = grids[m];
      g.n = IntVec3(4, 3, 5);
      g.h = Vec3(0.1, 0.2, 0.15);
      g.reset();
      for (std::size_t i = 0; i < g.count(); ++i) {
        g.mass[i] = u(rng) > -0.3 ? (1.5 + u(rng)) * std::pow(10.0, 2 * u(rng)) : 0.0;
        g.volume[i] = g.mass[i] > 0 ? 1e-3 * (1.2 + u(rng)) : 0.0;
        g.velocity[i] = Vec3(u(rng), u(rng), u(rng));
        g.velocity_star[i] = Vec3(u(rng), u(rng), u(rng));
        Mat3 s;
        for (int r = 0; r < 9; ++r) s(r / 3, r % 3) = 1e5 * u(rng);
        g.stress[i] = 0.5 * (s + s.transpose());
        gradient[m].push_back(Vec3(u(rng), u(rng), u(rng)));
        position[m].push_back(Vec3(u(rng), u(rng), u(rng)) * 0.05);
      }
    }
    for (NodeGrid& g : grids) {
      nodes.grid.push_back(&g);
      nodes.velocity.push_back(stage == ContactStage::Interpolated ? &g.velocity : &g.velocity_star);
    }
    nodes.gradient = gradient;
    nodes.position = position;
    nodes.h = grids[0].h;
    nodes.dt = 1e-3;
    nodes.t = 0.0;
  }
  Vec3 momentum(std::size_t node) const {
    Vec3 p = Vec3::Zero();
    for (std::size_t m = 0; m < grids.size(); ++m) p += grids[m].mass[node] * (*nodes.velocity[m])[node];
    return p;
  }
  double scale(std::size_t node) const {
    double s = 0;
    for (std::size_t m = 0; m < grids.size(); ++m) s += grids[m].mass[node] * (*nodes.velocity[m])[node].norm();
    return s;
  }
};

std::vector<int> all(int n) {
  std::vector<int> v;
  for (int i = 0; i < n; ++i) v.push_back(i);
  return v;
}

std::vector<ContactModelP> conserving_models(int materials) {
  FrictionParameters p;
  p.materials = all(materials);
  p.mu = 0.4;
  std::vector<ContactModelP> out;
  out.push_back(std::make_unique<SingleVelocityContact>(p.materials));
  out.push_back(std::make_unique<FrictionContact>(p));
  out.push_back(std::make_unique<FrictionBardContact>(p, 9.9e99, 2));
  out.push_back(std::make_unique<FrictionBardContact>(p, 0.5, 2));  // with the separation test
  out.push_back(std::make_unique<ApproachContact>(p));
  out.push_back(std::make_unique<NodalSvfContact>(0, materials - 1, 50.0, true));
  out.push_back(std::make_unique<NodalSvfContact>(0, materials - 1, 50.0, false));
  return out;
}

TEST(MpmContactModels, EveryPairwiseModelConservesMomentumToRoundOff) {
  for (int materials = 2; materials <= 4; ++materials)
    for (ContactStage stage : {ContactStage::Interpolated, ContactStage::Integrated})
      for (std::size_t k = 0; k < conserving_models(materials).size(); ++k) {
        RandomNodes r(materials, 17u + unsigned(materials) * 7u + unsigned(k), stage);
        const ContactModelP m = std::move(conserving_models(materials)[k]);
        const std::string model = m->type();
        std::vector<Vec3> before;
        for (std::size_t g = 0; g < r.nodes.nodes(); ++g) before.push_back(r.momentum(g));
        std::vector<std::vector<Vec3>> v0;
        for (auto* v : r.nodes.velocity) v0.push_back(*v);
        m->exchange(stage, r.nodes);
        int changed = 0;
        for (std::size_t g = 0; g < r.nodes.nodes(); ++g) {
          EXPECT_LE((r.momentum(g) - before[g]).norm(), 1e-13 * r.scale(g))
              << model << " materials " << materials << " node " << g;
          for (int a = 0; a < materials; ++a) changed += (*r.nodes.velocity[a])[g] != v0[a][g];
        }
        EXPECT_GT(changed, 0) << model << ": the random data must exercise the model";
      }
}

TEST(MpmContactModels, SingleVelocityGivesTheCentreOfMassVelocity) {
  RandomNodes r(3, 5u, ContactStage::Interpolated);
  std::vector<std::vector<Vec3>> v0;
  for (auto* v : r.nodes.velocity) v0.push_back(*v);
  SingleVelocityContact(all(3)).exchange(ContactStage::Interpolated, r.nodes);
  for (std::size_t g = 0; g < r.nodes.nodes(); ++g) {
    double m = 0;
    int with_mass = 0;
    Vec3 p = Vec3::Zero();
    for (int a = 0; a < 3; ++a) {
      m += r.grids[a].mass[g];
      p += r.grids[a].mass[g] * v0[a][g];
      with_mass += r.grids[a].mass[g] > 0;
    }
    for (int a = 0; a < 3; ++a) {
      if (r.grids[a].mass[g] == 0.0 || with_mass < 2) {
        EXPECT_EQ((*r.nodes.velocity[a])[g], v0[a][g]);  // untouched
      } else {
        EXPECT_LE(((*r.nodes.velocity[a])[g] - p / m).norm(), 1e-14 * (p / m).norm() + 1e-300);
      }
    }
  }
}

// Two bodies at one node, normal +z out of a into b; a approaches b with
// normal speed w and slides along x with speed s; b at rest.
ContactPair pair(double ma, double mb, double w, double s) {
  ContactPair p;
  p.ma = ma;
  p.mb = mb;
  p.va = Vec3(s, 0, w);  // n = +z points from a into b: dv_n > 0 means approach
  p.vb = Vec3(0, 0, 0);
  p.n = Vec3::UnitZ();
  return p;
}

TEST(MpmContactModels, CoulombSticksBelowTheFrictionLimitAndSlipsAboveIt) {
  const Vec3 h(1, 1, 1);
  const double dt = 1e-6;  // the strain limiter is inactive
  const double mu = 0.5;
  {
    // |dv_t| / |dv_n| = s / w = 0.4 <= mu: stick, both end with v_cm.
    ContactPair p = pair(2.0, 3.0, 1.0, 0.4);
    const Vec3 dp = coulomb_exchange(p, mu, h, dt);
    const Vec3 va = p.va + dp / p.ma, vb = p.vb - dp / p.mb;
    const Vec3 vcm = (p.ma * p.va + p.mb * p.vb) / (p.ma + p.mb);
    EXPECT_LE((va - vcm).norm(), 1e-15);
    EXPECT_LE((vb - vcm).norm(), 1e-15);
  }
  {
    // s / w = 2 > mu: slip. Normal relative velocity removed; the tangential
    // impulse is mu times the normal impulse; the sliding continues.
    ContactPair p = pair(2.0, 3.0, 1.0, 2.0);
    const Vec3 dp = coulomb_exchange(p, mu, h, dt);
    const Vec3 va = p.va + dp / p.ma, vb = p.vb - dp / p.mb;
    EXPECT_NEAR(va[2] - vb[2], 0.0, 1e-15);
    EXPECT_NEAR(std::abs(dp[0]), mu * std::abs(dp[2]), 1e-15);
    EXPECT_LT(dp[0], 0.0);  // friction opposes a's sliding
    EXPECT_GT(va[0] - vb[0], 0.0);
    // Closed form: dp_n = -m_eff w, dp_t = -mu m_eff w, m_eff = ma mb/(ma+mb) (eq. 1.106).
    const double meff = 2.0 * 3.0 / 5.0;
    EXPECT_NEAR(dp[2], -meff * 1.0, 1e-15);
    EXPECT_NEAR(dp[0], -mu * meff * 1.0, 1e-15);
  }
  {
    // mu = 0: frictionless, only the normal part changes.
    ContactPair p = pair(1.0, 1.0, 1.0, 3.0);
    const Vec3 dp = coulomb_exchange(p, 0.0, h, dt);
    EXPECT_EQ(dp[0], 0.0);
    EXPECT_NEAR(dp[2], -0.5, 1e-15);
  }
}

TEST(MpmContactModels, ApproachActsOnlyWhenApproaching) {
  // Two materials on a single node grid; a (0) has gradient +z (normal out of a
  // towards b), b (1) gradient -z.
  std::vector<NodeGrid> g(2);
  for (NodeGrid& x : g) {
    x.n = IntVec3(2, 2, 2);
    x.reset();
    x.mass.assign(8, 1.0);
    x.volume.assign(8, 1.0);
  }
  FrictionParameters p;
  p.materials = {0, 1};
  p.mu = 0.3;
  ApproachContact model(p);
  for (double w : {+1.0, -1.0}) {
    g[0].velocity.assign(8, Vec3(0, 0, w));
    g[1].velocity.assign(8, Vec3::Zero());
    ContactNodes n;
    n.grid = {&g[0], &g[1]};
    n.velocity = {&g[0].velocity, &g[1].velocity};
    n.gradient = {std::vector<Vec3>(8, Vec3::UnitZ()), std::vector<Vec3>(8, -Vec3::UnitZ())};
    n.h = Vec3::Ones();
    n.dt = 1e-6;
    model.exchange(ContactStage::Integrated, n);
    if (w > 0) {
      EXPECT_NEAR(g[0].velocity[3][2], 0.5, 1e-15);  // v_cm
      EXPECT_NEAR(g[1].velocity[3][2], 0.5, 1e-15);
    } else {
      EXPECT_EQ(g[0].velocity[3], Vec3(0, 0, -1));  // separating: untouched
      EXPECT_EQ(g[1].velocity[3], Vec3::Zero());
    }
  }
}

TEST(MpmContactModels, SpecifiedImposesTheMasterVelocity) {
  std::vector<NodeGrid> g(2);
  for (NodeGrid& x : g) {
    x.n = IntVec3(2, 2, 2);
    x.reset();
    x.volume.assign(8, 1.0);
  }
  g[0].mass.assign(8, 1.0);
  g[0].mass[0] = 0.0;  // no master at node 0: untouched
  g[1].mass.assign(8, 1.0);
  g[0].velocity.assign(8, Vec3(0, 0, -2));  // the master's interpolated velocity
  g[0].velocity_star.assign(8, Vec3(0.1, 0.2, -2.5));
  g[1].velocity_star.assign(8, Vec3(1, 2, 3));
  auto run = [&](const SpecifiedParameters& p, double t) {
    g[0].velocity_star.assign(8, Vec3(0.1, 0.2, -2.5));
    g[1].velocity_star.assign(8, Vec3(1, 2, 3));
    ContactNodes n;
    n.grid = {&g[0], &g[1]};
    n.velocity = {&g[0].velocity_star, &g[1].velocity_star};
    n.h = Vec3::Ones();
    n.t = t;
    n.dt = 1e-3;
    SpecifiedContact(p).exchange(ContactStage::Integrated, n);
  };
  SpecifiedParameters p;
  p.materials = {0, 1};
  run(p, 0.0);  // rigid velocity: the master keeps v_g; direction [0,0,1]
  EXPECT_EQ(g[0].velocity_star[3], Vec3(0, 0, -2));
  EXPECT_EQ(g[1].velocity_star[3], Vec3(1, 2, -2));
  EXPECT_EQ(g[1].velocity_star[0], Vec3(1, 2, 3));
  p.stop_time = 1.0;
  p.velocity_after_stop = Vec3(0, 0, 4);
  p.direction = IntVec3(1, 1, 1);
  run(p, 1.5);
  EXPECT_EQ(g[0].velocity_star[5], Vec3(0, 0, 4));
  EXPECT_EQ(g[1].velocity_star[5], Vec3(0, 0, 4));
  // Profile: linear between rows, end values outside.
  p.stop_time = 100;
  p.profile = {{0.0, Vec3(0, 0, 0)}, {2.0, Vec3(2, 4, 6)}};
  Vec3 v;
  ASSERT_TRUE(SpecifiedContact(p).imposed_velocity(0.5, v));
  EXPECT_LE((v - Vec3(0.5, 1, 1.5)).norm(), 1e-15);
  ASSERT_TRUE(SpecifiedContact(p).imposed_velocity(7.0, v));
  EXPECT_EQ(v, Vec3(2, 4, 6));
  SpecifiedParameters rigid;
  EXPECT_FALSE(SpecifiedContact(rigid).imposed_velocity(0.5, v));
}

std::unique_ptr<Deck> deck(const std::string& body) {
  return load_deck_from_string("<Uintah_specification>\n" + body + "</Uintah_specification>", "c.ups", ".");
}

template <class E>
void throws(const std::string& xml) {
  EXPECT_THROW(parse_contact(deck(xml)->root.require_child("contact"), 2), E) << xml;
}

// nodal_svf (Vaango NodalSVFContact): at a node where both materials have
// mass, f_b = k (v_a - v_b), k = myu V_cell phi_a phi_b (use_svf) or
// myu V_cell, phi = w V_g / V_cell, and v_b += f_b dt / (w m_b),
// v_a -= f_b dt / (w m_a), w = 2^(boundary directions of the node).
// Nodes with one material are left alone.
// Vaango's direction-based SpecifiedBodyContact loops over every material and ignores
// <materials>: the Taylor-impact decks (cylinderImpact_*.ups) name only the wall,
// <materials>[0], and the wall still stops the rod. With <direction>[0,1,0] the rod's
// y velocity at a wall node becomes the wall's (0 here), x and z are untouched.
TEST(MpmContactModels, DirectionBasedRigidContactActsOnEveryMaterial) {
  std::vector<NodeGrid> g(2);
  for (NodeGrid& x : g) {
    x.n = IntVec3(2, 2, 2);
    x.reset();
    x.volume.assign(8, 1.0);
    x.mass.assign(8, 1.0);
  }
  g[0].velocity.assign(8, Vec3::Zero());
  g[0].velocity_star.assign(8, Vec3::Zero());
  g[1].velocity_star.assign(8, Vec3(1, -227, 3));
  auto model = parse_contact(deck("<contact><type>rigid</type><materials>[0]</materials><direction>[0,1,0]</direction>"
                                  "</contact>")
                                 ->root.require_child("contact"),
                             2);
  ContactNodes n;
  n.grid = {&g[0], &g[1]};
  n.velocity = {&g[0].velocity_star, &g[1].velocity_star};
  n.h = Vec3::Ones();
  n.t = 0.0;
  n.dt = 1e-3;
  model->exchange(ContactStage::Integrated, n);
  for (int i = 0; i < 8; ++i) EXPECT_EQ(g[1].velocity_star[i], Vec3(1, 0, 3)) << "node " << i;
}

TEST(MpmContactModels, NodalSvfDragIsTheClosedForm) {
  for (bool use_svf : {true, false}) {
    RandomNodes r(2, 31u, ContactStage::Integrated);
    std::vector<Vec3> va0 = *r.nodes.velocity[0], vb0 = *r.nodes.velocity[1];
    const double myu = 50.0;
    NodalSvfContact(0, 1, myu, use_svf).exchange(ContactStage::Integrated, r.nodes);
    const double vc = r.nodes.cell_volume();
    int both = 0;
    for (std::size_t g = 0; g < r.nodes.nodes(); ++g) {
      const double ma = r.grids[0].mass[g], mb = r.grids[1].mass[g];
      const Vec3 va = (*r.nodes.velocity[0])[g], vb = (*r.nodes.velocity[1])[g];
      if (!(ma > 0 && mb > 0)) {
        EXPECT_EQ(va, va0[g]);
        EXPECT_EQ(vb, vb0[g]);
        continue;
      }
      ++both;
      const std::size_t i = g % 4, j = (g / 4) % 3, k = g / 12;  // n = (4, 3, 5)
      const double w = (i == 0 || i == 3 ? 2.0 : 1.0) * (j == 0 || j == 2 ? 2.0 : 1.0) * (k == 0 || k == 4 ? 2.0 : 1.0);
      const double kk = myu * vc * (use_svf ? (w * r.grids[0].volume[g] / vc) * (w * r.grids[1].volume[g] / vc) : 1.0);
      const Vec3 fb = kk * (va0[g] - vb0[g]);
      EXPECT_NEAR((vb - (vb0[g] + fb * r.nodes.dt / (w * mb))).norm(), 0.0, 1e-14 * (1 + vb.norm()));
      EXPECT_NEAR((va - (va0[g] - fb * r.nodes.dt / (w * ma))).norm(), 0.0, 1e-14 * (1 + va.norm()));
    }
    EXPECT_GT(both, 5);
  }
}

TEST(MpmContactModels, ParsingAcceptsVaangoParametersAndRejectsTheRest) {
  EXPECT_EQ(parse_contact(deck("<contact><type>null</type></contact>")->root.require_child("contact"), 2), nullptr);
  // Vaango's null contact ignores <materials> (inputs/MPM/AA.ups lists absent ones).
  EXPECT_EQ(parse_contact(deck("<contact><type>null</type><materials>[1,2,3]</materials></contact>")
                              ->root.require_child("contact"),
                          2),
            nullptr);
  auto f = parse_contact(
      deck("<contact><type> friction </type><mu>0.2</mu><materials>[0,1]</materials></contact>")->root.require_child(
          "contact"),
      2);
  ASSERT_TRUE(f);
  EXPECT_EQ(f->type(), "friction");
  auto r = parse_contact(
      deck("<contact><type>rigid</type><materials>[0,1]</materials><stop_time>9.9</stop_time></contact>")
          ->root.require_child("contact"),
      2);
  EXPECT_EQ(r->type(), "specified");
  EXPECT_FALSE(r->acts_on(ContactStage::Interpolated));
  auto bard1 = parse_contact(deck("<contact><type>friction_bard</type><mu>0.2</mu><one_or_two_step>1</one_or_two_step>"
                                  "</contact>")
                                 ->root.require_child("contact"),
                             2);
  EXPECT_FALSE(bard1->acts_on(ContactStage::Interpolated));
  EXPECT_TRUE(bard1->acts_on(ContactStage::Integrated));

  auto lr = parse_contact(deck("<contact><type>friction_LR</type><mu>0.1</mu><one_or_two_step>1</one_or_two_step>"
                               "</contact>")
                              ->root.require_child("contact"),
                          2);
  ASSERT_TRUE(lr);
  EXPECT_EQ(lr->type(), "friction_LR");
  EXPECT_FALSE(lr->acts_on(ContactStage::Interpolated));
  throws<DeckError>("<contact><type>friction_LR</type></contact>");  // mu required
  throws<DeckError>("<contact><type>friction_LR</type><mu>0.1</mu><myu>1</myu></contact>");
  auto svf = parse_contact(
      deck("<contact><type>nodal_svf</type><myu>1e3</myu><use_svf>true</use_svf></contact>")->root.require_child(
          "contact"),
      2);
  ASSERT_TRUE(svf);
  EXPECT_EQ(svf->type(), "nodal_svf");
  throws<DeckError>("<contact><type>nodal_svf</type><use_svf>true</use_svf></contact>");  // myu required
  throws<DeckError>("<contact><type>nodal_svf</type><myu>1</myu></contact>");            // use_svf required
  throws<DeckError>("<contact><type>nodal_svf</type><myu>1</myu><use_svf>1</use_svf><mu>0.1</mu></contact>");
  throws<DeckError>("<contact><type>nodal_svf</type><myu>-1</myu><use_svf>true</use_svf></contact>");
  throws<MissingFeature>(
      "<contact><type>friction</type><mu>0.1</mu><use_hardcoded_normals>true</use_hardcoded_normals></contact>");
  throws<DeckError>("<contact><type>stick</type></contact>");
  throws<DeckError>("<contact><type>friction</type></contact>");  // mu required
  throws<DeckError>("<contact><type>friction</type><mu>-1</mu></contact>");
  throws<DeckError>("<contact><type>single_velocity</type><mu>0.1</mu></contact>");
  throws<DeckError>("<contact><type>single_velocity</type><materials>[0,2]</materials></contact>");
  throws<DeckError>("<contact><type>rigid</type><direction>[0,2,0]</direction></contact>");
  throws<DeckError>("<contact><type>specified</type><filename>no_such_file.txt</filename></contact>");
  try {
    parse_contact(deck("<contact>\n<type>approach</type>\n<mu>0</mu><separation_factor>2</separation_factor></contact>")
                      ->root.require_child("contact"),
                  2);
    FAIL();
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("c.ups:4"), std::string::npos) << e.what();
  }
  EXPECT_EQ(contact_types(),
            (std::vector<std::string>{"null", "single_velocity", "friction", "friction_bard", "approach", "specified",
                                      "rigid", "nodal_svf", "friction_LR"}));
}

TEST(MpmContactModels, SpecifiedReadsAVelocityTable) {
  const std::string file = test::scratch_dir("contact_profile") + "/profile.txt";
  {
    std::ofstream out(file);
    out << "0 0 0 0\n1 0 0 -1\n";
  }
  auto m = parse_contact(deck("<contact><type>specified</type><filename>" + file + "</filename></contact>")
                             ->root.require_child("contact"),
                         2);
  Vec3 v;
  ASSERT_TRUE(dynamic_cast<SpecifiedContact&>(*m).imposed_velocity(0.25, v));
  EXPECT_LE((v - Vec3(0, 0, -0.25)).norm(), 1e-15);
  {
    std::ofstream out(file);
    out << "0 0 0 0\n0 0 0 -1\n";
  }
  EXPECT_THROW(parse_contact(deck("<contact><type>specified</type><filename>" + file + "</filename></contact>")
                                 ->root.require_child("contact"),
                             2),
               DeckError);
}

}  // namespace
}  // namespace tephra
