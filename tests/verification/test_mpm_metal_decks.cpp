// The starter metal decks (decks README A4, A5).
//
// A4, MPM/adiCuJC4000s696K.ups: one OFHC-Cu particle (elastic_plastic, Johnson-Cook,
// Mie-Grueneisen, T0 = 696 K) pulled by a rigid piston at 40 m/s through `rigid`
// contact. The particle's velocity gradient is set kinematically by the piston node
// (z = 0.01 m, v = 40 m/s) and the symmetry plane: l_zz = 40/0.01 = 4000 /s while
// the piston particle (z0 = 0.015 m) is in the second cell, i.e. for
// 0.005/40 = 1.25e-4 s; then the piston leaves the node, the specimen is released
// and rings elastically (the deck runs to 3e-4 s; Vaango's grid is the same). The
// lateral faces are free (uniaxial stress). The test covers the loading, 1.2e-4 s.
// Oracle: the returned deviator lies on the JC law at the particle's own state,
//   q = sqrt(3/2)|s| = [A + B eps_p^n][1 + C ln(eps_p_dot/1)][1 - T*^m]   (VT 10.2-10.3),
// with T the temperature of the return: the particle temperature at the step's
// start plus this step's adiabatic rise. The driver adds heating dt to T_p,
// and heating also holds the artificial-viscosity heating (the deck has
// artificial_viscosity, so its heating is on, as in Vaango), which the return
// does not see: T_p - heating dt <= T_return <= T_p after the step. The plastic strain rate tends to
// the imposed 4000 /s and eps_p to ln F_zz - q/E (uniaxial stress, isochoric flow).
// Its Vaango sisters (adiCu{MTS,PTW,SCG,ZA}4000s696K.ups: A4 with the flow, shear and
// melting blocks swapped) are checked the same way against their laws (below).
//
// A5, MPM/Impact/cylinderImpact_A_JC.ups: the Taylor impact (elastic_plastic_hp,
// JC flow, JC damage, 26.7k particles), the first 1.5 us of the deck's 80 us, unchanged
// (multiplier 0.8, <materials>[0]; docs/mpm-stability.md "Deck A5"):
// energy balance KE + SE + W_p = KE_0 minus the kinetic energy the rigid wall
// removes (the nodes in contact are set to the wall velocity: an inelastic
// collision of the first node layer, ~2 % of KE_0; see the test), the x <-> z mirror
// symmetry of the quarter model, CenterOfMassVelocity = TotalMomentum/TotalMass,
// and damage D = int eps_p_dot/eps_f >= 0 growing only where eps_p grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/LU>

#include "core/deck/DeckLoader.h"
#include "models/solid/ElasticPlastic.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

namespace fs = std::filesystem;

std::string deck_path(const std::string& name) { return test::shared_dir() + "/decks/inputs/MPM/" + name; }

double von_mises(const Mat3& s) {
  const Mat3 d = s - (s.trace() / 3.0) * Mat3::Identity();
  return std::sqrt(1.5 * d.squaredNorm());
}

// The deck with one more <DataArchiver><save label=...> (e.g. the Tephra label
// PlasticWork, which MPM sums only when the deck saves it and the Vaango decks do not).
std::unique_ptr<Deck> with_saved_label(std::unique_ptr<Deck> deck, const std::string& label) {
  for (DeckNode& n : deck->root.children)
    if (n.name == "DataArchiver") {
      DeckNode save;
      save.name = "save";
      save.attributes = {{"label", label}};
      save.file = n.file;
      save.line = n.line;
      n.children.push_back(save);
      deck->root.finalize_parents();
      return deck;
    }
  ADD_FAILURE() << deck->path << ": no <DataArchiver>";
  return deck;
}

// The deck's step rule (timestep_multiplier, delt_max) up to `end`; check(t, component) every step.
template <class Check>
int run_loaded_deck(std::unique_ptr<Deck> deck, double end, Check&& check,
                    const std::vector<std::pair<std::vector<std::string>, std::string>>& edits = {});

template <class Check>
int run_deck(const std::string& name, double end, Check&& check,
             const std::vector<std::pair<std::vector<std::string>, std::string>>& edits = {}) {
  return run_loaded_deck(load_deck(deck_path(name)), end, check, edits);
}

template <class Check>
int run_loaded_deck(std::unique_ptr<Deck> deck, double end, Check&& check,
                    const std::vector<std::pair<std::vector<std::string>, std::string>>& edits) {
  for (const auto& [path, text] : edits) {  // set the text of an element given by its path
    const DeckNode* n = &deck->root;
    for (const std::string& e : path) n = &n->require_child(e);
    const_cast<DeckNode*>(n)->text = text;
  }
  const DeckNode& time = deck->root.require_child("Time");
  const double multiplier = time.get_double("timestep_multiplier");
  const double delt_max = time.get_double("delt_max");
  auto c = make_mpm_component(*deck);
  c->initialize();
  check(0.0, 0.0, *c);
  double t = 0;
  int step = 0;
  while (t < end) {
    const double dt = std::min({multiplier * c->stable_timestep(), delt_max, end - t});
    c->advance(t, dt, ++step);
    t += dt;
    check(t, dt, *c);
  }
  return step;
}

// The sister decks are Tephra test decks in inputs/mpm/ (A4 with the flow, shear and
// melting blocks of Vaango's/Uintah's adiCu{MTS,PTW,SCG,ZA}4000s696K.ups; each file names its source).
std::string sister_deck_path(const std::string& name) { return test::source_dir() + "/inputs/mpm/" + name; }
std::string sister_deck_text(const std::string& name) { return test::slurp(sister_deck_path(name)); }

