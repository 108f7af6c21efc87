// SolidReactionModel rate laws (mpmice/SolidReaction.h).
#include "mpmice/SolidReaction.h"

#include <cmath>

namespace tephra {

double RateConstantLaw::k(double T) const {
  const double arrhenius = A * std::exp(-Ea / (kSolidReactionGasConstant * T));
  return kind == Kind::ModifiedArrhenius ? std::pow(T, b) * arrhenius : arrhenius;
}

double RateModelLaw::f(double F) const {
  const double r = 1.0 - F;  // the reactant's share
  switch (kind) {
    case Kind::AvaramiErofeev: return a * r * std::pow(-std::log(r), b);
    case Kind::ContractingCylinder: return 2.0 * std::sqrt(r);
    case Kind::ContractingSphere: return 3.0 * std::pow(r, 2.0 / 3.0);
    case Kind::Diffusion:
      if (dimension == 1) return 0.5 * F;
      if (dimension == 2) return 1.0 / (-std::log(r));
      return 3.0 * std::pow(r, 2.0 / 3.0) / (2.0 * (1.0 - std::cbrt(r)));
    case Kind::NthOrder: {
      double v = 1.0;
      for (int i = 0; i < n; ++i) v *= r;
      return v;
    }
    case Kind::Power: return a * std::pow(F, b);
    case Kind::ProutTompkins: return std::pow(F, n_real) * std::pow(1.0 - q * F, m);
  }
  return 0.0;
}

double solid_reaction_delF(const RateConstantLaw& k, const RateModelLaw& f, double T, double F, double dt) {
  if (!(F >= 0.0 && F < 1.0)) return 0.0;
  return k.k(T) * f.f(F) * dt;
}

}  // namespace tephra
