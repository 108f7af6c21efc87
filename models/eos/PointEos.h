#pragma once
// Adapter from a point model (p and its derivatives at one rho, T) to the
// batched EquationOfState interface: one virtual call per material and
// phase, the point loop inlined inside (DESIGN.md §2.3). Included only by
// the EOS .cpp files.
//
// A point model provides
//   PointThermo point(double rho, double T) const;   p, dp/drho|_T, dp/dT|_rho
//   double density(double p, double T) const;       rho(p, T)
//   double heat_capacity(double rho, double T, double p) const;  c_v with de = c_v dT
// and the adapter derives
//   dp/de|_rho = (dp/dT|_rho) / c_v,
//   c^2        = dp/drho|_e + (p/rho^2) dp/de|_rho          (EquationOfState.h)
//   beta       = (1/v) dv/dT|_p = (dp/dT|_rho) / (rho dp/drho|_T)
// (the last from the cyclic relation dv/dT|_p = -(dp/dT|_v)/(dp/dv|_T) with
// dv = -drho/rho^2). With e = e(T) only, dp/drho|_e = dp/drho|_T.
#include <string>
#include <utility>

#include "models/eos/EquationOfState.h"

namespace tephra {

struct PointThermo {
  double p = 0, dp_drho = 0, dp_dT = 0;
};

template <class Model>
class PointEos final : public EquationOfState {
 public:
  PointEos(std::string type, Model m) : type_(std::move(type)), m_(std::move(m)) {}
  std::string type() const override { return type_; }

  void evaluate(std::span<const double> rho, std::span<const double> T, std::span<EosState> out) const override {
    for (std::size_t i = 0; i < out.size(); ++i) {
      const PointThermo t = m_.point(rho[i], T[i]);
      EosState& s = out[i];
      s.p = t.p;
      s.dp_drho = t.dp_drho;
      s.dp_de = t.dp_dT / m_.heat_capacity(rho[i], T[i], t.p);
      s.c2 = s.dp_drho + s.dp_de * s.p / (rho[i] * rho[i]);
    }
  }
  void density(std::span<const double> p, std::span<const double> T, std::span<double> rho) const override {
    for (std::size_t i = 0; i < rho.size(); ++i) rho[i] = m_.density(p[i], T[i]);
  }
  void thermal_expansivity(std::span<const double> rho, std::span<const double> T,
                           std::span<double> beta) const override {
    for (std::size_t i = 0; i < beta.size(); ++i) {
      const PointThermo t = m_.point(rho[i], T[i]);
      beta[i] = t.dp_dT / (rho[i] * t.dp_drho);
    }
  }
  const Model& model() const { return m_; }

 private:
  std::string type_;
  Model m_;
};

template <class Model>
EquationOfStateP make_point_eos(std::string type, Model m) {
  return std::make_unique<PointEos<Model>>(std::move(type), std::move(m));
}

}  // namespace tephra
