// DDT0 point functions (mpmice/Ddt0.h).
#include "mpmice/Ddt0.h"

#include <cmath>

#include "mpmice/Ddt1.h"

namespace tephra {

Ddt0Branch ddt0_branch(const Ddt0Params& prm, double p, double theta_r, bool surface_or_cracked) {
  if (p > prm.jwl_pressure && theta_r > prm.volume_fraction) return Ddt0Branch::Detonating;
  if (p < prm.jwl_pressure && p > prm.sb_pressure && surface_or_cracked) return Ddt0Branch::Deflagrating;
  return Ddt0Branch::None;
}

Ddt0Detonation ddt0_detonation(const Ddt0Params& prm, double p, double reactant_mass, double product_mass,
                               double cell_volume, double dt) {
  const Ddt1Detonation d1 = ddt1_detonation(prm.G, prm.b, p, reactant_mass, product_mass, prm.rho0, cell_volume, dt);
  Ddt0Detonation d{d1.F, d1.delF, d1.mass};
  if (!(d.F < 0.99)) d.delF = d.mass = 0;  // DDT0's cut-off
  return d;
}

double ddt0_deflagration_mass(const Ddt0Params& prm, double dt, double area, double p, double T, double F,
                              bool cracked, double crack_cells) {
  const bool hot = T > prm.threshold_temperature;
  double dm = hot ? dt * area * prm.burn_coeff * std::pow(p / prm.ref_pressure, 0.778) : 0.0;
  // Uintah adds the crack term in the hot branch and again in the cracked-but-cold
  // one; without <useCrackModel> Gcrack is 0 here.
  if (prm.crack_model && (hot || cracked))
    dm += crack_cells * (prm.g_crack * (1 - F) * std::pow(p / prm.ref_pressure, prm.n_crack));
  return dm;
}

}  // namespace tephra