// Offline integration of a flow law with adiabatic heating along A4's path (uniaxial
// stress at eps_p_dot = 4000 /s from T0 = 696 K), independent of the MPM run:
//   dT/deps_p = chi sigma_y(eps_p, T, sigma_e, p_bar)/(rho c_p),   chi = 0.9, rho = 8930, c_p = 414
//   dsigma_e/deps_p = theta(T, sigma_e)  (MTS only; zero otherwise),
// p_bar = -sigma_y/3 (uniaxial tension), rho = rho_0 (plastic flow is isochoric; the
// elastic volume change ~ p/K < 1e-3 moves the heating by as much); classical RK4 in
// eps_p with step 2.5e-5. Returns sigma_y on the grid eps_p = k * 2.5e-5.
struct OfflineCurve {
  double step = 2.5e-5;
  std::vector<double> sigma;
  double at(double ep) const {  // linear interpolation
    const double x = ep / step;
    const std::size_t k = std::min(sigma.size() - 2, std::size_t(x));
    return sigma[k] + (x - double(k)) * (sigma[k + 1] - sigma[k]);
  }
};
template <class Sigma, class Theta>
OfflineCurve integrate_adiabatic(double ep_end, Sigma&& sigma_y, Theta&& theta) {
  const double chi = 0.9, rho = 8930.0, cp = 414.0;
  OfflineCurve c;
  double T = 696.0, se = 0.0, ep = 0.0, p_bar = 0.0;
  auto rhs = [&](double e, double T_, double se_, double& dT, double& dse) {
    const double s = sigma_y(e, T_, se_, p_bar);
    dT = chi * s / (rho * cp);
    dse = theta(T_, se_);
  };
  const double h = c.step;
  while (ep <= ep_end + h) {
    const double s = sigma_y(ep, T, se, p_bar);
    c.sigma.push_back(s);
    p_bar = -s / 3.0;
    double k1T, k1s, k2T, k2s, k3T, k3s, k4T, k4s;
    rhs(ep, T, se, k1T, k1s);
    rhs(ep + h / 2, T + h / 2 * k1T, se + h / 2 * k1s, k2T, k2s);
    rhs(ep + h / 2, T + h / 2 * k2T, se + h / 2 * k2s, k3T, k3s);
    rhs(ep + h, T + h * k3T, se + h * k3s, k4T, k4s);
    T += h / 6 * (k1T + 2 * k2T + 2 * k3T + k4T);
    se += h / 6 * (k1s + 2 * k2s + 2 * k3s + k4s);
    ep += h;
  }
  return c;
}
// Offline integration along the deck's own loading path in time (not at a constant plastic
// rate): the piston holds the total log strain rate at l_zz = 4000 /s from t = 0, the
// lateral faces are free (uniaxial stress), so with the hypo-elastic stress rate
//   dq/dt = E(T, p_bar) (4000 - eps_p_dot),   E = 9KG/(3K + G), K = rho_0 C_0^2 (the deck's
//   Mie-Grueneisen EOS at small strain), G = mu(T, p_bar) of the deck's shear model,
// and, while plastic, q = sigma_y(eps_p, eps_p_dot, T, sigma_e, p_bar): the plastic rate
// rises from 0 at yield towards 4000 /s over the elastic-plastic transition (the law's
// rate dependence sets how fast); heating dT = chi q deps_p/(rho c_p), MTS dsigma_e/deps_p =
// theta(rate, T, sigma_e) integrated over each step's increment (RK4 substeps, se_after below). Backward Euler in time with step h: Delta = deps_p solves (bisection;
// the residual decreases in Delta)
//   q_n + E (4000 h - Delta) = sigma_y(eps_p,n + Delta, Delta/h, T_n+1, sigma_e,n+1, p_bar,n),
// Delta = 0 (elastic) when the left side at Delta = 0 is below sigma_y at Delta -> 0.
// Returns the plastic points (eps_p, q), eps_p increasing. First order in h: the test
// prints the change from h to h/2 as the reference's own error.
struct PathCurve {
  std::vector<double> ep, q, rate;
  double at(double e) const {  // linear interpolation in eps_p
    const std::size_t k = std::min<std::size_t>(
        ep.size() - 1, std::max<std::size_t>(1, std::lower_bound(ep.begin(), ep.end(), e) - ep.begin()));
    return q[k - 1] + (e - ep[k - 1]) / (ep[k] - ep[k - 1]) * (q[k] - q[k - 1]);
  }
  double rate_at(double e) const {
    const std::size_t k = std::min<std::size_t>(ep.size() - 1, std::lower_bound(ep.begin(), ep.end(), e) - ep.begin());
    return rate[k];
  }
};
// law(ep, rate, T, sigma_e, p_bar, rho); theta(rate, T, sigma_e) (0 but for MTS); shear(T, p_bar, rho).
// The total strain history: the run's own equivalent deviatoric log strain
// e_eq(t) = (2/3)(ln F_zz - (ln F_xx + ln F_yy)/2) (piecewise linear between its steps) when given
// (the kinematics as the particle saw them: piston and lateral inertia), else uniaxial stress at 4000 /s.
struct StrainHistory {
  std::vector<double> t, eps, J;  // the run's step times, e_eq and J = det F
  void record(double time, const Mat3& F) {
    t.push_back(time);
    J.push_back(F.determinant());
    eps.push_back(2.0 / 3.0 * (std::log(F(2, 2)) - 0.5 * (std::log(F(0, 0)) + std::log(F(1, 1)))));
  }
  double J_at(double s) const {  // J at the run's step that starts at or before s (start-of-step state)
    const std::size_t k = std::upper_bound(t.begin(), t.end(), s * (1 + 1e-12)) - t.begin();
    return J[std::min(J.size() - 1, k > 0 ? k - 1 : 0)];
  }
  double at(double s) const {
    const std::size_t k = std::min<std::size_t>(
        t.size() - 1, std::max<std::size_t>(1, std::lower_bound(t.begin(), t.end(), s) - t.begin()));
    return eps[k - 1] + (s - t[k - 1]) / (t[k] - t[k - 1]) * (eps[k] - eps[k - 1]);
  }
};
template <class Law, class Theta, class Shear>
PathCurve integrate_loading_path(double t_end, double h, Law&& law, Theta&& theta, Shear&& shear,
                                 const StrainHistory& strain = {}) {
  const double chi = 0.9, rho = 8930.0, cp = 414.0, K = 8930.0 * 3940.0 * 3940.0;
  PathCurve c;
  double q = 0, ep = 0, T = 696.0, se = 0, p_bar = 0;
  // h = 0: the run's own step times (strain.t), i.e. the same time discretisation as the deck.
  std::vector<double> times;
  if (h > 0) {
    for (double t = 0; t < t_end; t += h) times.push_back(t);
    times.push_back(t_end);
  } else {
    times = strain.t;
  }
  for (std::size_t n = 0; n + 1 < times.size(); ++n) {
    const double t = times[n];
    h = times[n + 1] - t;
    // With the run's history: its volume J (start of step), rho = rho_0/J and the small-strain
    // Mie-Grueneisen pressure p_bar = K (1 - J) (the laws' and moduli's pressure and density
    // inputs: SCG mu(p, eta), PTW mu(rho) and xi_dot(rho)); else p_bar = -q/3, rho = rho_0.
    double rho_t = rho;
    if (!strain.t.empty()) {
      const double J = strain.J_at(t);
      rho_t = rho / J;
      p_bar = K * (1 - J);
    }
    const double G = shear(T, p_bar, rho_t), E = 9 * K * G / (3 * K + G);
    // Uniaxial stress at 4000 /s: dq = E (4000 h - deps_p). The run's history: dq = 3G (de_eq - deps_p),
    // de_eq = (2/3) d(ln F_zz - ln F_xx) (axisymmetric: the particle's lateral strain as it happened,
    // which at first lags the uniaxial-stress contraction: the particle's lateral inertia).
    const bool uniaxial = strain.t.size() < 2;
    const double d_total = uniaxial ? 4000.0 * h : strain.at(t + h) - strain.at(t);
    const double M = uniaxial ? E : 3 * G;
    auto q_of = [&](double d) { return q + M * (d_total - d); };
    auto T_of = [&](double d) { return T + chi * q_of(d) * d / (rho * cp); };
    // MTS: sigma_e after the step's increment d, dsigma_e/deps_p = theta(rate, T, sigma_e) integrated over
    // [0, d] at the step's rate and T by classical RK4 with substeps of at most 1e-4 in eps_p (the run's
    // steps carry ~4e-3; the fine reference ~4e-5); theta = 0 (the other laws) leaves sigma_e at 0.
    auto se_after = [&](double d, double rate, double T1) {
      const int n = std::max(1, int(std::ceil(d / 1e-4)));
      const double k = d / n;
      double x = se;
      for (int i = 0; i < n; ++i) {
        const double k1 = theta(rate, T1, x), k2 = theta(rate, T1, x + 0.5 * k * k1);
        const double k3 = theta(rate, T1, x + 0.5 * k * k2), k4 = theta(rate, T1, x + k * k3);
        x += k / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
      }
      return x;
    };
    auto residual = [&](double d) {
      const double T1 = T_of(d);
      const double rate = std::max(d / h, 1e-8);  // the models' rate floor (FlowAd.h kMinPlasticRate)
      return q_of(d) - law(ep + d, rate, T1, se_after(d, rate, T1), p_bar, rho_t);
    };
    double d = 0;
    if (residual(1e-300) > 0) {  // plastic
      double lo = 0, hi = d_total + q / M;  // residual(hi) = -sigma_y < 0
      for (int i = 0; i < 80; ++i) (residual(0.5 * (lo + hi)) > 0 ? lo : hi) = 0.5 * (lo + hi);
      d = 0.5 * (lo + hi);
    }
    const double T1 = T_of(d);
    se = se_after(d, std::max(d / h, 1e-8), T1);
    q = q_of(d);
    T = T1;
    ep += d;
    p_bar = -q / 3.0;
    if (d > 0) c.ep.push_back(ep), c.q.push_back(q), c.rate.push_back(d / h);
  }
  return c;
}
// max over the run's plastic steps with eps_p >= 0.01 of |q - q_path(eps_p)|/q_path.
double worst_against_path(const std::vector<std::pair<double, double>>& ep_q, const PathCurve& c, double* at_ep) {
  double worst = 0;
  for (const auto& [ep, q] : ep_q)
    if (ep >= 0.01 && std::abs(q / c.at(ep) - 1) > worst) worst = std::abs(q / c.at(ep) - 1), *at_ep = ep;
  return worst;
}
// The path reference at steps h and h/2 against the run; asserts 1 % when `assert_1pct`.
template <class Law, class Theta, class Shear>
double check_against_path(const std::string& name, const std::vector<std::pair<double, double>>& ep_q, Law&& law,
                          Theta&& theta, Shear&& shear, const StrainHistory& strain,
                          double* continuous_error = nullptr) {
  const double h = 1e-8;  // h -> h/2 changes the curve by ~2e-4 (printed)
  {  // the same at a constant total rate of 4000 /s (printed: how much the run's own kinematics matter)
    const PathCurve c0 = integrate_loading_path(1.2e-4, h, law, theta, shear);
    double at0 = 0;
    const double w0 = worst_against_path(ep_q, c0, &at0);
    std::printf("%s: vs the loading path at a constant total rate 4000 /s: max |q/q_path - 1| = %.3e at eps_p = "
                "%.4f; plastic rate there at eps_p = 0.001, 0.01, 0.03: %.0f, %.0f, %.0f /s\n", name.c_str(), w0,
                at0, c0.rate_at(0.001), c0.rate_at(0.01), c0.rate_at(0.03));
  }
  std::printf("%s: run's equivalent deviatoric strain rate de_eq/dt over steps 1-8 (uniaxial stress: 4000 /s):",
              name.c_str());
  for (std::size_t k = 1; k < std::min<std::size_t>(9, strain.t.size()); ++k)
    std::printf(" %.0f", (strain.eps[k] - strain.eps[k - 1]) / (strain.t[k] - strain.t[k - 1]));
  std::printf(" /s (dt %.2e s)\n", strain.t[2] - strain.t[1]);
  const PathCurve c1 = integrate_loading_path(1.2e-4, h, law, theta, shear, strain);
  const PathCurve c2 = integrate_loading_path(1.2e-4, h / 2, law, theta, shear, strain);
  double ref_change = 0, at1 = 0, at2 = 0;
  for (const auto& [ep, q] : ep_q)
    if (ep >= 0.01) ref_change = std::max(ref_change, std::abs(c1.at(ep) / c2.at(ep) - 1));
  const double w1 = worst_against_path(ep_q, c1, &at1), w2 = worst_against_path(ep_q, c2, &at2);
  // The same integration on the run's own time steps (backward Euler, rate = Delta eps_p/dt as the
  // return): the run's time-step error at the deck's dt is w2 - (this).
  const PathCurve cr = integrate_loading_path(1.2e-4, 0.0, law, theta, shear, strain);
  double atr = 0;
  const double wr = worst_against_path(ep_q, cr, &atr);
  std::printf("%s: path reference plastic rate at eps_p = 0.001, 0.003, 0.01, 0.03: %.0f, %.0f, %.0f, %.0f /s\n",
              name.c_str(), c2.rate_at(0.001), c2.rate_at(0.003), c2.rate_at(0.01), c2.rate_at(0.03));
  std::printf("%s: stress-plastic strain curve vs offline integration along the run's total-strain history "
              "(e_eq(t), hypo-elastic then plastic, adiabatic): max |q/q_path - 1| = %.3e at eps_p = %.4f (h = %.1e s), "
              "%.3e at %.4f (h/2); reference change h -> h/2 %.2e\n",
              name.c_str(), w1, at1, h, w2, at2, ref_change);
  std::printf("%s: vs the same integration on the run's own time steps (dt %.2e s): max |q/q_path - 1| = %.3e at "
              "eps_p = %.4f; the run's time-step error (h -> 0 vs the run's dt) %s 1 %%\n",
              name.c_str(), strain.t[2] - strain.t[1], wr, atr, w2 < 0.01 ? "within" : "NOT within");
  if (continuous_error) *continuous_error = w2;
  return wr;
}

