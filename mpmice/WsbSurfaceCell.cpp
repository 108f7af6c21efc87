// The WSB burning-surface rule (mpmice/WsbSurfaceCell.h).
#include "mpmice/WsbSurfaceCell.h"

#include <algorithm>

namespace tephra {

WsbSurface wsb_surface_cell(const SolidBurnModel& model, const WsbIgnition& ig, const double wm[8],
                            const BurnCell& cell) {
  WsbSurface s;
  double mx = 1e-100, mn = 1e100;  // Uintah's d_SMALL_NUM bounds
  for (int n = 0; n < 8; ++n) mx = std::max(mx, wm[n]), mn = std::min(mn, wm[n]);
  s.on_surface = mn / mx < 0.7 && cell.particles > 0;
  const IceModelInput& in = *cell.in;
  const std::size_t pi = cell.patch, r = model.reactant(), q = model.product();
  double max_r = -1, max_p = -1;
  for (int k = -1; k <= 1; ++k)
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i) {
        const IntVec3 n = cell.c + IntVec3(i, j, k);
        if (in.mats[r].vol_frac_CC[pi](n) > max_r) {
          max_r = in.mats[r].vol_frac_CC[pi](n);
          s.T0 = in.mats[r].temp_CC[pi](n);
        }
        if (in.mats[q].vol_frac_CC[pi](n) > max_p) {
          max_p = in.mats[q].vol_frac_CC[pi](n);
          s.pressure = in.press_equil_CC[pi](n);
        }
        for (std::size_t m = 0; m < in.mats.size(); ++m) {
          const double T = in.mats[m].temp_CC[pi](n);
          if (T > ig.ignition_temp) s.hot_neighbour = true;
          if (s.on_surface && !s.ignited && model.particles_in(pi, n) <= ig.boundary_particles &&
              in.mats[m].vol_frac_CC[pi](n) > 0.2 && T > ig.ignition_temp)
            s.ignited = true;
        }
      }
  return s;
}

double wsb_burnable_mass(const BurnCell& cell) {
  constexpr double kMinCellDensity = 1e-12;  // [kg/m^3]
  return std::max(0.0, cell.solid_mass - cell.volume * kMinCellDensity);
}

}  // namespace tephra
