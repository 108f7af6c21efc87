#pragma once
// Test helpers for solid models: parameters from a map (failures throw
// std::invalid_argument / std::logic_error instead of deck errors), sample
// parameters for every registered model, and a one-point driver over the
// span interface (header-only; tests only).
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/LU>

#include "models/ModelParameters.h"
#include "models/solid/ConstitutiveModel.h"
#include "tests/support/TestPaths.h"

namespace tephra::test {

class MapModelParameters final : public ModelParameters {
 public:
  std::map<std::string, double> values;
  MapModelParameters() = default;
  explicit MapModelParameters(std::map<std::string, double> v) : values(std::move(v)) {}
  bool has(const std::string& n) const override { return values.count(n) > 0; }
  double get_double(const std::string& n) const override {
    if (!has(n)) throw std::invalid_argument("missing " + n);
    return values.at(n);
  }
  double get_double(const std::string& n, double f) const override { return has(n) ? values.at(n) : f; }
  bool get_bool(const std::string& n, bool f) const override { return has(n) ? values.at(n) != 0 : f; }
  [[noreturn]] void fail(const std::string& n, const std::string& m) const override {
    throw std::invalid_argument(n + ": " + m);
  }
  [[noreturn]] void missing_feature(const std::string& n, const std::string& m) const override {
    throw std::logic_error(n + ": " + m);
  }
  // Sub-model blocks (<name type="...">), this block's type attribute, and the
  // values of the enclosing <material> (melt_temp, specific_heat, ...).
  std::map<std::string, std::shared_ptr<MapModelParameters>> blocks;
  std::string type;
  std::map<std::string, double> enclosing;
  // Flags of the deck's <MPM> section (e.g. DoThermalExpansion); absent: the fallback.
  std::map<std::string, bool> mpm_flags;
  bool mpm_flag(const std::string& n, bool f) const override { return mpm_flags.count(n) ? mpm_flags.at(n) : f; }
  MapModelParameters& add_block(const std::string& name, const std::string& key,
                                std::map<std::string, double> v = {}) {
    auto b = std::make_shared<MapModelParameters>(std::move(v));
    b->type = key;
    blocks[name] = b;
    return *b;
  }
  const ModelParameters* block(const std::string& n) const override {
    auto it = blocks.find(n);
    return it == blocks.end() ? nullptr : it->second.get();
  }
  std::string type_attribute() const override { return type; }
  double enclosing_double(const std::string& n, double f) const override {
    return enclosing.count(n) ? enclosing.at(n) : f;
  }
  // Text values (vectors such as "[1, 0, 0]").
  std::map<std::string, std::string> strings;
  std::string get_string(const std::string& n, const std::string& f) const override {
    return strings.count(n) ? strings.at(n) : f;
  }
};

// Parameters of every registered model for the contract tests (a new model
// must add a row: ContractTable.EveryRegisteredModelHasSampleParameters).
// Steel-like moduli (K = 8 GPa, G = 3 GPa); the contracts use relative tolerances.
inline const std::map<std::string, std::map<std::string, double>>& sample_solid_parameters() {
  static const std::map<std::string, std::map<std::string, double>> table = {
      {"comp_neo_hook", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}}},
      {"cnh_mms", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}}},
      {"hypo_elastic", {{"K", 8.0e9}, {"G", 3.0e9}}},
      {"hypo_elastic_mms", {{"K", 8.0e9}, {"G", 3.0e9}}},
      // Failure strain 0.5: far beyond the contracts' small strains (the elastic branch).
      {"cnh_damage", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}, {"failure_variable_mean", 0.5}}},
      // comp_neo_hook_plastic's sample with a failure strain far beyond the contracts' strains.
      {"cnhp_damage", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}, {"yield_stress", 3.0e7},
                       {"hardening_modulus", 1.0e8}, {"failure_variable_mean", 0.5}}},
      // Vaango's const_test_cmr.ups: G = 2 (C1 + C2) = 2.4e5, nu = 0.49.
      {"comp_mooney_rivlin", {{"he_constant_1", 1.0e5}, {"he_constant_2", 2.0e4}, {"he_PR", 0.49}}},
      {"rigid", {}},
      // Yields at a shear strain of ~ sigma_y / (sqrt(3) G) = 6e-3 (the contracts see both branches).
      {"comp_neo_hook_plastic",
       {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}, {"yield_stress", 3.0e7}, {"hardening_modulus", 1.0e8}}},
      // UCNH defaults to usePlasticity = false: the comp_neo_hook stress (hyperelastic contracts).
      {"UCNH", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}}},
      // Blocks and material values: sample_solid_blocks().
      {"elastic_plastic_hp", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}, {"taylor_quinney_coeff", 0.9}}},
      // Vaango's defaults otherwise (alpha = 1e-5: the thermal term is exercised, T_0 = the first T).
      {"elastic_plastic", {{"bulk_modulus", 8.0e9}, {"shear_modulus", 3.0e9}, {"taylor_quinney_coeff", 0.9}}},
      // PBX 9501 crack constants of the stock burn decks; G = sum G_i = 3 GPa and
      // PR = 1/3 give K = 2G(1+nu)/(3(1-2nu)) = 8 GPa; slow relaxation (tau_i >= 1e5 s)
      // and a 10 nm initial crack so the small-strain contract sees the elastic limit.
      {"visco_scram", {{"PR", 1.0 / 3.0}, {"CrackParameterA", 1e-3}, {"CrackPowerValue", 10.0},
                       {"CrackMaxGrowthRate", 300.0}, {"StressIntensityF", 500.0}, {"CrackFriction", 0.35},
                       {"InitialCrackRadius", 1e-8}, {"CrackGrowthRate", 12.0},
                       {"G1", 0.6e9}, {"G2", 0.6e9}, {"G3", 0.6e9}, {"G4", 0.6e9}, {"G5", 0.6e9},
                       {"RTau1", 0.0}, {"RTau2", 1e-6}, {"RTau3", 1e-6}, {"RTau4", 1e-5}, {"RTau5", 1e-5},
                       {"Beta", 1.5e-4}, {"Gamma", 1.0}, {"DCp_DTemperature", 3.30773}}},
      // ---- chapter-3 special materials (solid-models). Air-like gas (K = gamma p_ref).
      {"ideal_gas", {{"gamma", 1.4}, {"specific_heat", 716.0}, {"reference_pressure", 101325.0}}},
      // Tait-like water (K = gamma kappa = 2.2 GPa); no viscosity: the contracts see the EOS only.
      {"water", {{"bulk_modulus", 2.2e9 / 7.15}, {"gamma", 7.15}, {"viscosity", 0.0}}},
      {"murnaghanMPM", {{"K", 8.0e9}, {"Kprime", 4.0}, {"pressure", 101325.0}, {"rho0", 7800.0}, {"viscosity", 0.0}}},
      // ANFO (Souers' JWL++ constants of inputs/ICE/EOSData); ignition at 0.2 GPa with a fast
      // rate and coarse burn substeps so the contracts' paths burn (f is a scalar of J and p: objective).
      {"jwlpp_mpm", {{"ignition_pressure", 2.0e8}, {"viscosity", 0.0}, {"murnaghan_K", 3.9e-10}, {"murnaghan_n", 7.4},
                     {"jwl_A", 2.9867e11}, {"jwl_B", 4.11706e9}, {"jwl_C", 7.206147e8}, {"jwl_R1", 4.95},
                     {"jwl_R2", 1.15}, {"jwl_om", 0.35}, {"reaction_G", 1e-9}, {"reaction_b", 1.0},
                     {"max_burn_timestep_size", 1e-2}}},
      // K = K_e + K_ve = 8 GPa, G = G_e + G_ve = 3 GPa; slow relaxation (tau >= 1e5 s) so the
      // small-strain contract sees the instantaneous moduli.
      {"mw_visco_elastic", {{"e_shear_modulus", 2.0e9}, {"e_bulk_modulus", 6.0e9}, {"ve_shear_modulus", 1.0e9},
                            {"ve_bulk_modulus", 2.0e9}, {"ve_volumetric_viscosity", 6.0e14},
                            {"ve_deviatoric_viscosity", 2.0e14}}},
      // Matrix G = 2 (c1 + c2) = 3 GPa, K = 8 GPa; weak fibres (c3 c4 ~ 1e-12 G, direction in
      // sample_solid_blocks) so the small-strain contracts see the matrix: the fibres are
      // bilinear (no compression) and checked in test_model_trans_iso_hyper.
      {"trans_iso_hyper", {{"bulk_modulus", 8.0e9}, {"c1", 1.0e9}, {"c2", 0.5e9}, {"c3", 1e-3}, {"c4", 3.0},
                           {"c5", 1e-2}, {"fiber_stretch", 1.1}, {"max_fiber_strain", 2.0},
                           {"max_matrix_strain", 2.0}, {"failure_option", 0.0}}},
      // trans_iso_hyper's sample with two slow Prony terms (t >= 1e5 s: the contracts' steps see
      // the instantaneous deviator (1 + 0.3) G; test_model_visco_trans_iso_hyper checks relaxation).
      {"visco_trans_iso_hyper", {{"bulk_modulus", 8.0e9}, {"c1", 1.0e9}, {"c2", 0.5e9}, {"c3", 1e-3}, {"c4", 3.0},
                                 {"c5", 1e-2}, {"fiber_stretch", 1.1}, {"max_fiber_strain", 2.0},
                                 {"max_matrix_strain", 2.0}, {"failure_option", 0.0}, {"y1", 0.2}, {"t1", 1e5},
                                 {"y2", 0.1}, {"t2", 1e6}}},
      // SUVIC-I (flow block in add_sample_blocks) with initial yield and drag stresses of 1 GPa:
      // elastic on the contracts' small strains, slow inelastic flow (~4e-4 /s) on the large paths.
      {"visco_plastic", {{"shear_modulus", 3.0e9}, {"bulk_modulus", 8.0e9}}},
      // p-alpha: alpha_0 = 1.25 at the contracts' rho_0 = 7800 (material values in add_sample_blocks),
      // elastic to J = 1 - Pe/K0 = 0.99; Ku = K0 so tension has the same slope K0 (the small-strain contract).
      {"p_alpha", {{"Ps", 1.0e9}, {"Pe", 8.0e7}, {"rhoS", 9750.0}, {"K0", 8.0e9}, {"Ks", 1.6e11}, {"Ku", 8.0e9},
                   {"T_0", 300.0}, {"C_0", 4500.0}, {"Gamma_0", 1.5}, {"S_alpha", 1.5}}},
      // Polar orthotropic with isotropic constants (E = 8 GPa, nu = 1/3, G = 3 GPa: K = 8 GPa)
      // so the isotropic contracts apply; the orthotropy: test_model_polar_orthotropic_hypoelastic.
      {"polar_orthotropic_hypoelastic", {{"E_r", 8.0e9}, {"E_theta", 8.0e9}, {"E_z", 8.0e9}, {"nu_theta_r", 1.0 / 3},
                                         {"nu_z_r", 1.0 / 3}, {"nu_z_theta", 1.0 / 3}, {"G_theta_z", 3.0e9},
                                         {"G_z_r", 3.0e9}, {"G_r_theta", 3.0e9}}},
      // Programmed burn with jwlpp_mpm's ANFO constants; the front starts 100 km away
      // (strings in add_sample_blocks), so the contracts see the unreacted Murnaghan solid.
      {"program_burn", {{"K", 3.9e-10}, {"n", 7.4}, {"A", 2.9867e11}, {"B", 4.11706e9}, {"C", 7.206147e8},
                        {"R1", 4.95}, {"R2", 1.15}, {"om", 0.35}, {"rho0", 7800.0}, {"D", 8000.0}}},
      // ---- geomaterials (solids-geo). Cam-Clay: a clay at p = -100 kPa (K = -p/kt = 1 MPa,
      // G = mu0 + alpha |p0| = 5.5 MPa), over-consolidated to p_c = -200 kPa (the reference
      // state is the critical-state point of the ellipse); sub-model blocks in add_sample_blocks.
      // kt = 0.1: p ~ exp(-eps_v/kt), so the contracts' central differences of dp/drho
      // (h = 1e-4 rho) keep their truncation error (h/(kt rho))^2/6 below 1e-6.
      {"camclay", {}},
      // Mohr-Coulomb (classic): K = 8 GPa, G = 3 GPa, c = 10 MPa, phi = 30, psi = 10 degrees (blocks
      // in add_sample_blocks): elastic below shear strains ~1e-3, plastic on the contracts' large paths.
      {"mohr_coulomb", {}},
      // Tabular EOS (solids, VT §22.2): tests/support/tabular_eos_sample.json (file names in
      // add_sample_blocks), slopes 4, 6, 8, 12, 20 GPa; K = dp/deta = 8 GPa on [0.95, 1.05], p(1) = 0,
      // so the small-strain contract and the hooks' central differences at x = 0.9, 1, 1.1 stay
      // inside one segment.
      {"tabular_eos", {}},
  };
  return table;
}

