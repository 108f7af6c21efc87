// Cam-Clay (models/geo/CamClay.h, VT ch. 20) pieces against closed forms and identities:
//  - Borja's hyperelastic law: p = dW/d eps_v, q = dW/d eps_s and the four second
//    derivatives by central differences; p = p0 at the reference strain (inventory oracle 16);
//  - the elastic tangent (VT eq. 20.7, corrected) against finite differences of sigma(eps^e);
//  - yield identities: f = 0 at (0, 0), (p_c, 0) and the critical-state point (p_c/2, M|p_c|/2);
//    the p_c update factor exp(0.01/0.12) = 1.086904 (inventory oracle 16);
//  - the Newton return: every residual of VT eq. 20.2 below 1e-12 (f/p_c^2 below 1e-10) on
//    random trial states, dgamma > 0, quadratic convergence (few iterations);
//  - the MPMICE density hook rho(p) = rho0/[1 + eps_v0 - kt ln(p/p0)] (Remark 2, sign corrected);
//  - deck errors: wrong sub-model keys and an inadmissible reference state.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "models/geo/CamClay.h"
#include "tests/support/SolidModelDriver.h"

namespace tephra {
namespace {

using M3 = Eigen::Matrix3d;

BorjaElasticParams elastic(double alpha) {
  BorjaElasticParams b;
  b.p0 = -1.0e5;
  b.alpha = alpha;
  b.kappa = 0.03;
  b.eps_v0 = 0.002;
  b.mu0 = 5.0e6;
  return b;
}

TEST(CamClayBorja, InvariantsAreDerivativesOfTheEnergy) {
  for (double alpha : {0.0, 5.0, 60.0}) {
    const BorjaElasticParams b = elastic(alpha);
    for (double ev : {-0.05, -0.01, 0.0, 0.004})
      for (double es : {0.0, 0.003, 0.02}) {
        const BorjaInvariants r = borja_invariants(b, ev, es);
        const double h = 1e-6;
        auto W = [&](double v, double s) { return borja_energy(b, v, s); };
        const double scale = std::abs(b.p0) * std::exp(-(ev - b.eps_v0) / b.kappa) + b.mu0;
        EXPECT_NEAR(r.p, (W(ev + h, es) - W(ev - h, es)) / (2 * h), 1e-7 * scale);
        if (es > 0) EXPECT_NEAR(r.q, (W(ev, es + h) - W(ev, es - h)) / (2 * h), 1e-7 * scale);
        auto P = [&](double v, double s) { return borja_invariants(b, v, s).p; };
        auto Q = [&](double v, double s) { return borja_invariants(b, v, s).q; };
        const double k = 1e-7;
        EXPECT_NEAR(r.dp_dv, (P(ev + k, es) - P(ev - k, es)) / (2 * k), 1e-6 * scale / b.kappa);
        EXPECT_NEAR(r.dq_ds, (Q(ev, es + k) - Q(ev, es - k)) / (2 * k), 1e-6 * scale);
        if (es > k) {
          EXPECT_NEAR(r.dp_ds, (P(ev, es + k) - P(ev, es - k)) / (2 * k), 1e-6 * scale);
          EXPECT_NEAR(r.dq_dv, (Q(ev + k, es) - Q(ev - k, es)) / (2 * k), 1e-6 * scale);
        }
        // K = dp/d eps_v = -p/kt (VT §20.2.1)
        EXPECT_NEAR(r.dp_dv, -r.p / b.kappa, 1e-12 * std::abs(r.p / b.kappa));
      }
  }
  // p = p0 at eps_v = eps_v0, eps_s = 0 (inventory oracle 16); mu = mu0 - alpha p0 there.
  const BorjaElasticParams b = elastic(5.0);
  EXPECT_DOUBLE_EQ(borja_invariants(b, b.eps_v0, 0.0).p, b.p0);
  EXPECT_DOUBLE_EQ(borja_invariants(b, b.eps_v0, 0.0).mu, b.mu0 - 5.0 * b.p0);
}

TEST(CamClayBorja, ElasticTangentMatchesFiniteDifferences) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.01, 0.01);
  for (double alpha : {0.0, 20.0})
    for (int t = 0; t < 5; ++t) {
      const BorjaElasticParams b = elastic(alpha);
      M3 eps;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) eps(i, j) = u(rng);
      eps = (0.5 * (eps + eps.transpose())).eval();  // eval: no aliasing
      const Eigen::Matrix<double, 9, 9> C = borja_elastic_tangent(b, eps);
      const double h = 1e-7;
      double scale = C.norm();
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          M3 d = M3::Zero();
          d(k, l) += 0.5 * h;
          d(l, k) += 0.5 * h;  // symmetric perturbation: C : sym(e_k e_l)
          const M3 fd = (borja_stress(b, eps + d) - borja_stress(b, eps - d)) / (2 * h);
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              EXPECT_NEAR(C(3 * i + j, 3 * k + l), fd(i, j), 1e-6 * scale) << i << j << k << l;
        }
      // Hyperelastic: major symmetry C_ijkl = C_klij.
      EXPECT_LE((C - C.transpose()).norm(), 1e-12 * scale);
    }
}

