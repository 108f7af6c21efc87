// The rate laws of the MPMICE mass-conversion models DDT0, Test and
// SolidReactionModel (mpmice/Ddt0.h, mpmice/TestMassModel.cpp,
// mpmice/SolidReaction.h) against their closed forms (the formulas of
// Uintah's HEChem/DDT0.cc, Models/TestModel.cc and
// Models/SolidReactionModel/*.cc, restated in those headers), and their deck
// checks (DeckError / MissingFeature naming the element).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "core/base/Errors.h"
#include "core/deck/DeckLoader.h"
#include "mpmice/BurnModels.h"
#include "mpmice/Ddt0.h"
#include "mpmice/MesoBurn.h"
#include "mpmice/MpmIceComponent.h"
#include "mpmice/SolidReaction.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

Ddt0Params ddt0_params() {
  Ddt0Params p;
  p.jwl_pressure = 5.3e9;
  p.sb_pressure = 2e5;
  p.volume_fraction = 0.01;
  p.G = 2.33e-6;
  p.b = 1.2;
  p.E0 = 5.4e6;
  p.threshold_temperature = 400;
  p.enthalpy = 2e6;
  p.burn_coeff = 75.3;
  p.ref_pressure = 101325;
  p.rho0 = 1800;
  return p;
}

TEST(MpmIceDdt0, BranchesFollowThePressureThresholds) {
  const Ddt0Params p = ddt0_params();
  EXPECT_EQ(ddt0_branch(p, 6e9, 0.5, false), Ddt0Branch::Detonating);
  EXPECT_EQ(ddt0_branch(p, 6e9, 0.005, true), Ddt0Branch::None);  // theta_r below ThresholdVolFrac
  EXPECT_EQ(ddt0_branch(p, 1e6, 0.5, true), Ddt0Branch::Deflagrating);
  EXPECT_EQ(ddt0_branch(p, 1e6, 0.5, false), Ddt0Branch::None);  // not a surface (nor cracked) cell
  EXPECT_EQ(ddt0_branch(p, 1e5, 0.5, true), Ddt0Branch::None);   // below ThresholdPressureSB
}

TEST(MpmIceDdt0, DetonationIsTheJwlppLawWithTheFCutOff) {
  const Ddt0Params p = ddt0_params();
  const double P = 1e10, Mr = 3e-3, Mp = 1e-3, V = 1e-6, dt = 1e-9;
  const Ddt0Detonation d = ddt0_detonation(p, P, Mr, Mp, V, dt);
  // F = Mp/(Mr + Mp) = 0.25; delF = G P^b (1 - F) dt; dm = delF (Mr + Mp) below both caps.
  const double delF = 2.33e-6 * std::pow(1e10, 1.2) * 0.75 * 1e-9;
  EXPECT_DOUBLE_EQ(d.F, 0.25);
  EXPECT_NEAR(d.delF, delF, 1e-14 * delF);
  EXPECT_NEAR(d.mass, delF * 4e-3, 1e-14 * delF * 4e-3);
  ASSERT_LT(d.mass, 0.2 * 1800 * V);
  // The 20 % cap (Souers' p. 55): with a long step dm = 0.2 rho0 V.
  EXPECT_DOUBLE_EQ(ddt0_detonation(p, P, Mr, Mp, V, 1e-3).mass, std::min(Mr, 0.2 * 1800 * V));
  // DDT0's cut-off: F >= 0.99 reacts no more (DDT1 goes on to F = 1).
  const Ddt0Detonation late = ddt0_detonation(p, P, 0.009e-3, 0.991e-3, V, dt);
  EXPECT_GT(late.F, 0.99);
  EXPECT_EQ(late.delF, 0.0);
  EXPECT_EQ(late.mass, 0.0);
}