// The sub-model blocks and enclosing-material values of the composed models'
// samples (von Mises with linear hardening, sigma_0 = 30 MPa: yields at a
// shear strain of ~1e-2, so the contracts see both branches).
inline void add_sample_blocks(const std::string& type, MapModelParameters& p) {
  if (type == "visco_scram") p.enclosing = {{"specific_heat", 996.0}};  // heating needs c_v
  if (type == "trans_iso_hyper" || type == "visco_trans_iso_hyper") p.strings["direction_of_symm"] = "[0.6, 0.8, 0]";
  if (type == "polar_orthotropic_hypoelastic") {
    p.strings["symmetry_axis_top"] = "[0, 0, 1]";
    p.strings["symmetry_axis_bottom"] = "[0, 0, 0]";
  }
  if (type == "program_burn") p.strings["starting_location"] = "[1e5, 0, 0]";
  if (type == "tabular_eos") {
    p.strings["filename"] = source_dir() + "/tests/support/tabular_eos_sample.json";
    p.strings["independent_variables"] = "DensityRatio";
    p.strings["dependent_variables"] = "Pressure";
    p.add_block("interpolation", "linear");
  }
  if (type == "p_alpha") p.enclosing = {{"density", 7800.0}, {"specific_heat", 450.0}};
  if (type == "visco_plastic") {
    p.enclosing = {{"specific_heat", 2000.0}};  // plastic heating needs c_p
    p.add_block("viscoplastic_flow_model", "suvic_i", {{"initial_yield", 1.0e9}, {"initial_drag", 1.0e9}});
    return;
  }
  if (type == "mohr_coulomb") {
    p.strings["model_type"] = "classic";
    p.add_block("model_parameters", "",
                {{"shear_modulus", 3.0e9}, {"bulk_modulus", 8.0e9}, {"cohesion", 1.0e7},
                 {"angle_internal_friction", 30.0}, {"angle_dilation", 10.0}});
    p.add_block("integration_parameters", "");
    return;
  }
  if (type == "camclay") {
    p.add_block("equation_of_state", "borja_pressure",
                {{"p0", -1.0e5}, {"alpha", 5.0}, {"kappatilde", 0.1}, {"epse_v0", 0.0}});
    p.add_block("shear_modulus_model", "borja_shear", {{"mu0", 5.0e6}});
    p.add_block("yield_condition", "camclay", {{"M", 1.2}});
    p.add_block("internal_variable_model", "borja_consolidation_pressure", {{"pc0", -2.0e5}, {"lambdatilde", 0.4}});
    return;
  }
  if (type != "elastic_plastic_hp" && type != "elastic_plastic") return;
  p.add_block("yield_condition", "von_mises");
  p.add_block("flow_model", "linear", {{"sigma_0", 3.0e7}, {"K", 1.0e8}});
  p.enclosing = {{"melt_temp", 1356.0}, {"specific_heat", 414.0}, {"density", 8930.0}};
}

