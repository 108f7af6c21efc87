// <type>nodal_svf</type>: Vaango's NodalSVFContact (Mackenzie et al. 2011,
// "Modeling strategies for multiphase drag interactions using the material
// point method"; facts checked in Vaango's NodalSVFContact.cc). A drag
// between two interpenetrating materials alpha, beta at every node:
//   f_beta = k (v_alpha - v_beta),  f_alpha = -f_beta,
//   k = myu V_cell phi_alpha phi_beta  (<use_svf>true: nodal smoothed volume
//       fractions phi = w V_g / V_cell, w = 8 NC_CCweight, 1 inside and
//       2^(boundary directions) on the grid boundary)
//   k = myu V_cell                     (<use_svf>false: "nodal bang-bang")
//   v_beta += f_beta dt / (w m_beta),  v_alpha += f_alpha dt / (w m_alpha),
// with myu in N s / m^4 (a drag per unit volume and relative velocity).
// Acts at both stages, where both materials have mass (Vaango divides by the
// node mass, which is zero elsewhere). Momentum: m_alpha dv_alpha +
// m_beta dv_beta = (f_alpha + f_beta) dt / w = 0 at every node.
// The update is explicit (Vaango's): stable for
// k dt (1/m_alpha + 1/m_beta) / w < 2 (the relative velocity is multiplied
// by 1 - k dt (1/m_a + 1/m_b)/w per application).
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

void NodalSvfContact::exchange(ContactStage, ContactNodes& nodes) const {
  const int a = alpha_, b = beta_;
  const double v_cell = nodes.cell_volume();
  for (std::size_t g = 0; g < nodes.nodes(); ++g) {
    const double ma = nodes.grid[a]->mass[g], mb = nodes.grid[b]->mass[g];
    if (!(ma > 0.0 && mb > 0.0)) continue;
    const double w = boundary_volume_factor(*nodes.grid[0], g);
    double k = myu_ * v_cell;
    if (use_svf_) k *= (w * nodes.grid[a]->volume[g] / v_cell) * (w * nodes.grid[b]->volume[g] / v_cell);
    Vec3& va = (*nodes.velocity[a])[g];
    Vec3& vb = (*nodes.velocity[b])[g];
    const Vec3 fb = k * (va - vb);  // both from the velocities before the update
    vb += fb * (nodes.dt / (w * mb));
    va -= fb * (nodes.dt / (w * ma));
  }
}

}  // namespace tephra