TEST(MpmIceDdt0, DeflagrationIsTheSimpleBurnLawPlusTheCrackTerm) {
  Ddt0Params p = ddt0_params();
  const double dt = 1e-7, A = 4e-6, P = 1e6, F = 0.3;
  // Hot: dm = dt A BurnCoeff (P/refPressure)^0.778.
  const double sb = dt * A * 75.3 * std::pow(1e6 / 101325, 0.778);
  EXPECT_NEAR(ddt0_deflagration_mass(p, dt, A, P, 500, F, false), sb, 1e-14 * sb);
  EXPECT_EQ(ddt0_deflagration_mass(p, dt, A, P, 0, F, false), 0.0);  // no material above ThresholdTemp
  EXPECT_EQ(ddt0_deflagration_mass(p, dt, A, P, 0, F, true), 0.0);   // cracked, but no crack model
  // Crack model: + Gcrack (1 - F) (P/refPressure)^nCrack (Uintah's term, no dt),
  // in hot cells and in cracked cold ones.
  p.crack_model = true;
  p.g_crack = 1e-9;
  p.n_crack = 0.5;
  const double crack = 1e-9 * 0.7 * std::sqrt(1e6 / 101325);
  EXPECT_NEAR(ddt0_deflagration_mass(p, dt, A, P, 500, F, false), sb + crack, 1e-14 * (sb + crack));
  EXPECT_NEAR(ddt0_deflagration_mass(p, dt, A, P, 0, F, true), crack, 1e-14 * crack);
  EXPECT_EQ(ddt0_deflagration_mass(p, dt, A, P, 0, F, false), 0.0);
  // Axisymmetric (session 25): the crack term is a mass per Cartesian cell, so a
  // per-radian cell of r_c dx dy = (r_c/dz) dx dy dz carries r_c/dz of it; the
  // Simple_Burn part already has the per-radian area A.
  EXPECT_NEAR(ddt0_deflagration_mass(p, dt, A, P, 500, F, false, 3.5), sb + 3.5 * crack, 1e-14 * (sb + 3.5 * crack));
  EXPECT_NEAR(ddt0_deflagration_mass(p, dt, A, P, 0, F, true, 0.5), 0.5 * crack, 1e-14 * crack);
}

TEST(MpmIceTestModel, FractionIsRateTimesDtCappedAtOne) {
  EXPECT_DOUBLE_EQ(test_model_fraction(1000.0, 1e-4), 0.1);
  EXPECT_DOUBLE_EQ(test_model_fraction(1000.0, 2e-3), 1.0);
  EXPECT_DOUBLE_EQ(test_model_fraction(0.0, 1e-4), 0.0);
}

TEST(MpmIceSolidReaction, RateConstantsAreArrheniusForms) {
  const double R = 8.314462175, T = 600;
  RateConstantLaw k;
  k.A = 1e12;
  k.Ea = 2 * R * T;  // Ea/(R T) = 2: k = A e^-2
  EXPECT_NEAR(k.k(T), 1e12 * std::exp(-2.0), 1e-14 * 1e12);
  k.kind = RateConstantLaw::Kind::ModifiedArrhenius;
  k.b = 0.5;  // k = A T^b e^-2
  EXPECT_NEAR(k.k(T), 1e12 * std::sqrt(600.0) * std::exp(-2.0), 1e-14 * 1e12 * std::sqrt(600.0));
}