// max over the plastic steps with eps_p >= 0.01 of |q - sigma_offline(eps_p)|/sigma_offline.
double worst_against_offline(const std::vector<std::pair<double, double>>& ep_q, const OfflineCurve& c) {
  double worst = 0, at = 0;
  for (const auto& [ep, q] : ep_q)
    if (ep >= 0.01 && std::abs(q - c.at(ep)) / c.at(ep) > worst) worst = std::abs(q - c.at(ep)) / c.at(ep), at = ep;
  std::printf("  offline comparison: worst at eps_p = %.4f\n", at);
  return worst;
}

TEST(MetalDecks, A4AdiabaticCopperFollowsTheJohnsonCookLaw) {
  // Deck constants: JC A, B, C, n, m; T_r = 298, T_m = 1793 (Vaango's JC defaults); E from K, G.
  const double A = 90e6, B = 292e6, C = 0.025, n = 0.31, m = 1.09, Tr = 298, Tm = 1793;
  const double K = 129e9, G = 46e9, E = 9 * K * G / (3 * K + G);
  auto jc = [&](double ep, double rate, double T) {
    const double Ts = (T - Tr) / (Tm - Tr);
    return (A + B * std::pow(ep, n)) * (1 + C * std::log(std::max(rate, 1.0))) * (1 - std::pow(Ts, m));
  };
  double worst_law = 0, worst_ep = 0, last_rate = 0, last_ep = 0, wp = 0, se = 0, acc = 0;
  int checks = 0;
  std::vector<std::pair<double, double>> ep_q;
  const int steps = run_deck("adiCuJC4000s696K.ups", 1.2e-4, [&](double t, double dt, const MpmComponent& c) {
    const MpmMaterial& mat = c.materials()[1];
    const Particles& p = mat.particles;
    ASSERT_EQ(p.size(), 1u);
    ASSERT_EQ(mat.model->type(), "elastic_plastic");
    if (t > 0) wp += mat.plastic_work[0] * p.volume0[0];
    se = p.energy_density[0] * p.volume0[0];
    acc = c.reductions({"AccStrainEnergy"}).at("AccStrainEnergy")[0];
    const double ep = p.history[0][0], rate = p.history[1][0];
    if (t <= 0 || ep < 0.01 || !(rate > 0)) return;  // plastic steps after yield
    const double q = von_mises(p.stress[0]);
    // The return's temperature lies in [T_p - heating dt, T_p], T_p after the step (see the top).
    const double T_hi = p.temperature[0], T_lo = p.temperature[0] - mat.heating[0] * dt;
    const double lo = jc(ep, rate, T_hi), hi = jc(ep, rate, T_lo);
    const double err = q < lo ? (lo - q) / q : (q > hi ? (q - hi) / q : 0.0);
    worst_law = std::max(worst_law, err);
    worst_ep = std::max(worst_ep, std::abs(ep - (std::log(p.F[0](2, 2)) - q / E)));
    ep_q.emplace_back(ep, q);
    last_rate = rate;
    last_ep = ep;
    ++checks;
  });
  std::printf("A4: %d steps, %d checks, max |q - JC|/q = %.3e, max |eps_p - (ln F_zz - q/E)| = %.3e, "
              "final eps_p %.4f, eps_p_dot %.1f /s\n",
              steps, checks, worst_law, worst_ep, last_ep, last_rate);
  EXPECT_GT(checks, 100);
  EXPECT_LT(worst_law, 1e-9);        // the return's own tolerance is 1e-12 (deck)
  EXPECT_LT(worst_ep, 2e-3);          // small-strain elastic split; observed above
  EXPECT_GT(last_ep, 0.45);           // 4000 /s for 1.2e-4 s: eps ~ 0.48
  EXPECT_NEAR(last_rate / 4000.0, 1.0, 0.02);
  // The stress-plastic strain curve against the JC law integrated offline with adiabatic
  // heating at 4000 /s (integrate_adiabatic; not the run's temperature): 1 % from eps_p = 0.01.
  const OfflineCurve offline = integrate_adiabatic(
      0.5, [&](double ep, double T, double, double) { return jc(ep, 4000.0, T); }, [](double, double) { return 0.0; });
  const double off = worst_against_offline(ep_q, offline);
  std::printf("A4: stress-plastic strain curve vs offline adiabatic integration: max |q/sigma_offline - 1| = %.3e "
              "(sigma_offline(0.45) = %.4e Pa)\n", off, offline.at(0.45));
  EXPECT_LT(off, 0.01);
  // The plastic work (PlasticWork's per-particle sum, V0 J sigma : Delta eps_p each step: the
  // current volume J V0 times the Cauchy stress) against the offline
  //   W_p = V0 int_0^{eps_p} sigma_offline(e) de   (trapezoid on the offline grid),
  // J = 1 for isochoric plastic flow; the elastic and thermal volume change (sigma/3K +
  // 3 alpha dT ~ 2e-3) and the return's backward-Euler sigma_{n+1} Delta eps_p (above: ~3e-3)
  // are the expected differences: 1 %.
  double wp_offline = 0;
  for (double e = 0; e + offline.step <= last_ep + 1e-12; e += offline.step)
    wp_offline += 0.5 * (offline.at(e) + offline.at(e + offline.step)) * offline.step;
  wp_offline *= 1e-6;  // V0 = (1 cm)^3
  std::printf("A4: plastic work %.6e J vs offline V0 int sigma de_p = %.6e J (ratio %.5f)\n", wp, wp_offline,
              wp / wp_offline);
  EXPECT_NEAR(wp / wp_offline, 1.0, 0.01);
  // AccStrainEnergy (the stress work, trapezoid in time) = plastic work + stored energy
  // (the rigid piston does none). The model's plastic work is backward Euler,
  // J sigma_y,n+1 Delta eps_p, which exceeds the trapezoid by sum 1/2 Delta sigma_y Delta eps_p
  // ~ 1/2 (4000 dt) (2.7e8 - 1.1e8 Pa) V = 0.33 J of 118 J (2.8e-3; observed 1.7e-3).
  std::printf("A4: AccStrainEnergy %.6e J, plastic work + stored energy %.6e J\n", acc, wp + se);
  EXPECT_LT(acc, wp + se);
  EXPECT_NEAR(acc / (wp + se), 1.0, 3e-3);
}

