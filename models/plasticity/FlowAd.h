#pragma once
// Evaluates a flow law written once over a scalar type with exact derivatives:
// slots (0, 1, 2) = (ε_p, ε̇_p, T). Included by flow-model sources only.
#include "models/plasticity/Dual.h"
#include "models/plasticity/FlowStressModel.h"

namespace tephra {

template <class Law>
FlowStress evaluate_flow_law(const Law& law, const PlasticState& s, double d_eps_p_extra = 0.0) {
  const ad::Dual ep(s.eps_p, 0), rate(s.eps_p_rate, 1), T(s.temperature, 2);
  const ad::Dual y = law(ep, rate, T);
  return {y.v, y.d[0] + d_eps_p_extra, y.d[1], y.d[2]};
}

// Rate floor for laws with ln ε̇ (ZA, MTS, PTW): a point at rest would make
// ln ε̇ = -inf. Below this rate the law is evaluated at the floor and its
// rate derivative is zero (a documented choice; Vaango floors similarly).
inline constexpr double kMinPlasticRate = 1.0e-8;  // [1/s]

inline ad::Dual floor_rate(const ad::Dual& rate) {
  return rate.v < kMinPlasticRate ? ad::Dual(kMinPlasticRate) : rate;
}

}  // namespace tephra
