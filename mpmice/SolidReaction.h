#pragma once
// The rate laws of <Model type="SolidReactionModel"> (Uintah's
// Models/SolidReactionModel/: SolidReactionModel.cc and one class per
// sub-model, read for the formulas and parameter names; used by
// mpmice/SolidReactionModel.cpp). In every cell, with F = rho_p/(rho_r + rho_p)
// the product's share of the cell mass (Uintah's comments call it the
// "fraction reactant", the code passes the product fraction):
//   delF = k(T_r) f(F) dt   (0 unless 0 <= F < 1),
//   dm   = min(delF (M_r + M_p), M_r),     heat released <E0> dm,
// T_r the reactant's cell temperature.
//
// Rate constant k(T) [1/s], <RateConstantModel type=...>, R = 8.314462175 J/(mol K):
//   Arrhenius          k = A exp(-Ea/(R T))
//   ModifiedArrhenius  k = A T^b exp(-Ea/(R T))
// Rate model f(F), <RateModel type=...>:
//   AvaramiErofeev      f = a (1 - F) (-ln(1 - F))^b
//   ContractingCylinder f = 2 (1 - F)^(1/2)
//   ContractingSphere   f = 3 (1 - F)^(2/3)
//   Diffusion           dimension 1: f = F/2 (Uintah's formula; the textbook
//                       1-D parabolic law is 1/(2F)); 2: f = 1/(-ln(1 - F));
//                       3 (Jander): f = 3 (1 - F)^(2/3) / (2 (1 - (1 - F)^(1/3)));
//                       4 (Ginstling-Brounshtein): Uintah has no formula
//                       (returns -999): MissingFeature
//   NthOrder            f = (1 - F)^n, n a non-negative integer (Uintah
//                       multiplies n times in a loop)
//   Power               f = a F^b
//   ProutTompkins       f = F^n (1 - q F)^m; <p> (default -log10(1 - q)) is
//                       read and not used by Uintah's formula: read, no effect.
// Where f is infinite (Diffusion 3 at F = 0) delF is infinite and the cap
// dm = M_r burns the cell's reactant in the step, as in Uintah; a negative
// f (Diffusion 2 at F = 0 gives 1/(-0) = -inf) burns nothing.
#include <string>

namespace tephra {

constexpr double kSolidReactionGasConstant = 8.314462175;  // R [J/(mol K)], Uintah's value

struct RateConstantLaw {
  enum class Kind { Arrhenius, ModifiedArrhenius } kind = Kind::Arrhenius;
  double A = 0, Ea = 0, b = 0;  // A [1/s (K^-b)], Ea [J/mol], b (ModifiedArrhenius)
  double k(double T) const;     // [1/s]
};

struct RateModelLaw {
  enum class Kind { AvaramiErofeev, ContractingCylinder, ContractingSphere, Diffusion, NthOrder, Power, ProutTompkins };
  Kind kind = Kind::NthOrder;
  double a = 0, b = 0;  // AvaramiErofeev, Power
  int dimension = 1;    // Diffusion: 1, 2, 3
  int n = 1;            // NthOrder (integer); ProutTompkins uses n_real
  double n_real = 0, q = 0, m = 0;  // ProutTompkins
  double f(double F) const;
};

// The step's fraction change delF = k(T) f(F) dt (0 unless 0 <= F < 1).
double solid_reaction_delF(const RateConstantLaw& k, const RateModelLaw& f, double T, double F, double dt);

}  // namespace tephra