// The MTS sister deck (inputs/mpm/adiCuMTS4000s696K.ups, Vaango's adiCuMTS4000s696K.ups):
// A4 with the flow and shear blocks of MaterialData/MTSPlasticETPCu.xml and
// MTSShearETPCu.xml inlined (deck spelling "mts_model"). Oracle: the returned q equals the
// MTS law of VT eq. 10.16-10.23 evaluated by the model's own flow object at the particle's
// state (eps_p, eps_p_dot, T, mu, sigma_e from its history), and sigma_e grows with eps_p;
// and the stress-plastic-strain curve matches the law written out below (sigma_i = 0):
//   sigma_y = sigma_a + S_e sigma_e mu/mu_0,  S_e = [1 - (k/b^3 T/(g_0e mu) ln(edot_0e/edot))^{1/q_e}]^{1/p_e},
//   dsigma_e/deps_p = theta_0 (1 - F) + theta_IV F,  theta_0 = a_0 + a_1 ln edot + a_2 sqrt(edot) - a_3 T,
//   F = tanh(alpha sigma_e/sigma_es)/tanh(alpha),  sigma_es = sigma_es0 exp(k/b^3 T/(g_0es mu) ln(edot/edot_es0)),
//   mu = mu_0 - D/(exp(T_0/T) - 1) (mts_shear, VT 7.5),
// integrated offline with adiabatic heating, each asserted to 1 %: at a constant 4000 /s in
// uniaxial stress (integrate_adiabatic, RK4 in eps_p) 7.8e-4; along the run's own kinematics
// (integrate_loading_path, see check_sister_deck) at h -> 0 (1e-8 s, 5e-9 s) 3.4e-4, on the
// run's own time steps 1.1e-4 (session 15 figures). Until session 14 the returns advanced
// sigma_e explicitly, sigma_e,n + theta(sigma_e,n) Delta eps_p: 1.11 % (h -> 0) and 1.15 %
// (constant rate) at eps_p 0.02-0.04, the deck's 0.0044 strain per step overshooting sigma_e's
// saturating growth; now the returns integrate eq. 10.19 over the step's increment
// (FlowStressModel::evolve_internal_stress, MtsFlow.cpp).
TEST(MetalDecks, A4MtsSisterDeckFollowsTheMtsLaw) {
  auto deck = load_deck_from_string(sister_deck_text("adiCuMTS4000s696K.ups"), "adiCuMTS4000s696K.ups",
                                    test::source_dir() + "/inputs/mpm");
  double worst = 0, prev_se = 0, last_ep = 0;
  int checks = 0;
  std::vector<std::pair<double, double>> ep_q;
  StrainHistory strain;
  run_loaded_deck(std::move(deck), 1.2e-4, [&](double t, double dt, const MpmComponent& c) {
    const MpmMaterial& mat = c.materials()[1];
    const Particles& p = mat.particles;
    strain.record(t, p.F[0]);
    const auto& model = static_cast<const ElasticPlastic&>(*mat.model);
    ASSERT_EQ(model.flow_->type(), "mechanical_threshold_stress");
    const double ep = p.history[0][0], rate = p.history[1][0], se = p.history[6][0];
    EXPECT_GE(se, prev_se);
    prev_se = se;
    if (t <= 0 || !(rate > 0)) return;
    PlasticState st;
    st.eps_p = ep;
    st.eps_p_rate = rate;
    st.density0 = 8930.0;
    st.density = 8930.0 / p.F[0].determinant();
    st.sigma_e = se;
    // mts_shear at the start-of-step state (VT 7.5, T_0 = 180, D = 3e9, mu_0 = 47.7e9)
    const double T_start = p.temperature[0] - mat.heating[0] * dt;  // the driver added heating dt
    st.shear_modulus = 47.7e9 - 3.0e9 / (std::exp(180.0 / T_start) - 1.0);
    const double q = von_mises(p.stress[0]);
    // The return's T lies in [T_start, T_p] (see A4: heating dt also holds the
    // artificial-viscosity heating, which the return does not see).
    st.temperature = p.temperature[0];
    const double lo = model.flow_->evaluate(st).sigma_y;
    st.temperature = T_start;
    const double hi = model.flow_->evaluate(st).sigma_y;
    worst = std::max(worst, q < lo ? lo / q - 1.0 : (q > hi ? q / hi - 1.0 : 0.0));
    if (ep >= 0.01) ep_q.emplace_back(ep, q);
    last_ep = ep;
    ++checks;
  });
  const double sigma_a = 40e6, mu0 = 47.7e9, D = 3e9, T0 = 180, kb3 = 0.823e6, g0e = 1.6, edot0e = 1e7,
               pe = 0.666667, qe = 1.0, a0 = 2390e6, a1 = 12e6, a2 = 1.696e6, a3 = 0, thetaIV = 0, alpha = 2,
               edot_es0 = 1e7, g0es = 0.2625, sigma_es0 = 770e6, edot = 4000.0;
  auto mu_of = [&](double T) { return mu0 - D / (std::exp(T0 / T) - 1.0); };
  const OfflineCurve offline = integrate_adiabatic(
      0.5,
      [&](double, double T, double se, double) {
        const double mu = mu_of(T);
        const double Se = std::pow(1.0 - std::pow(kb3 * T / (g0e * mu) * std::log(edot0e / edot), 1.0 / qe), 1.0 / pe);
        return sigma_a + Se * se * mu / mu0;
      },
      [&](double T, double se) {
        const double mu = mu_of(T);
        const double theta0 = a0 + a1 * std::log(edot) + a2 * std::sqrt(edot) - a3 * T;
        const double ses = sigma_es0 * std::exp(kb3 * T / (g0es * mu) * std::log(edot / edot_es0));
        const double F = std::tanh(alpha * se / ses) / std::tanh(alpha);
        return theta0 * (1 - F) + thetaIV * F;
      });
  const double off = worst_against_offline(ep_q, offline);
  std::printf("A4 MTS: stress-plastic strain curve vs offline adiabatic integration: max |q/sigma_offline - 1| = "
              "%.3e (sigma_offline(0.45) = %.4e Pa)\n", off, offline.at(0.45));
  EXPECT_LT(off, 0.01);  // constant 4000 /s, uniaxial stress
  // The same law along the loading path (integrate_loading_path: the plastic rate rises to 4000 /s).
  double path_continuous = 0;
  const double path = check_against_path(
      "A4 MTS", ep_q,
      [&](double, double rate, double T, double se, double, double) {
        const double mu = mu_of(T);
        const double x = kb3 * T / (g0e * mu) * std::log(edot0e / rate);  // >= 1: S_e = 0
        const double Se = std::pow(std::max(0.0, 1.0 - std::pow(std::max(0.0, x), 1.0 / qe)), 1.0 / pe);
        return sigma_a + Se * se * mu / mu0;
      },
      [&](double rate, double T, double se) {
        const double mu = mu_of(T);
        const double r = rate;
        const double theta0 = a0 + a1 * std::log(r) + a2 * std::sqrt(r) - a3 * T;
        const double ses = sigma_es0 * std::exp(kb3 * T / (g0es * mu) * std::log(r / edot_es0));
        const double F = std::tanh(alpha * se / ses) / std::tanh(alpha);
        return theta0 * (1 - F) + thetaIV * F;
      },
      [&](double T, double, double) { return mu_of(T); }, strain, &path_continuous);
  EXPECT_LT(path, 0.01);             // on the run's own time steps
  EXPECT_LT(path_continuous, 0.01);  // h -> 0: the run's time-step error within 1 %
  std::printf("A4 MTS: %d checks, max |q/sigma_y(MTS) - 1| = %.3e, final eps_p %.4f, sigma_e %.4e Pa\n", checks,
              worst, last_ep, prev_se);
  EXPECT_GT(checks, 100);
  EXPECT_LT(worst, 1e-10);  // the return tolerance is 1e-12 (deck); observed 4.5e-13
  EXPECT_GT(last_ep, 0.45);
  EXPECT_GT(prev_se, 1e8);
}

