#pragma once
// The point functions of <Model type="DDT0"> (Uintah's and Vaango's
// HEChem/DDT0.cc, read for the rules and parameter names; used by
// mpmice/Ddt0Model.cpp): the older deflagration-to-detonation model, Simple_Burn
// surface burning below a pressure threshold and JWL++ detonation above it.
// Per interior cell, with p_c the cell's equilibration pressure:
//   * detonation (JWL++, Souers' rate law): p_c > <ThresholdPressureJWL> and
//     theta_r > <ThresholdVolFrac> (default 0.01):
//        F = rho_p/(rho_r + rho_p),  delF = G p_c^b (1 - F) dt  (0 once F >= 0.99,
//        DDT0's cut-off; DDT1 uses F >= 1),
//        dm = min(delF (M_r + M_p), M_r, 0.2 rho0 V)   (mpmice/Ddt1.h: the same law);
//     heat released E0 dm;
//   * deflagration: <ThresholdPressureSB> < p_c < <ThresholdPressureJWL>, and
//     the cell is a Simple_Burn surface cell (0.4 < (max - min)/max < 1 over
//     the corner values w_n m_n, mpmice/SimpleBurn.h) or, with
//     <useCrackModel>, "cracked enough" (some reactant particle's crack
//     radius above w(p_c) = sqrt(8e8/p_c^2.84), mpmice/Ddt1.h). T = the
//     hottest material with theta > 0.2 above <ThresholdTemp> (0 if none);
//       dm = dt A BurnCoeff (p_c/refPressure)^0.778            if T > ThresholdTemp,
//       + Gcrack (1 - F) (p_c/refPressure)^nCrack              if T > ThresholdTemp or cracked
//         (with <useCrackModel> only: Uintah's crack term, a mass per step, not
//         multiplied by dt - kept as Uintah has it),
//     at most M_r; heat released <Enthalpy> dm. A is the Simple_Burn area of
//     the corner values.
// <CrackVolThreshold> (default 1e-14) only changes a temperature Uintah does
// not use afterwards: read, no effect.
namespace tephra {

enum class Ddt0Branch { None = 0, Detonating = 1, Deflagrating = 2 };

struct Ddt0Params {
  double jwl_pressure = 0;        // <ThresholdPressureJWL> [Pa]
  double sb_pressure = 0;         // <ThresholdPressureSB> [Pa]
  double volume_fraction = 0.01;  // <ThresholdVolFrac>
  double G = 0, b = 0, E0 = 0;    // JWL++: rate constant [1/(s Pa^b)], exponent, heat [J/kg]
  double threshold_temperature = 0;  // <ThresholdTemp> [K]
  double enthalpy = 0;            // <Enthalpy> [J/kg]
  double burn_coeff = 0;          // <BurnCoeff> [kg/(m^2 s)]
  double ref_pressure = 1;        // <refPressure> [Pa]
  bool crack_model = false;       // <useCrackModel>
  double g_crack = 0, n_crack = 0;  // <Gcrack> [kg], <nCrack>
  double rho0 = 0;                // the MPM reactant's density [kg/m^3] (the 20 % cap)
};

// The branch of a cell: p its equilibration pressure, theta_r the reactant's
// volume fraction, surface_or_cracked the deflagration cell test above.
Ddt0Branch ddt0_branch(const Ddt0Params& prm, double p, double theta_r, bool surface_or_cracked);

// JWL++ in one cell (the DDT1 law with DDT0's F < 0.99 cut-off).
struct Ddt0Detonation {
  double F = 0, delF = 0, mass = 0;
};
Ddt0Detonation ddt0_detonation(const Ddt0Params& prm, double p, double reactant_mass, double product_mass,
                               double cell_volume, double dt);

// The deflagration mass of one cell (before the cap at M_r): T the burning
// temperature (0 if no material is hot enough), area the Simple_Burn area,
// F the product fraction, cracked the crack test, crack_cells the cell's
// size in Cartesian cells for the crack term (a mass per cell per step in
// Uintah): 1, or r_c / dz per radian in axisymmetric MPMICE.
double ddt0_deflagration_mass(const Ddt0Params& prm, double dt, double area, double p, double T, double F,
                              bool cracked, double crack_cells = 1.0);

}  // namespace tephra
