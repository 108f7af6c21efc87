#pragma once
// The deformation-gradient update of the explicit step (Vaango's
// DeformationGradientComputer, <MPM><deformation_gradient algorithm=...>).
// With l constant over the step the exact update is F_{n+1} = exp(dt l) F_n.
// The algorithms are polynomial approximations of exp(A), A = dt l:
//   first_order      F_{n+1} = (I + A) F_n                       (eq. 1.75)
//   subcycling       (I + A/s)^s F_n, s = min(max(1, 2 floor(|A|)), 1000)
//                    (|A| the Frobenius norm; s = 1 unless |A| >= 1)
//   taylor_series    sum_{k=0}^{N} A^k / k!  F_n, N = <num_terms>
//   cayley_hamilton  the same truncated series, evaluated as a0 I + a1 A + a2 A^2
//                    with the Cayley-Hamilton recursion (A^3 = I1 A^2 - I2 A + I3 I).
// Why it matters: for a rigid rotation l = W (skew), I + dt W is not a
// rotation: (I + dt W)^T (I + dt W) = I - dt^2 W^2, a stretch of
// 1 + (omega dt)^2 / 2 per step, which accumulates to a spurious strain
// ~ omega^2 dt t / 2 (first order in dt). The N-term series leaves an error
// O((omega dt)^{N+1}) per step.
#include <string>
#include <vector>

#include "core/base/Types.h"

namespace tephra {

enum class DeformationGradientAlgorithm { FirstOrder, Subcycling, TaylorSeries, CayleyHamilton };

// Maps Vaango's name; throws std::invalid_argument for anything else.
DeformationGradientAlgorithm deformation_gradient_algorithm(const std::string& name);

// The increment F_{n+1} F_n^{-1} for A = dt l with `terms` series terms (unused by
// first_order and subcycling).
Mat3 deformation_gradient_increment(DeformationGradientAlgorithm alg, const Mat3& A, int terms);

// F_p <- increment(dt L_p) F_p for every particle.
void update_deformation_gradients(DeformationGradientAlgorithm alg, int terms, double dt,
                                  const std::vector<Mat3>& L, std::vector<Mat3>& F);

// F_p = increment(dt L_p) F_old_p (the same bits as the in-place form), F sized
// to F_old: one pass that keeps F_n for the model without copying it.
void update_deformation_gradients(DeformationGradientAlgorithm alg, int terms, double dt,
                                  const std::vector<Mat3>& L, const std::vector<Mat3>& F_old,
                                  std::vector<Mat3>& F);

}  // namespace tephra