// The PTW, SCG and ZA sister decks (Vaango's adiCu{PTW,SCG,ZA}4000s696K.ups): A4 with the
// flow, shear and melting blocks swapped, constants as in those decks (the manual's ch. 10
// copper values). The returned q is checked against the flow law written out here (VT eq.
// 10.4-10.10, 10.24-10.28) at the particle's state, with the temperature bracket of A4:
// the law is decreasing in T (and increasing in mu, itself decreasing in T), so
//   law(T_p) <= q <= law(T_p - heating dt)
// holds for the return's T_{n+1} in that interval (A4's comment: heating dt also holds the
// artificial-viscosity heating). The moduli state of elastic_plastic is the start of the step
// (VT §18.2): p̄_n = -tr(sigma_n)/3 of the previous step, rho = rho_0/J.
struct SisterState {
  double ep, rate, T, p_bar, rho;  // p̄ positive in compression
};
// Runs a sister deck over A4's loading (1.2e-4 s) and checks q against law(state) with the
// temperature bracket above at every plastic step (q inside the bracket to 1e-9), then that the
// run reached A4's state: more than 100 plastic steps, eps_p > 0.45 (4000 /s for 1.2e-4 s:
// eps ~ 0.48) at eps_p_dot = 4000 /s within 2 %. Then the stress-plastic-strain curve
// against the offline integration of the same law with adiabatic heating
// (integrate_adiabatic: the run's own temperature is not used): within 1 % from eps_p = 0.01.
// That constant-rate uniaxial-stress reference is NOT met for SCG, PTW: 2.36 %, 1.81 % at
// eps_p = 0.011-0.03 (printed; `offline_within_1pct` false; MTS, above, meets it since
// session 15: its 1.15 % was the explicit sigma_e update). Measured cause
// (session 14): not a rate still rising to 4000 /s: the particle's lateral inertia. The
// one-particle specimen starts in uniaxial strain and its lateral contraction rings: the
// equivalent deviatoric strain rate (2/3) d(ln F_zz - ln F_xx)/dt is 2661, 3617, 4363, 4572,
// 4478, 4310 /s over the first steps (uniaxial stress: 4000), the plastic rate overshoots to
// ~4300 /s at eps_p = 0.01, and the volume J (hence p and rho in SCG's mu(p, eta) and PTW's
// mu(rho), xi_dot(rho)) rings with it. SCG's thermal stress is at its drag limit at 4000 /s
// (d sigma_t/d eps_p_dot = C_2 = 1.2e4 Pa s: 1 % of q per ~100 /s) and PTW's rate term is
// close behind, so these two feel it most. The reference that the asserted 1 % uses is
// integrate_loading_path driven by the run's own e_eq(t) and J(t) (kinematics only; the
// stress, eps_p, T are integrated offline), at h -> 0 and on the run's own time steps.
template <class Law, class Shear>
void check_sister_deck(const std::string& name, Law&& law, Shear&& shear, bool offline_within_1pct) {
  double last_ep = 0, last_rate = 0;
  int checks = 0;
  const std::string xml = sister_deck_text(name);
  EXPECT_FALSE(xml.empty());
  auto deck = load_deck_from_string(xml, name, test::source_dir() + "/inputs/mpm");
  std::vector<std::pair<double, double>> ep_q;
  double worst = 0, p_prev = 0, width = 0;
  StrainHistory strain;
  run_loaded_deck(std::move(deck), 1.2e-4, [&](double t, double dt, const MpmComponent& c) {
    const MpmMaterial& mat = c.materials()[1];
    const Particles& p = mat.particles;
    const double ep = p.history[0][0], rate = p.history[1][0];
    strain.record(t, p.F[0]);
    const double p_start = p_prev;
    p_prev = -p.stress[0].trace() / 3.0;
    if (t <= 0 || ep < 0.01 || !(rate > 0)) return;
    const double q = von_mises(p.stress[0]);
    const double rho = 8930.0 / p.F[0].determinant();
    const double lo = law(SisterState{ep, rate, p.temperature[0], p_start, rho});
    const double hi = law(SisterState{ep, rate, p.temperature[0] - mat.heating[0] * dt, p_start, rho});
    EXPECT_LE(lo, hi);
    worst = std::max(worst, q < lo ? (lo - q) / q : (q > hi ? (q - hi) / q : 0.0));
    width = std::max(width, (hi - lo) / q);
    ep_q.emplace_back(ep, q);
    if (ep_q.size() == 1 || (ep >= 0.03 && ep_q[ep_q.size() - 2].first < 0.03))
      std::printf("%s: run at eps_p = %.4f: eps_p_dot %.0f /s, T %.2f K, q %.4e Pa\n", name.c_str(), ep, rate,
                  p.temperature[0], q);
    last_ep = ep;
    last_rate = rate;
    ++checks;
  });
  const OfflineCurve offline = integrate_adiabatic(
      0.5, [&](double ep, double T, double, double p_bar) { return law(SisterState{ep, 4000.0, T, p_bar, 8930.0}); },
      [](double, double) { return 0.0; });
  const double off = worst_against_offline(ep_q, offline);
  std::printf("%s: stress-plastic strain curve vs offline adiabatic integration: max |q/sigma_offline - 1| = %.3e "
              "(sigma_offline(0.45) = %.4e Pa)\n", name.c_str(), off, offline.at(0.45));
  if (offline_within_1pct) EXPECT_LT(off, 0.01);
  double path_continuous = 0;
  const double path = check_against_path(
      name, ep_q, [&](double ep, double rate, double T, double, double p_bar, double rho) {
        return law(SisterState{ep, rate, T, p_bar, rho});
      }, [](double, double, double) { return 0.0; }, shear, strain, &path_continuous);
  EXPECT_LT(path, 0.01);             // on the run's own time steps
  EXPECT_LT(path_continuous, 0.01);  // h -> 0 (1e-8, 5e-9 s): also the run's time-step error within 1 %
  std::printf("%s: %d checks, max excursion of q outside [law(T_p), law(T_p - heating dt)] %.3e, widest bracket "
              "(hi - lo)/q %.2e, final eps_p %.4f, eps_p_dot %.1f /s\n",
              name.c_str(), checks, worst, width, last_ep, last_rate);
  EXPECT_LT(width, 2e-3);  // the bracket is one step's heating wide: the check pins q to ~1e-3
  EXPECT_GT(checks, 100);
  EXPECT_LT(worst, 1e-9);
  EXPECT_GT(last_ep, 0.45);
  EXPECT_NEAR(last_rate / 4000.0, 1.0, 0.02);
}