TEST(CamClayYield, IdentitiesOfTheSurface) {
  const double M = 1.2, pc = -2.0e5;
  EXPECT_EQ(camclay_yield(M, 0.0, 0.0, pc), 0.0);
  EXPECT_EQ(camclay_yield(M, pc, 0.0, pc), 0.0);
  // Critical state: p = p_c/2, q = M |p_c|/2 -> f = -p_c^2/4 + p_c^2/4 = 0.
  EXPECT_NEAR(camclay_yield(M, pc / 2, M * std::abs(pc) / 2, pc), 0.0, 1e-6);
  EXPECT_LT(camclay_yield(M, pc / 2, 0.0, pc), 0.0);  // inside
  // p_c update factor with kt = 0.03, lt = 0.15, eps_v_trial - eps_v = -0.01: exp(0.01/0.12).
  CamClayParams c;
  c.elastic = elastic(0.0);
  c.lambda = 0.15;
  EXPECT_NEAR(camclay_pc_update(c, 1.0, 0.0, 0.01), 1.086904, 5e-7);
  EXPECT_NEAR(camclay_pc_update(c, 1.0, 0.0, 0.01), std::exp(0.01 / 0.12), 1e-15);
}

TEST(CamClayReturn, ConvergesOntoTheSurfaceWithConsistentFlow) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uv(-0.03, 0.02), us(0.0, 0.05);
  int tested = 0, worst_iterations = 0;
  for (double alpha : {0.0, 5.0})
    for (int t = 0; t < 200; ++t) {
      CamClayParams c;
      c.elastic = elastic(alpha);
      c.M = 1.2;
      c.lambda = 0.15;
      const double pc_n = -2.0e5;
      const double ev_tr = uv(rng), es_tr = us(rng);
      const BorjaInvariants v = borja_invariants(c.elastic, ev_tr, es_tr);
      if (camclay_yield(c.M, v.p, v.q, pc_n) <= 0.0) continue;  // elastic trial
      ++tested;
      const CamClayReturnResult r = camclay_return(c, ev_tr, es_tr, pc_n);
      ASSERT_TRUE(r.converged) << ev_tr << " " << es_tr;
      worst_iterations = std::max(worst_iterations, r.iterations);
      const BorjaInvariants w = borja_invariants(c.elastic, r.eps_v, r.eps_s);
      const double pc = camclay_pc_update(c, pc_n, ev_tr, r.eps_v);
      EXPECT_DOUBLE_EQ(pc, r.pc);
      // VT eq. 20.2: the three residuals.
      EXPECT_LE(std::abs(camclay_yield(c.M, w.p, w.q, pc)) / (pc * pc), 1e-10);
      EXPECT_LE(std::abs(r.eps_v - ev_tr + r.dgamma * (2 * w.p - pc)), 1e-12);
      EXPECT_LE(std::abs(r.eps_s - es_tr + r.dgamma * 2 * w.q / (c.M * c.M)), 1e-12);
      EXPECT_GT(r.dgamma, 0.0);
      EXPECT_GE(r.eps_s, 0.0);
    }
  EXPECT_GT(tested, 100);
  EXPECT_LE(worst_iterations, 30);
}