// Contract exceptions of special materials (each with its reason, VT ch. 3):
//  tensionless: sigma = 0 for J >= 1 (ideal_gas, VT eq. 3.3-3.4): the small-strain
//    limit is checked on a compressive path;
//  thermal hooks: the MPMICE hooks are a thermal EOS p(rho, T) (ideal_gas: (gamma-1) rho c_v T),
//    not the mechanical p(J): no p(rho0) = 0 / dp/drho = K/rho0 reference checks.
inline bool sample_is_tensionless(const std::string& type) { return type == "ideal_gas"; }
inline bool sample_has_thermal_hooks(const std::string& type) { return type == "ideal_gas"; }
//  prestressed: the reference state (F = I, no history) carries an isotropic stress
//    sigma_0 = p(0) I (camclay: Borja's p = p0 exp(eps_v0/kt) != 0, VT §20.2.1); the
//    contracts check sigma - sigma_0 and that sigma_0 is isotropic and kept.
inline bool sample_is_prestressed(const std::string& type) { return type == "camclay"; }

inline ConstitutiveModelP make_sample_model(const std::string& type) {
  MapModelParameters p(sample_solid_parameters().at(type));
  add_sample_blocks(type, p);
  return create_constitutive_model(type, p);
}

// One material point carried through steps of the span interface.
struct PointState {
  Eigen::Matrix3d F = Eigen::Matrix3d::Identity();
  Eigen::Matrix3d stress = Eigen::Matrix3d::Zero();
  double temperature = 300.0;
  std::vector<std::vector<double>> history;
  double wave_speed = 0, energy_density = 0, plastic_work = 0, heating = 0;
  Eigen::Vector3d x = Eigen::Vector3d::Zero();  // position (point context)
  double time = 0.0;                            // t_n; step_point passes t_n + dt
  double volume0 = 1e-9;                        // reference volume V0 [m^3] (a 1 mm cube)