// ZA (VT 10.8-10.10) with the deck's constants: B = K = 0, so
//   sigma_y = sigma_g + k_H sqrt_l_inv + B_0 sqrt(eps_p) exp(-(alpha_0 - alpha_1 ln eps_p_dot) T).
TEST(MetalDecks, A4ZaSisterDeckFollowsTheZerilliArmstrongLaw) {
  auto za = [](const SisterState& s) {
    return 46.5e6 + 5.0e6 * 3.7 + 890e6 * std::sqrt(s.ep) * std::exp(-(0.0028 - 0.000115 * std::log(s.rate)) * s.T);
  };
  check_sister_deck("adiCuZA4000s696K.ups", za, [](double, double, double) { return 46.0e9; }, true);  // constant_shear
}

// SCG (VT 10.4-10.7) with the deck's constants and scg_shear (VT 7.6):
//   sigma_y = [min(sigma_0 (1 + beta eps_p)^n, Y_max) + sigma_t] mu/mu_0,
//   mu = mu_0 [1 + A p̄/eta^{1/3} - B (T - 300)],  eta = rho/rho_0,
//   sigma_t in [0, sigma_P] solving eps_p_dot = [exp(2U_k/(k_B T) (1 - sigma_t/sigma_P)^2)/C1 + C2/sigma_t]^{-1}
// (bisection here: the rate increases with sigma_t).
TEST(MetalDecks, A4ScgSisterDeckFollowsTheSteinbergCochranGuinanLaw) {
  auto scg = [](const SisterState& s) {
    const double mu0 = 47.7e9, A = 28.0e-12, B = 0.92e-3, C1 = 0.71e6, C2 = 0.012e6, Uk = 0.31, kB = 8.617385e-5,
                 sP = 0.5e8;
    const double mu = mu0 * (1 + A * s.p_bar / std::cbrt(s.rho / 8930.0) - B * (s.T - 300.0));
    auto rate_of = [&](double st) {
      const double u = 1 - st / sP;
      return 1.0 / (std::exp(2 * Uk / (kB * s.T) * u * u) / C1 + C2 / st);
    };
    double lo = 0, hi = sP;
    if (rate_of(sP) <= s.rate) {
      lo = sP;
    } else {
      for (int i = 0; i < 200; ++i) (rate_of(0.5 * (lo + hi)) < s.rate ? lo : hi) = 0.5 * (lo + hi);
    }
    const double sigma_t = 0.5 * (lo + hi);
    return (std::min(0.125e9 * std::pow(1 + 36 * s.ep, 0.45), 0.64e9) + sigma_t) * mu / mu0;
  };
  auto scg_shear = [](double T, double p_bar, double rho) {
    return 47.7e9 * (1 + 28.0e-12 * p_bar / std::cbrt(rho / 8930.0) - 0.92e-3 * (T - 300.0));
  };
  check_sister_deck("adiCuSCG4000s696K.ups", scg, scg_shear, false);  // const-rate 2.36 %; path 0.91 %
}

// PTW (VT 10.24-10.28, psi = eps_p: inventory erratum) with the deck's constants:
//   sigma_y = 2 mu [tau_s + a ln(1 - phi exp(-b - theta eps_p/(a phi)))],  a = (s0 - tau_y)/d,
//   b = (tau_s - tau_y)/a,  phi = exp(b) - 1,  with r = eps_p_dot/(gamma xi_dot), z = kappa (T/T_m) ln(1/r):
//   tau_s = max(s0 - (s0 - sinf) erf z, s0 r^beta),  tau_y = max(y0 - (y0 - yinf) erf z, min(y1 r^y2, s0 r^beta)),
//   xi_dot = 1/2 (4 pi rho/(3 M))^{1/3} sqrt(mu/rho)  (M in kg: 63.54 amu).
// mu (np_shear, VT 7.7-7.8) and T_m (scg_Tm, VT 13.1) come from the model's own shear and
// melting sub-models at the start-of-step state (their closed forms: test_submodel_oracles).
TEST(MetalDecks, A4PtwSisterDeckFollowsThePrestonTonksWallaceLaw) {
  const auto deck = load_deck_from_string(sister_deck_text("adiCuPTW4000s696K.ups"), "adiCuPTW4000s696K.ups",
                                          test::source_dir() + "/inputs/mpm");
  auto component = make_mpm_component(*deck);
  component->initialize();
  const auto& model = static_cast<const ElasticPlastic&>(*component->materials()[1].model);
  ASSERT_EQ(model.flow_->type(), "preston_tonks_wallace");
  ASSERT_EQ(model.shear_->type(), "np_shear");
  auto ptw = [&](const SisterState& s) {
    PlasticState st;
    st.temperature = s.T;
    st.density0 = 8930.0;
    st.density = s.rho;
    st.pressure = s.p_bar;
    st.melt_temperature = model.melt_->melt_temperature(st);
    const double mu = model.shear_->shear_modulus(st), Tm = st.melt_temperature;
    const double theta = 0.025, d = 2.0, s0 = 0.0085, sinf = 0.00055, kappa = 0.11, gamma = 1e-5, y0 = 1e-4,
                 yinf = 1e-4, y1 = 0.094, y2 = 0.575, beta = 0.25, M = 63.54 * 1.66053906660e-27;
    const double xi_dot = 0.5 * std::cbrt(4 * M_PI * s.rho / (3 * M)) * std::sqrt(mu / s.rho);
    const double r = s.rate / (gamma * xi_dot), z = kappa * s.T / Tm * std::log(1 / r);
    const double ts = std::max(s0 - (s0 - sinf) * std::erf(z), s0 * std::pow(r, beta));
    const double ty = std::max(y0 - (y0 - yinf) * std::erf(z), std::min(y1 * std::pow(r, y2), s0 * std::pow(r, beta)));
    if (ty >= ts) return 2 * mu * ts;
    const double a = (s0 - ty) / d, b = (ts - ty) / a, phi = std::exp(b) - 1;
    return 2 * mu * (ts + a * std::log(1 - phi * std::exp(-b - theta * s.ep / (a * phi))));
  };
  auto np_shear = [&](double T, double p_bar, double rho) {
    PlasticState st;
    st.temperature = T;
    st.density0 = 8930.0;
    st.density = rho;
    st.pressure = p_bar;
    st.melt_temperature = model.melt_->melt_temperature(st);
    return model.shear_->shear_modulus(st);
  };
  check_sister_deck("adiCuPTW4000s696K.ups", ptw, np_shear, false);  // const-rate 1.81 %; path 0.40 %
}