TEST(MpmIceSolidReaction, RateModelsAreTheirClosedForms) {
  using K = RateModelLaw::Kind;
  RateModelLaw f;
  f.kind = K::ContractingCylinder;  // 2 (1 - F)^(1/2): 1 - F = 1/4 gives 1
  EXPECT_DOUBLE_EQ(f.f(0.75), 1.0);
  f.kind = K::ContractingSphere;  // 3 (1 - F)^(2/3): 1 - F = 1/8 gives 3/4
  EXPECT_NEAR(f.f(0.875), 0.75, 1e-15);
  f.kind = K::AvaramiErofeev;  // a (1 - F) (-ln(1 - F))^b: 1 - F = e^-2 gives a e^-2 2^b
  f.a = 3;
  f.b = 0.5;
  EXPECT_NEAR(f.f(1 - std::exp(-2.0)), 3 * std::exp(-2.0) * std::sqrt(2.0), 1e-14);
  f.kind = K::Diffusion;  // 1: F/2; 2: 1/(-ln(1 - F)); 3 (Jander): 3 r^(2/3)/(2 (1 - r^(1/3)))
  f.dimension = 1;
  EXPECT_DOUBLE_EQ(f.f(0.3), 0.15);
  f.dimension = 2;
  EXPECT_NEAR(f.f(1 - std::exp(-2.0)), 0.5, 1e-14);
  f.dimension = 3;  // r = 1/8: 3 (1/4)/(2 (1/2)) = 3/4
  EXPECT_NEAR(f.f(0.875), 0.75, 1e-14);
  f.kind = K::NthOrder;  // (1 - F)^n
  f.n = 3;
  EXPECT_DOUBLE_EQ(f.f(0.5), 0.125);
  f.n = 0;
  EXPECT_DOUBLE_EQ(f.f(0.5), 1.0);
  f.kind = K::Power;  // a F^b
  f.a = 3;
  f.b = 0.5;
  EXPECT_DOUBLE_EQ(f.f(0.25), 1.5);
  f.kind = K::ProutTompkins;  // F^n (1 - q F)^m
  f.n_real = 2;
  f.q = 1;
  f.m = 3;
  EXPECT_DOUBLE_EQ(f.f(0.5), 0.25 * 0.125);
}

TEST(MpmIceSolidReaction, DelFIsKTimesFTimesDtForFInZeroOne) {
  RateConstantLaw k;
  k.A = 50;  // Ea = 0: k = A
  RateModelLaw f;
  f.kind = RateModelLaw::Kind::NthOrder;
  f.n = 1;
  EXPECT_DOUBLE_EQ(solid_reaction_delF(k, f, 300, 0.2, 1e-3), 50 * 0.8 * 1e-3);
  EXPECT_EQ(solid_reaction_delF(k, f, 300, 1.0, 1e-3), 0.0);  // all product: F = 1
  EXPECT_EQ(solid_reaction_delF(k, f, 300, std::nan(""), 1e-3), 0.0);  // empty cell: 0/0
}

TEST(MpmIceMesoBurn, InductionTimeIsTheThermalExplosionTime) {
  MesoInduction m;
  m.Ta = 2e4;
  m.k = 1e15;
  m.Cv = 1.5e3;
  m.Qc = 4e5;
  const double T = 500;  // tau = T^2 Cv/(Ta Qc) exp(Ta/T)/k
  const double tau = 500.0 * 500 * 1.5e3 / (2e4 * 4e5) * std::exp(40.0) / 1e15;
  EXPECT_NEAR(meso_induction_time(m, T), tau, 1e-14 * tau);
}

TEST(MpmIceMesoBurn, ClockRelaxesGeometricallyAndCountsTimeAbove470K) {
  MesoInduction m;
  m.Ta = 1000;
  m.k = 1e3;
  m.Cv = 1e3;
  m.Qc = 4e5;
  const double T = 600, dt = 1e-3, t600 = meso_induction_time(m, T);
  MesoClock c;
  bool induced = false;
  int n = 0;
  while (!induced && n < 10000) induced = meso_advance_clock(c, m, T, dt), ++n;
  // Closed form of the recurrence tau <- 0.99 tau + 0.01 t600 from 3.1536e13:
  // tau_n = t600 + 0.99^n (3.1536e13 - t600); t_n = n dt (T > 470 K).
  const double tau_n = t600 + std::pow(0.99, n) * (3.1536e13 - t600);
  EXPECT_NEAR(c.tau, tau_n, 1e-11 * tau_n);
  EXPECT_NEAR(c.time_induced, n * dt, 1e-12 * n * dt);
  EXPECT_GT(n * dt, tau_n);
  const double tau_prev = t600 + std::pow(0.99, n - 1) * (3.1536e13 - t600);
  EXPECT_LE((n - 1) * dt, tau_prev);  // not induced one step earlier
  // At or below 470 K the clock does not run.
  MesoClock cold;
  EXPECT_FALSE(meso_advance_clock(cold, m, 470.0, 1.0));
  EXPECT_EQ(cold.time_induced, 0.0);
}

// --- deck checks, on MPMICE/massX.ups with its <Models> replaced ---------

