#pragma once
// The rotation of the last polar decomposition of a point, kept as model
// history so that the next step does not decompose the same F again.
//
// A Green-Naghdi (hypoelastic) update decomposes F_n = R_n U_n and
// F_{n+1} = R_{n+1} U_{n+1} every step (HypoElastic.h). The MPM driver's F_n
// of a step is the F_{n+1} of the previous step (the same bits: step 9 of
// advance() swaps the columns), so the previous step's R_{n+1} is this step's
// R_n. Two history columns per point hold it:
//   polarFT  the F that was decomposed (9 values),
//   polarRT  its Newton rotation R (9 values).
// The cached R is used only when polarFT holds exactly the bits of the F_n
// asked for (+0 and -0 differ); U_n = sym(R_n^T F_n) is then formed as
// polar_decomposition_newton forms it. So the result is the bits of
// polar_decomposition_newton(F_n) whatever happened to the point in between
// (reordered, migrated, restarted, F reset by the driver, the update run
// twice): a stale or missing entry only costs the decomposition. A point
// whose iteration fell back to the eigen-solve (polar_rotation_newton
// false) stores a NaN key, which no F_n matches (an F_n with a NaN has no
// finite det and is rejected before).
// Cost: 144 B per point (and in checkpoints) for ~one Newton polar
// decomposition per point-step (docs/performance.md, Session 24).
#include <cstdint>
#include <cstring>
#include <limits>
#include <span>
#include <vector>

#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/PolarNewton.h"

namespace tephra {

// The two history declarations, to append to a model's history(). The
// columns hold Eigen's column-major storage of F and R, which read as the
// row-major tensors of the history convention are F^T and R^T: hence the
// names (a plain copy of the 72 bytes per matrix).
inline std::vector<HistoryVariable> polar_cache_history() {
  const std::vector<double> I{1, 0, 0, 0, 1, 0, 0, 0, 1};  // F = I: R = I, the reference state
  return {{"polarFT", 9, I, "transpose of the deformation gradient F of the cached polar decomposition (PolarCache.h)"},
          {"polarRT", 9, I, "transpose of the rotation R of F = R U, Newton iteration (PolarCache.h)"}};
}

// The cache columns of a span of n points; off (every call decomposes) when
// the driver did not supply them at the expected width.
class PolarCache {
 public:
  PolarCache(HistoryColumns history, std::size_t first_column, std::size_t n) {
    if (history.size() >= first_column + 2 && history[first_column].size() == 9 * n &&
        history[first_column + 1].size() == 9 * n) {
      F_ = history[first_column].data();
      R_ = history[first_column + 1].data();
    }
  }
  bool on() const { return F_ != nullptr; }

  // polar_decomposition_newton(F) of point i, from the cache when it holds F.
  PolarDecomposition decompose_old(std::size_t i, const Eigen::Matrix3d& F) const {
    if (F_ && same_bits(F_ + 9 * i, F.data())) return polar_with_rotation(Eigen::Map<const Eigen::Matrix3d>(R_ + 9 * i), F);
    return polar_decomposition_newton(F);
  }

  // polar_decomposition_newton(F) of point i, stored for the next step.
  PolarDecomposition decompose_new(std::size_t i, const Eigen::Matrix3d& F) const {
    Eigen::Matrix3d R;
    if (polar_rotation_newton(F, R)) {
      if (F_) {
        std::memcpy(F_ + 9 * i, F.data(), sizeof(double) * 9);
        std::memcpy(R_ + 9 * i, R.data(), sizeof(double) * 9);
      }
      return polar_with_rotation(R, F);
    }
    if (F_)
      for (int k = 0; k < 9; ++k) F_[9 * i + k] = std::numeric_limits<double>::quiet_NaN();
    return polar_decomposition(F);
  }

  // Bit-for-bit equality of 9 doubles (+0 and -0 differ, as they may in a result).
  static bool same_bits(const double* a, const double* b) {
    std::uint64_t diff = 0;
    for (int k = 0; k < 9; ++k) {
      std::uint64_t x, y;
      std::memcpy(&x, a + k, 8);
      std::memcpy(&y, b + k, 8);
      diff |= x ^ y;
    }
    return diff == 0;
  }

 private:
  double* F_ = nullptr;
  double* R_ = nullptr;
};

}  // namespace tephra