  explicit PointState(const ConstitutiveModel& m) {
    for (const HistoryVariable& h : m.history()) history.push_back(h.initial);
  }
};

// One step F_n = s.F -> F_new with l = (F_new F_n^{-1} - I)/dt. Returns the
// model's return code (-1 on success); on success s holds the new state.
inline long step_point(const ConstitutiveModel& m, double density0, PointState& s, const Eigen::Matrix3d& F_new,
                       double dt) {
  const Eigen::Matrix3d F_old = s.F;
  const Eigen::Matrix3d L = dt > 0 ? Eigen::Matrix3d((F_new * F_old.inverse() - Eigen::Matrix3d::Identity()) / dt)
                                   : Eigen::Matrix3d::Zero();
  const Eigen::Matrix3d stress_old = s.stress;
  std::vector<std::span<double>> hist(s.history.begin(), s.history.end());
  SolidUpdateInput in;
  in.dt = dt;
  in.density0 = density0;
  in.F_old = {&F_old, 1};
  in.F_new = {&F_new, 1};
  in.L = {&L, 1};
  in.temperature = {&s.temperature, 1};
  in.stress_old = {&stress_old, 1};
  const Eigen::Vector3d x = s.x;
  in.position = {&x, 1};
  in.time = s.time + dt;
  in.reference_volume = {&s.volume0, 1};
  const SolidUpdateOutput out{{&s.stress, 1},       {&s.wave_speed, 1}, {&s.energy_density, 1},
                              {&s.plastic_work, 1}, {&s.heating, 1},    hist};
  const long r = m.update(in, out);
  s.F = F_new;
  s.time += dt;
  return r;
}

// Drives the point along F(t) = path(k / n), k = 1..n, over total time 1.
template <class Path>
PointState drive_path(const ConstitutiveModel& m, double density0, Path&& path, int n) {
  PointState s(m);
  if (step_point(m, density0, s, Eigen::Matrix3d::Identity(), 0.0) != -1) throw std::runtime_error("init failed");
  for (int k = 1; k <= n; ++k)
    if (step_point(m, density0, s, path(double(k) / n), 1.0 / n) != -1) throw std::runtime_error("step failed");
  return s;
}

}  // namespace tephra::test
