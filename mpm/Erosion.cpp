#include "mpm/Erosion.h"

#include <algorithm>

namespace tephra {

bool erosion_algorithm_from_name(const std::string& name, ErosionAlgorithm& out) {
  if (name == "none") out = ErosionAlgorithm::None;
  else if (name == "ZeroStress") out = ErosionAlgorithm::ZeroStress;
  else if (name == "AllowNoTension") out = ErosionAlgorithm::AllowNoTension;
  else if (name == "AllowNoShear") out = ErosionAlgorithm::AllowNoShear;
  else if (name == "KeepStress") out = ErosionAlgorithm::KeepStress;
  else return false;
  return true;
}

void erode_failed_particles(ErosionAlgorithm a, std::span<const double> localized, std::vector<Mat3>& stress,
                            std::vector<double>& wave_speed, double reference_wave_speed) {
  if (a == ErosionAlgorithm::None || a == ErosionAlgorithm::KeepStress) return;
  for (std::size_t i = 0; i < localized.size(); ++i) {
    if (localized[i] == 0.0) continue;
    const double p = stress[i].trace() / 3.0;  // mean stress, tension positive
    switch (a) {
      case ErosionAlgorithm::ZeroStress:
        stress[i].setZero();
        wave_speed[i] = std::min(wave_speed[i], reference_wave_speed);
        break;
      case ErosionAlgorithm::AllowNoTension:
        stress[i] = p > 0.0 ? Mat3::Zero() : Mat3(p * Mat3::Identity());
        break;
      case ErosionAlgorithm::AllowNoShear: stress[i] = p * Mat3::Identity(); break;
      default: break;
    }
  }
}

}  // namespace tephra
