#pragma once
// update() of an elastic model whose state is a function of F_{n+1} alone
// (hyperelastic: comp_neo_hook, cnh_mms, comp_mooney_rivlin, trans_iso_hyper):
// point(F, rho0) -> SolidPointResult for every point, no dissipation and no
// internal heating. A point with J <= 0 or a non-finite stress, wave speed or
// energy is inadmissible (for_each_point returns the lowest such index).
#include <cmath>

#include "models/solid/ConstitutiveModel.h"
#include "models/solid/PointLoop.h"

namespace tephra {

template <class PointFunction>
long update_elastic_points(const SolidUpdateInput& in, const SolidUpdateOutput& out, PointFunction&& point) {
  return for_each_point(in.F_new.size(), [&](std::size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const SolidPointResult r = point(in.F_new[i], in.density0);
    if (!r.stress.allFinite() || !std::isfinite(r.wave_speed) || !std::isfinite(r.energy_density)) return false;
    out.stress[i] = r.stress;
    out.wave_speed[i] = r.wave_speed;
    out.energy_density[i] = r.energy_density;
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return true;
  });
}

}  // namespace tephra