std::string massx_with_models(const std::string& models) {
  std::ifstream in(test::shared_dir() + "/decks/inputs/MPMICE/massX.ups");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string s = ss.str();
  const auto a = s.find("<Models>"), b = s.find("</Models>");
  return s.substr(0, a) + "<Models>" + models + s.substr(b);
}

void build(const std::string& models) {
  auto deck = load_deck_from_string(massx_with_models(models), "massX_models.ups",
                                    test::shared_dir() + "/decks/inputs/MPMICE");
  make_mpmice_component(*deck);
}

const char* kDdt0 =
    "<Model type=\"DDT0\"><DDT0><fromMaterial>reactant</fromMaterial><toMaterial>product</toMaterial>"
    "<ThresholdPressureJWL>1e9</ThresholdPressureJWL><G>1</G><b>0</b><E0>0</E0>"
    "<Enthalpy>0</Enthalpy><BurnCoeff>1</BurnCoeff><refPressure>1</refPressure>"
    "<ThresholdTemp>299</ThresholdTemp><ThresholdPressureSB>500</ThresholdPressureSB>%</DDT0></Model>";

std::string with(const char* base, const std::string& extra) {
  std::string s = base;
  return s.replace(s.find('%'), 1, extra);
}

TEST(MpmIceMassModelDecks, ValidBlocksBuild) {
  EXPECT_NO_THROW(build(with(kDdt0, "")));
  EXPECT_NO_THROW(build("<Model type=\"Test\"><Test><fromMaterial>reactant</fromMaterial>"
                        "<toMaterial>product</toMaterial><rate>10</rate><startTime>0</startTime></Test></Model>"));
  EXPECT_NO_THROW(build("<Model type=\"SolidReactionModel\"><SolidReactionModel><fromMaterial>reactant</fromMaterial>"
                        "<toMaterial>product</toMaterial><E0>0</E0>"
                        "<RateConstantModel type=\"ModifiedArrhenius\"><A>1</A><Ea>0</Ea><b>1</b></RateConstantModel>"
                        "<RateModel type=\"ProutTompkins\"><q>0.5</q><n>1</n><m>1</m></RateModel>"
                        "</SolidReactionModel></Model>"));
}

TEST(MpmIceMassModelDecks, BadInputIsADeckErrorNamingTheElement) {
  try {
    build(with(kDdt0, "<Bogus>1</Bogus>"));
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("Bogus"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("massX_models.ups"), std::string::npos) << e.what();
  }
  // Missing required <rate>.
  EXPECT_THROW(build("<Model type=\"Test\"><Test><fromMaterial>reactant</fromMaterial>"
                     "<toMaterial>product</toMaterial></Test></Model>"),
               DeckError);
  // The reactant must be the MPM material.
  EXPECT_THROW(build(with(kDdt0, "").replace(with(kDdt0, "").find("reactant"), 8, "product")), DeckError);
  const std::string srm =
      "<Model type=\"SolidReactionModel\"><SolidReactionModel><fromMaterial>reactant</fromMaterial>"
      "<toMaterial>product</toMaterial><E0>0</E0>"
      "<RateConstantModel type=\"Arrhenius\"><A>1</A><Ea>0</Ea></RateConstantModel>%</SolidReactionModel></Model>";
  try {
    build(with(srm.c_str(), "<RateModel type=\"NthOrder\"><n>1.5</n></RateModel>"));
    FAIL() << "no error";
  } catch (const DeckError& e) {
    EXPECT_NE(std::string(e.what()).find("NthOrder"), std::string::npos) << e.what();
  }
  EXPECT_THROW(build(with(srm.c_str(), "<RateModel type=\"Power\"><a>1</a></RateModel>")), DeckError);  // no <b>
  EXPECT_THROW(build(with(srm.c_str(), "")), DeckError);                                                  // no <RateModel>
  // Diffusion of dimension 4: Uintah has no formula (exit 3).
  EXPECT_THROW(build(with(srm.c_str(), "<RateModel type=\"Diffusion\"><dimension>4</dimension></RateModel>")),
               MissingFeature);
}

}  // namespace
}  // namespace tephra