// A sister deck through the executable, to its end (3e-4 s): exit 0, no NaN (one test per deck:
// ~10 s each).
void run_sister_deck_executable(const std::string& name) {
  const fs::path dir = fs::path(test::scratch_dir("metal_sister_" + name));
  std::string out;
  ASSERT_EQ(test::run_tephra(sister_deck_path(name + ".ups") + " --quiet --output " + (dir / "out").string(), &out), 0)
      << out;
  std::ifstream in(dir / "out" / "BndyForce_zplus.dat");
  ASSERT_TRUE(in);
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(line.find("nan"), std::string::npos) << line;
  }
  EXPECT_GE(rows, 250);  // outputInterval 1e-6 over 3e-4 s
}
TEST(MetalDecks, A4PtwSisterRunsToTheEndThroughTheExecutable) {
  run_sister_deck_executable("adiCuPTW4000s696K");
}
TEST(MetalDecks, A4ScgSisterRunsToTheEndThroughTheExecutable) {
  run_sister_deck_executable("adiCuSCG4000s696K");
}
TEST(MetalDecks, A4MtsSisterRunsToTheEndThroughTheExecutable) {
  run_sister_deck_executable("adiCuMTS4000s696K");
}
TEST(MetalDecks, A4ZaSisterRunsToTheEndThroughTheExecutable) {
  run_sister_deck_executable("adiCuZA4000s696K");
}

// The deck through the executable: every saved label exists, the run ends with exit 0.
TEST(MetalDecks, A4RunsToTheEndThroughTheExecutable) {
  const fs::path dir = fs::path(test::scratch_dir("metal_a4")) / "out";
  std::string out;
  ASSERT_EQ(test::run_tephra(deck_path("adiCuJC4000s696K.ups") + " --quiet --output " + dir.string(), &out), 0) << out;
  std::ifstream in(dir / "BndyForce_zplus.dat");
  ASSERT_TRUE(in);
  std::string line;
  int rows = 0;
  while (std::getline(in, line)) {
    ++rows;
    EXPECT_EQ(line.find("nan"), std::string::npos) << line;
  }
  EXPECT_GE(rows, 250);  // outputInterval 1e-6 over 3e-4 s
}

TEST(MetalDecks, A5TaylorImpactEnergySymmetryAndDamage) {
  const double end = 1.5e-6;  // ~35 steps of the deck's 80 us (the wave has crossed ~7 mm)
  double ke0 = 0, wp = 0, worst_sym = 0, worst_com = 0, max_loss = -1, min_loss = 1, last_loss = 0;
  std::map<long long, std::size_t> index;   // particle id -> row
  std::map<std::size_t, std::size_t> mirror;  // row -> row of the x <-> z mirror particle
  std::vector<double> ep_prev, d_prev;
  bool damage_ok = true;
  double damage_max = 0;
  // The deck as written: timestep_multiplier 0.8 is stable with the velocity gradient
  // from the updated particle velocities at under-filled nodes (mpm/UpdatedGridVelocity.h;
  // with Vaango's v*_g the surface nodes diverge x3 per step), and <materials>[0] with
  // the direction-based rigid contact acts on every material, as in Vaango.
  const std::vector<std::pair<std::vector<std::string>, std::string>> edits = {};
  run_deck("Impact/cylinderImpact_A_JC.ups", end, [&](double t, double, const MpmComponent& c) {
    const MpmMaterial& mat = c.materials()[1];
    const Particles& p = mat.particles;
    if (t == 0) {
      ke0 = 0;
      for (std::size_t i = 0; i < p.size(); ++i) ke0 += 0.5 * p.mass[i] * p.v[i].squaredNorm();
      // Mirror pairs from the seeding positions (x and z are seeded on the same lattice).
      std::map<std::tuple<long, long, long>, std::size_t> at;
      auto key = [](const Vec3& x) {
        return std::make_tuple(std::lround(x[0] * 1e7), std::lround(x[1] * 1e7), std::lround(x[2] * 1e7));
      };
      for (std::size_t i = 0; i < p.size(); ++i) at[key(p.x[i])] = i;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const auto it = at.find(key(Vec3(p.x[i][2], p.x[i][1], p.x[i][0])));
        ASSERT_NE(it, at.end()) << "no mirror for particle " << i;
        mirror[i] = it->second;
      }
      ep_prev.assign(p.size(), 0.0);
      d_prev.assign(p.size(), 0.0);
      return;
    }
    double ke = 0, se = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      ke += 0.5 * p.mass[i] * p.v[i].squaredNorm();
      se += p.energy_density[i] * p.volume0[i];
      wp += mat.plastic_work[i] * p.volume0[i];
      const double ep = p.history[0][i], D = p.history[3][i];
      if (D < d_prev[i] - 1e-15 || (D > d_prev[i] && !(ep > ep_prev[i]))) damage_ok = false;
      damage_max = std::max(damage_max, D);
      ep_prev[i] = ep;
      d_prev[i] = D;
      const std::size_t j = mirror[i];
      worst_sym = std::max(worst_sym, (p.x[i] - Vec3(p.x[j][2], p.x[j][1], p.x[j][0])).norm() / 3.24e-2);
    }
    max_loss = std::max(max_loss, (ke0 - ke - se - wp) / ke0);
    min_loss = std::min(min_loss, (ke0 - ke - se - wp) / ke0);
    last_loss = (ke0 - ke - se - wp) / ke0;
    const auto r = c.reductions({"TotalMass", "TotalMomentum", "CenterOfMassVelocity"});
    const double M = r.at("TotalMass")[0];
    for (int d = 0; d < 3; ++d)
      worst_com = std::max(worst_com, std::abs(r.at("CenterOfMassVelocity")[d] * M - r.at("TotalMomentum")[d]) /
                                          (227.0 * M));
  }, edits);
  std::printf("A5 (%.1f us): KE0 %.4e J, energy loss (KE0 - KE - SE - Wp)/KE0 min %.4e max %.4e last %.4e, "
              "plastic work %.4e J, max mirror asymmetry %.2e L0, max damage %.3e\n",
              end * 1e6, ke0, min_loss, max_loss, last_loss, wp, worst_sym, damage_max);
  EXPECT_GT(wp, 0.0);
  // The wall stops the first node layer at once: an inelastic collision losing the KE of
  // that node's mass, sum of (1 - d/h) over the bottom particle layers (d = 0.06, 0.42,
  // 0.77 mm below h = 1.057 mm: 1.83 layers of the 92 at res 3) = 2.0 % of KE0 (observed
  // 1.9 % after step 1); the next layers add as the foot spreads (observed 2.6 % at 1.5 us).
  EXPECT_GT(min_loss, 0.0);    // never energy created
  EXPECT_LT(max_loss, 0.035);
  EXPECT_LT(worst_sym, 1e-9);
  EXPECT_LT(worst_com, 1e-12);
  EXPECT_TRUE(damage_ok);
  EXPECT_GT(damage_max, 0.0);
}

