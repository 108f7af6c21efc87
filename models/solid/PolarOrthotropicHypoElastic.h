#pragma once
// Vaango's "polar_orthotropic_hypoelastic" (VT ch. 2 list item 12; Vaango class
// PolarOrthotropicHypoElastic): linear orthotropic hypoelasticity in the
// cylindrical frame (e_r, e_theta, e_z) of an axis through <symmetry_axis_bottom>
// and <symmetry_axis_top>, with the Green-Naghdi rate (unrotated frame, as
// hypo_elastic, HypoElastic.h):
//
//   tau_{n+1} = tau_n + Q^T [ C : (Q de Q^T) ] Q,  Q = rows (e_r, e_theta, e_z)
//
// C = S^{-1}, the compliance S in Voigt order (r, theta, z, theta-z, z-r, r-theta)
// with engineering shear strains:
//   S = [ 1/E_r         -nu_tr/E_t   -nu_zr/E_z   0       0       0      ]
//       [ -nu_tr/E_t    1/E_t        -nu_zt/E_z   0       0       0      ]
//       [ -nu_zr/E_z    -nu_zt/E_z   1/E_z        0       0       0      ]
//       [ 0 ...                                   1/G_tz  0       0      ]
//       [ 0 ...                                           1/G_zr  0      ]
//       [ 0 ...                                                   1/G_rt ]
// i.e. eps_r = sigma_r/E_r - nu_tr sigma_t/E_t - nu_zr sigma_z/E_z (and cyclic),
// gamma_ij = sigma_ij / G_ij. The frame is MATERIAL: it is fixed at
// initialization from the particle's initial position x_p (the point context,
// SolidUpdateInput::position) and kept as history "RCoord", "ThetaCoord", "ZCoord"
// (Vaango's labels): r = distance to the axis, theta measured about e_z from the
// in-plane projection of the global e_1 (e_2 when the axis is along e_1), z along
// the axis from the bottom point. Vaango computes theta with acos (so in [0, pi]:
// points with negative sine get the mirrored frame); Tephra uses the signed angle.
// Wave speed sqrt(max(C_rr, C_tt, C_zz)/rho) (Vaango). Stored energy: the
// complementary energy J sigma_loc : S : sigma_loc / 2. Heating 0; no MPMICE hooks.
// Moduli for time-step estimates: bulk 1/(sum of S_ij, i,j < 3), shear max G.
#include <Eigen/Core>

#include "models/solid/ConstitutiveModel.h"

namespace tephra {

struct PolarOrthotropicParams {
  Eigen::Vector3d top, bottom;
  double Er = 0, Et = 0, Ez = 0, nu_tr = 0, nu_zr = 0, nu_zt = 0, G_tz = 0, G_zr = 0, G_rt = 0;
  Eigen::Matrix<double, 6, 6> compliance() const;
};

// The cylindrical coordinates (r, theta, z) of x, and the local frame rows Q(theta).
Eigen::Vector3d polar_coordinates(const Eigen::Vector3d& x, const PolarOrthotropicParams& p);
Eigen::Matrix3d polar_frame(double theta, const PolarOrthotropicParams& p);

class PolarOrthotropicHypoElastic final : public ConstitutiveModel {
 public:
  explicit PolarOrthotropicHypoElastic(const PolarOrthotropicParams& p);
  static ConstitutiveModelP create(const ModelParameters& params);
  std::string type() const override { return "polar_orthotropic_hypoelastic"; }
  long update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const override;
  std::vector<HistoryVariable> history() const override;
  double bulk_modulus() const override { return bulk_; }
  double shear_modulus() const override { return shear_; }
  bool needs_position() const override { return true; }
  const Eigen::Matrix<double, 6, 6>& stiffness() const { return C_; }

 private:
  PolarOrthotropicParams p_;
  Eigen::Matrix<double, 6, 6> C_, S_;
  double bulk_ = 0, shear_ = 0, longitudinal_ = 0;
};

}  // namespace tephra
