// Contact friction heating (<do_contact_friction_heating>, mpm/contact/
// CoulombExchange.h friction_work, mpm/contact/FrictionHeating.h).
//
// Oracles (closed forms, derivations in the comments):
//  1. One slipping pair: m_a = 2, m_b = 3 (m_eff = 6/5), normal n = +z, a
//     approaches with w = 1 and slides with s = 2 along x, b at rest, mu = 0.5
//     (s/w = 2 > mu: slip). The exchange gives J_n = m_eff w = 1.2,
//     J_t = mu J_n = 0.6, the slip after is s - mu w (1/m_a + 1/m_b) m_eff =
//     s - mu w = 1.5, so Q = J_t (s - mu w) = 0.9 J. Vaango's per-body rule
//     m mu |dv_n| (|dv_t| - mu |dv_n|) with dv relative to v_cm gives a:
//     2 * 0.5 * 0.6 * (1.2 - 0.3) = 0.54 and b: 3 * 0.5 * 0.4 * (0.8 - 0.2) =
//     0.36, which add up to Q. The tangential kinetic energy removed,
//     m_eff (s^2 - (s - mu w)^2)/2 = 1.05, is Q + J_t^2/(2 m_eff) = 0.9 + 0.15.
//     Sticking (s/w = 0.4 < mu) and mu = 0 give Q = 0.
//  2. The node loop of friction and approach records exactly that split.
//  3. Node work to particles: sum_p m_p c_v Delta T_p = sum_g W_g (the stencil
//     weights of a particle sum to 1 and sum_p m_p S_gp = m_g), for linear and
//     gimp stencils of real particle sets, to round-off.
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"
#include "mpm/contact/FrictionHeating.h"

