#pragma once
// Vaango's "visco_trans_iso_hyper" (VT ch. 2 list; Vaango class
// ViscoTransIsoHyper): the transversely isotropic hyperelastic solid of
// "trans_iso_hyper" (TransIsoHyper.h, VT eqs. 4.13-4.19) with up to six
// viscoelastic Prony terms (<y1..y6> [-], <t1..t6> [s]) acting on the
// deviatoric (matrix + fibre) stress, the quasi-linear viscoelastic form of
// Puso & Weiss (J. Biomech. Eng. 120 (1998) 62) with the integration of
// Simo (CMAME 60 (1987) 153), eqs. (3.11)-(3.14) there:
//
//   S_e    = J F^{-1} dev(sigma_e) F^{-T}      elastic deviatoric stress, pulled back (PK2 frame)
//   H_i(t) = int_0^t exp(-(t - s)/t_i) dS_e/ds ds                (hereditary integral of term i)
//   sigma  = sigma_e + (1/J) F (sum_i y_i H_i) F^T
//
// so the relaxation function of the deviatoric stress is G(t) = 1 + sum_i y_i exp(-t/t_i):
// long-term response = the elastic law, instantaneous = (1 + sum y_i) times its deviator.
// Step update (Simo 1987, the midpoint rule for the increment, second order in dt):
//   H_i^{n+1} = exp(-dt/t_i) H_i^n + exp(-dt/(2 t_i)) (S_e^{n+1} - S_e^n)
// Exact relaxation at constant S_e: H_i^{n+1} = exp(-dt/t_i) H_i^n.
// Term i is active when y_i != 0; it needs t_i > 0 (DeckError otherwise).
// History: "SeDev" (S_e of the last step, 9) and "Hvisco<i>" (9 each, active terms).
// The frame: Vaango's internal frame for the history (Cauchy vs PK2) was not
// checked; the PK2 frame above is objective (a rigid rotation of a held state
// rotates sigma and leaves H_i unchanged).
// Limitations: energy_density reports the elastic W(F) only; the viscous
// dissipation is not computed (plastic_work = 0); the fibre/matrix failure
// options are MissingFeature as in trans_iso_hyper.
#include <vector>

#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/TransIsoHyper.h"

namespace tephra {

struct PronyTerm {
  double y = 0.0;    // <y_i> weight relative to the elastic deviator [-]
  double tau = 0.0;  // <t_i> relaxation time [s] (> 0)
};

class ViscoTransIsoHyper final : public ConstitutiveModel {
 public:
  ViscoTransIsoHyper(const TransIsoHyperParams& p, std::vector<PronyTerm> terms)
      : p_(p), terms_(std::move(terms)) {}
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "visco_trans_iso_hyper"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return p_.kappa; }
  // The instantaneous shear modulus (1 + sum y_i) G.
  double shear_modulus() const override;

 private:
  TransIsoHyperParams p_;
  std::vector<PronyTerm> terms_;  // active terms only
};

}  // namespace tephra