// A5 in free flight: the wall moved down to y <= -1.5 mm (one particle layer at
// y = -1.47 mm), so no node is shared with the rod (lowest particles at y = 0.29 mm)
// before ~0.78 us. A rigid translation at 227 m/s has l = 0 exactly; the strain
// energy is round-off (~1e-27 J) and must stay there at the deck's multiplier 0.8.
// With l_p from v*_g at every node (Vaango's USL) the surface nodes reached only by
// the outer particle layer (fill phi ~ 1/18) are unstable above Courant number
// sqrt(4 phi/(2 - phi)) and the strain energy grows x10 per step (1e-22 J after 9
// steps, docs/mpm-stability.md); observed here with the fill switch: < 4e-27 J.
TEST(MetalDecks, A5FreeFlightStaysAtRoundOff) {
  double se_first = 0, se_max = 0;
  int steps = 0;
  run_deck("Impact/cylinderImpact_A_JC.ups", 0.7e-6, [&](double t, double, const MpmComponent& c) {
    if (t == 0) return;
    const Particles& p = c.materials()[1].particles;
    double se = 0;
    for (std::size_t i = 0; i < p.size(); ++i) se += p.energy_density[i] * p.volume0[i];
    if (++steps == 2) se_first = se;
    se_max = std::max(se_max, se);
  }, {{{"MaterialProperties", "MPM", "material", "geom_object", "box", "max"}, "[1.0e-2,-0.15e-2,1.0e-2]"}});
  std::printf("A5 free flight: %d steps, strain energy after step 2 %.3e J, max %.3e J\n", steps, se_first, se_max);
  EXPECT_GE(steps, 8);
  EXPECT_LT(se_max, 1e-25);            // round-off of KE0 = 60 J: ~1e-27 J (USL: 3e-22 J)
  EXPECT_LT(se_max, 10.0 * se_first);  // no growth (USL: x1e5 over these steps)
}


// A5 coarsened, run to rest: the coarsest level of the refinement study
// (tests/bench/taylor_impact_study.py, docs/models/taylor-impact.md): the deck
// unchanged except the grid, isotropic h = 1 mm on [0, 9] x [-3, 36] x [0, 9] mm
// (the wall face y = 0 a grid line; 3 x 3 x 3 particles per cell as the deck),
// to 84 us (the deck's 80 us end is before rest: the rod stops at ~81.5 us at this h). Checks:
//  - at rest: the length L(t) (max y + the particle's half extent (h/6) sum_j |F_yj|) has its
//    minimum inside the run, at t_rest in (70, 84) us, and rises after it (the top's elastic
//    spring-back), so the rod stopped; KE(t_rest) < 0.5 % of KE0;
//  - PlasticWork (mpm/StrainWork.h) = sum over steps and particles of the model's
//    plastic work V0 w_p (the same sum taken here from the step outputs; round-off);
//  - energy: the deficit (KE0 - KE - SE - W_p)/KE0 is never negative (no energy
//    created) and below 4.5 % at the end (study: 4.04 % at 80 us). It is NOT within 2 %: the
//    rigid wall stops the node layer y = 0 every step (an inelastic capture of that
//    layer's momentum: 1.8 % of KE0 at h = 1 mm, first order in h; taylor-impact.md);
//  - final shape, the converging measures of the study (session 16-17): L_rest/L_seed, L at rest
//    over the same measure at t = 0, and the footprint radius ratio R_A/R_A,seed,
//    R_A = sqrt(4 A/pi), A = sum (h/3)^2 |cof(F)_yy| over the first particle row (seeded at
//    y0 < h/3), equal the study's h = 1 mm figures (0.5952 and 2.0546, at the rest frame of 1 us
//    frames) to 0.2 % and 0.5 % -- a quarter and a fifth of the change to the next level (0.5898,
//    2.1024), so a change
//    of the step or the model shows here first.
TEST(MetalDecks, A5CoarseTaylorImpactRunsToRest) {
  const double h = 1e-3, end = 84e-6, l = h / 3.0;
  double ke0 = 0, wp_sum = 0, min_deficit = 1, deficit = 0, ke = 0, wp_reduced = 0;
  std::map<long long, double> y0;  // particle id -> seeded y
  double L_seed = 0, RA_seed = 0, L_rest = 1e9, t_rest = 0, ke_rest = 0, RA = 0, L_end = 0;
  // L (module comment) and the footprint radius R_A of one state of the rod.
  const auto length = [&](const Particles& p) {
    double L = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const Mat3& F = p.F[i];
      L = std::max(L, p.x[i][1] + 0.5 * l * (std::abs(F(1, 0)) + std::abs(F(1, 1)) + std::abs(F(1, 2))));
    }
    return L;
  };
  const auto footprint = [&](const Particles& p) {
    double area = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (y0.at(p.id[i]) >= l) continue;
      const Mat3& F = p.F[i];
      area += l * l * std::abs(F(0, 0) * F(2, 2) - F(0, 2) * F(2, 0));  // cof(F)_yy
    }
    return std::sqrt(4.0 * area / std::acos(-1.0));
  };
  const std::vector<std::pair<std::vector<std::string>, std::string>> edits = {
      {{"Grid", "Level", "Box", "lower"}, "[0.0,-3.0e-3,0.0]"},
      {{"Grid", "Level", "Box", "upper"}, "[9.0e-3,36.0e-3,9.0e-3]"},
      {{"Grid", "Level", "Box", "resolution"}, "[9,39,9]"}};
  const int steps = run_loaded_deck(
      with_saved_label(load_deck(deck_path("Impact/cylinderImpact_A_JC.ups")), "PlasticWork"), end,
      [&](double t, double, const MpmComponent& c) {
    const MpmMaterial& mat = c.materials()[1];
    const Particles& p = mat.particles;
    const auto r = c.reductions({"KineticEnergy", "StrainEnergy", "PlasticWork"});
    if (t == 0) {
      ke0 = r.at("KineticEnergy")[0];
      for (std::size_t i = 0; i < p.size(); ++i) y0[p.id[i]] = p.x[i][1];
      L_seed = length(p);
      RA_seed = footprint(p);
      return;
    }
    for (std::size_t i = 0; i < p.size(); ++i) wp_sum += mat.plastic_work[i] * p.volume0[i];
    ke = r.at("KineticEnergy")[0];
    wp_reduced = r.at("PlasticWork")[0];
    deficit = (ke0 - ke - r.at("StrainEnergy")[0] - wp_reduced) / ke0;
    min_deficit = std::min(min_deficit, deficit);
    if (t < 70e-6) return;
    const double L = length(p);
    if (L < L_rest) {
      L_rest = L;
      t_rest = t;
      ke_rest = ke;
      RA = footprint(p);
    }
    L_end = L;
  }, edits);
  std::printf("A5 at h = 1 mm to rest: %d steps, KE0 %.4f J, rest at %.2f us: KE/KE0 %.3e, L_rest %.4f mm, "
              "L_rest/L_seed %.4f (L_seed %.4f mm), R_A %.4f mm, R_A/R_A,seed %.4f; L(end) - L_rest %.2e mm; "
              "deficit (KE0-KE-SE-Wp)/KE0 end %.4f min %.2e, PlasticWork %.6e J vs step sum %.6e J\n",
              steps, ke0, t_rest * 1e6, ke_rest / ke0, L_rest * 1e3, L_rest / L_seed, L_seed * 1e3, RA * 1e3,
              RA / RA_seed, (L_end - L_rest) * 1e3, deficit, min_deficit, wp_reduced, wp_sum);
  EXPECT_GT(t_rest, 70e-6);
  EXPECT_LT(t_rest, end - 1e-6);  // stopped inside the run
  EXPECT_GT(L_end, L_rest);       // and springs back after
  EXPECT_LT(ke_rest / ke0, 5e-3);
  EXPECT_NEAR(wp_reduced, wp_sum, 1e-12 * wp_sum);
  EXPECT_GE(min_deficit, 0.0);
  EXPECT_LT(deficit, 0.045);
  EXPECT_NEAR(L_rest / L_seed, 0.5952, 0.002 * 0.5952);
  EXPECT_NEAR(RA / RA_seed, 2.0546, 0.005 * 2.0546);
}

}  // namespace
}  // namespace tephra