namespace tephra {
namespace {

ContactPair slipping_pair(double s) {
  ContactPair p;
  p.ma = 2.0;
  p.mb = 3.0;
  p.va = Vec3(s, 0, 1.0);  // n = +z from a into b: approach speed 1
  p.vb = Vec3::Zero();
  p.n = Vec3::UnitZ();
  return p;
}

TEST(MpmContactHeating, FrictionWorkOfASlippingPairIsTheClosedForm) {
  const Vec3 h(1, 1, 1);
  const double dt = 1e-6;  // the strain limiter is inactive
  {
    const ContactPair p = slipping_pair(2.0);
    const Vec3 dp = coulomb_exchange(p, 0.5, h, dt);
    const double Q = friction_work(p, dp);
    EXPECT_NEAR(Q, 0.9, 1e-15);
    // Kinetic energy removed from the tangential motion = Q + J_t^2 / (2 m_eff).
    const double meff = 1.2;
    const Vec3 va = p.va + dp / p.ma, vb = p.vb - dp / p.mb;
    const double ke0 = 0.5 * p.ma * p.va.squaredNorm() + 0.5 * p.mb * p.vb.squaredNorm();
    const double ke1 = 0.5 * p.ma * va.squaredNorm() + 0.5 * p.mb * vb.squaredNorm();
    const double normal_loss = 0.5 * meff * 1.0 * 1.0;  // the approach w = 1 removed (inelastic)
    EXPECT_NEAR(ke0 - ke1 - normal_loss, Q + 0.6 * 0.6 / (2 * meff), 1e-14);
  }
  {
    // s/w = 0.4 < mu: stick. Both end with v_cm, so the slip after is zero
    // up to the rounding of velocities of size 1 (u = 1.1e-16) times J_t < 1.
    const ContactPair p = slipping_pair(0.4);
    EXPECT_NEAR(friction_work(p, coulomb_exchange(p, 0.5, h, dt)), 0.0, 1e-15);
  }
  {
    const ContactPair p = slipping_pair(2.0);  // frictionless
    EXPECT_EQ(friction_work(p, coulomb_exchange(p, 0.0, h, dt)), 0.0);
  }
}

TEST(MpmContactHeating, NodeLoopSplitsTheWorkAsVaangoDoes) {
  for (const std::string type : {"friction", "approach"}) {
    std::vector<NodeGrid> g(2);
    ContactNodes nodes;
    for (int m = 0; m < 2; ++m) {
      g[m].n = IntVec3(1, 1, 1);
      g[m].h = Vec3(1, 1, 1);
      g[m].reset();
      g[m].mass[0] = m == 0 ? 2.0 : 3.0;
      g[m].volume[0] = 0.5;
      g[m].stress[0] = -1e3 * Mat3::Identity();  // compression: friction acts
      nodes.grid.push_back(&g[m]);
      nodes.velocity.push_back(&g[m].velocity);
    }
    g[0].velocity[0] = Vec3(2.0, 0, 1.0);
    g[1].velocity[0] = Vec3::Zero();
    nodes.gradient = {{Vec3(0, 0, 2.0)}, {Vec3(0, 0, -1.0)}};  // a's is larger: n = +z
    nodes.h = Vec3(1, 1, 1);
    nodes.dt = 1e-6;
    nodes.friction_work.assign(2, std::vector<double>(1, 0.0));
    FrictionParameters p;
    p.materials = {0, 1};
    p.mu = 0.5;
    if (type == "friction") FrictionContact(p).exchange(ContactStage::Integrated, nodes);
    else ApproachContact(p).exchange(ContactStage::Integrated, nodes);
    EXPECT_NEAR(nodes.friction_work[0][0], 0.54, 1e-15) << type;
    EXPECT_NEAR(nodes.friction_work[1][0], 0.36, 1e-15) << type;
  }
}

std::unique_ptr<MpmComponent> block(const std::string& interpolator) {
  std::ostringstream s;
  s << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator><interpolator>" << interpolator
    << "</interpolator></MPM><PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants>"
    << "<MaterialProperties><MPM><material><density>1000</density><constitutive_model type='comp_neo_hook'>"
    << "<bulk_modulus>1e7</bulk_modulus><shear_modulus>5e6</shear_modulus></constitutive_model>"
    << "<thermal_conductivity>0</thermal_conductivity><specific_heat>837</specific_heat><geom_object><box>"
    << "<min>[0.13,0.1,0.07]</min><max>[0.61,0.5,0.33]</max></box><res>[3,2,2]</res>"
    << "<velocity>[0,0,0]</velocity><temperature>300</temperature></geom_object></material></MPM>"
    << "</MaterialProperties><Grid><BoundaryConditions></BoundaryConditions><Level><Box><lower>[0,0,0]</lower>"
    << "<upper>[0.8,0.6,0.4]</upper><resolution>[16,12,8]</resolution><extraCells>[1,1,1]</extraCells>"
    << "<patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "heating.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  c->advance(0.0, 1e-12, 1);  // the stencils and node masses of a step
  return c;
}

TEST(MpmContactHeating, NodeWorkBecomesParticleHeatExactly) {
  for (const std::string interpolator : {"linear", "gimp"}) {
    auto c = block(interpolator);
    MpmMaterial& m = c->materials()[0];
    std::mt19937 rng(3u);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::vector<double> work(m.grid.count(), 0.0);
    double total = 0.0;
    for (std::size_t g = 0; g < work.size(); ++g)
      if (m.grid.mass[g] > 0.0) work[g] = u(rng), total += work[g];
    const std::vector<double> T0 = m.particles.temperature;
    friction_heat_to_particles(m.stencils, m.grid, work, m.specific_heat, m.particles);
    double heat = 0.0;
    for (std::size_t i = 0; i < T0.size(); ++i)
      heat += m.particles.mass[i] * m.specific_heat * (m.particles.temperature[i] - T0[i]);
    // Round-off: T ~ 300 K carries increments of ~1e-3 K, each rounded to
    // u * 300 (u = 1.1e-16): relative to the heat, ~300/1e-3 * u = 3.3e-11.
    EXPECT_NEAR(heat, total, 1e-10 * total) << interpolator;
  }
}

// The flag is read (no longer accepted and ignored); heating divides by c_v,
// so a material with specific_heat 0 is a DeckError naming the element.
TEST(MpmContactHeating, FlagNeedsAPositiveSpecificHeat) {
  auto deck_with = [](const std::string& cv) {
    return "<Uintah_specification><MPM><do_contact_friction_heating>true</do_contact_friction_heating></MPM>"
           "<MaterialProperties><MPM><material><density>1000</density><constitutive_model type='comp_neo_hook'>"
           "<bulk_modulus>1e7</bulk_modulus><shear_modulus>5e6</shear_modulus></constitutive_model>"
           "<thermal_conductivity>0</thermal_conductivity><specific_heat>" + cv + "</specific_heat><geom_object>"
           "<box><min>[0,0,0]</min><max>[0.1,0.1,0.1]</max></box><res>[2,2,2]</res><velocity>[0,0,0]</velocity>"
           "<temperature>300</temperature></geom_object></material></MPM></MaterialProperties><Grid>"
           "<Level><Box><lower>[0,0,0]</lower><upper>[0.2,0.2,0.2]</upper><resolution>[4,4,4]</resolution>"
           "<extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  };
  EXPECT_THROW(make_mpm_component(*load_deck_from_string(deck_with("0"), "cv0.ups", ".")), DeckError);
  auto c = make_mpm_component(*load_deck_from_string(deck_with("837"), "cv.ups", "."));
  EXPECT_TRUE(c->setup().flags.contact_friction_heating);
}

}  // namespace
}  // namespace tephra