TEST(CamClayHooks, DensityAtPressureIsRemark2) {
  test::MapModelParameters p;
  test::add_sample_blocks("camclay", p);
  const ConstitutiveModelP m = create_constitutive_model("camclay", p);
  const auto& cc = dynamic_cast<const CamClay&>(*m).params();
  const double rho0 = 1800.0;
  // The gauge pressure is relative to the reference p(0) = p0 exp(eps_v0/kt) (= p0 here).
  const double p_ref = cc.elastic.p0 * std::exp(cc.elastic.eps_v0 / cc.elastic.kappa);
  for (double P : {-5.0e4, 0.0, 3.0e4, 2.0e5}) {
    const double p = p_ref - P;  // tension-positive mean stress
    const double expected = rho0 / (1.0 + cc.elastic.eps_v0 - cc.elastic.kappa * std::log(p / cc.elastic.p0));
    EXPECT_NEAR(*m->density_at_pressure(P, rho0, 300.0), expected, 1e-12 * expected);
    // and dp/dJ = dp/d eps_v = -p/kt (Remark 1) at that density: dP/drho = (-p/kt) rho0/rho^2
    const auto e = *m->pressure_at_density(expected, rho0, 300.0);
    EXPECT_NEAR(e.pressure, P, 1e-9 * std::abs(p_ref));
    EXPECT_NEAR(e.dp_drho, -p / cc.elastic.kappa * rho0 / (expected * expected), 1e-12 * e.dp_drho);
  }
  // Tension beyond p = 0 is never reached (J -> infinity): rho -> 0.
  // (gauge P = p_ref - p: P = p_ref + 1 is p = -1 Pa, J = 1 - kt ln(1e-5); P = p_ref - 1e3 is p = +1 kPa)
  EXPECT_NEAR(*m->density_at_pressure(p_ref + 1.0, rho0, 300.0), rho0 / (1.0 - cc.elastic.kappa * std::log(1e-5)), 1e-9 * rho0);
  EXPECT_EQ(*m->density_at_pressure(p_ref - 1.0e3, rho0, 300.0), 0.0);
}

TEST(CamClayDeck, WrongSubModelsAndInadmissibleReferenceStateAreErrors) {
  {
    test::MapModelParameters p;
    test::add_sample_blocks("camclay", p);
    p.blocks["yield_condition"]->type = "von_mises";
    EXPECT_THROW(create_constitutive_model("camclay", p), std::invalid_argument);
  }
  {
    test::MapModelParameters p;
    test::add_sample_blocks("camclay", p);
    p.blocks.erase("internal_variable_model");
    EXPECT_THROW(create_constitutive_model("camclay", p), std::invalid_argument);
  }
  {
    test::MapModelParameters p;
    test::add_sample_blocks("camclay", p);
    p.blocks["internal_variable_model"]->values["pc0"] = -0.5e5;  // |p_c| < |p(0)| = 1e5: outside
    EXPECT_THROW(create_constitutive_model("camclay", p), std::invalid_argument);
  }
  {
    test::MapModelParameters p;
    test::add_sample_blocks("camclay", p);
    p.blocks["internal_variable_model"]->values["lambdatilde"] = 0.02;  // must exceed kappatilde
    EXPECT_THROW(create_constitutive_model("camclay", p), std::invalid_argument);
  }
}

}  // namespace
}  // namespace tephra
