#pragma once
// The kinetic-energy ledger of the explicit step (Tephra labels; Vaango has no
// such reductions), for the energy budget of impact problems
// (docs/models/taylor-impact.md). Per node g and component d of each material, the
// step's node velocities are
//   v_g   (P2G, after the grid BCs on v_g),  v^c_g (after the interpolated contact),
//   v*_g  (v^c_g + dt a_force, before the integrated contact),
//   v^f_g (after the integrated contact and the grid BCs: the velocity the particles move with),
// and Delta_g = a_g dt = v^f_g - v_g (the FLIP increment). A component is constrained
// in the step when a correction changed it after the force was applied (v^f != v*):
// the wall's normal velocity under rigid contact, a symmetry plane's normal velocity,
// a Dirichlet velocity. Summed over the steps and all materials:
//
//   ContactKineticEnergyRemoved   over the components last set by the contact:
//                                 1/2 m_g (v_g,d^2 - v^f_g,d^2) (the rigid wall's capture of
//                                 the node layer it touches: the normal velocity P2G gave it);
//                                 plus, over the free components, the interpolated
//                                 contact's 1/2 m_g (v_g,d^2 - v^c_g,d^2);
//   BoundaryKineticEnergyRemoved  the same over the components last set by the grid BCs;
//   GridForceWork                 over the free components, 1/2 m_g (v*_g,d^2 - v^c_g,d^2): the
//                                 kinetic energy the node forces (f_int + f_ext, damping)
//                                 give the motion (minus the stress work). The force on a
//                                 constrained component never reaches the particles and is
//                                 counted nowhere;
//   TransferKineticEnergyLoss     1/2 sum_g m_g |Delta_g|^2 - 1/2 sum_p m_p |Delta v_p|^2 with
//                                 Delta v_p = sum_g S_gp Delta_g (the FLIP update); >= 0 by
//                                 Jensen's inequality (S_gp >= 0, sum_g S_gp = 1).
//
// Identity of the step (FLIP, v_p += sum_g S_gp Delta_g, m_g v_g = sum_p m_p S_gp v_p):
//   sum_p 1/2 m_p |v_p^{n+1}|^2 - sum_p 1/2 m_p |v_p^n|^2
//     = sum_g m_g v_g . Delta_g + 1/2 sum_p m_p |Delta v_p|^2
//     = sum_g 1/2 m_g (|v^f_g|^2 - |v_g|^2) - 1/2 sum_g m_g |Delta_g|^2 + 1/2 sum_p m_p |Delta v_p|^2
//     = GridForceWork - ContactKineticEnergyRemoved - BoundaryKineticEnergyRemoved
//       - TransferKineticEnergyLoss                                   (per step),
// exact to round-off when nothing else changes the particle velocities
// (no velocity clamp, deletion, velocity surfaces, MMS restarts, MPMICE).
// The grid BCs applied to v_g after P2G are not counted: a_g is taken against
// the corrected v_g, and the components they correct are set again on v*_g, so
// Delta_g is zero in them and the particles never see that change.
// Computed only when the deck saves one of the labels. On MPI ranks every
// node is counted by one rank (the lowest whose node box holds it: after the
// node combines it holds the global m_g and velocities there), every particle
// by its own, and the step's four terms are added over the ranks in rank
// order: the 1-rank totals to round-off.
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"

namespace tephra {

struct EnergyLedger {
  double contact_removed = 0.0;    // ContactKineticEnergyRemoved
  double boundary_removed = 0.0;   // BoundaryKineticEnergyRemoved
  double grid_force_work = 0.0;    // GridForceWork
  double transfer_loss = 0.0;      // TransferKineticEnergyLoss
};

// The ledger's reduction labels.
const std::vector<const char*>& energy_ledger_labels();

// Adds one material's node terms of the step to the ledger (the definitions above):
// v_p2g = v_g, v_c = v^c_g, v_star = v*_g, v_contact = v*_g after the integrated contact,
// v_final = v^f_g, and 1/2 sum_g m_g |a_g dt|^2 to transfer_loss. `counted`
// (MPI ranks): only the nodes with counted[g] != 0 (each node on one rank).
void add_node_terms(const NodeGrid& g, const std::vector<Vec3>& v_p2g, const std::vector<Vec3>& v_c,
                    const std::vector<Vec3>& v_star, const std::vector<Vec3>& v_contact,
                    const std::vector<Vec3>& v_final, double dt, EnergyLedger& ledger,
                    const std::vector<char>* counted = nullptr);

// 1/2 sum_p m_p |v_p - v_old_p|^2 (the particle part of TransferKineticEnergyLoss).
double particle_increment_energy(const Particles& p, const std::vector<Vec3>& v_old);

}  // namespace tephra
