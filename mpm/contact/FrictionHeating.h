#pragma once
// <MPM><do_contact_friction_heating>true: the frictional work of the
// Coulomb contact models becomes heat in the particles of the two bodies
// (Vaango: FrictionContact/ApproachContact compute the work per material and
// node, SerialMPM's particle update adds frictionTempRate * d_addFrictionWork
// to the temperature rate; here from the exchange actually applied,
// CoulombExchange.h friction_work).
//
// Per material alpha, node g: W_g [J] summed over the contact stages of the
// step (interpolated and integrated; not the re-contact of the MUSL velocity,
// which moves no particle). Its temperature rate W_g / (c_v m_g dt) goes to
// the particles with the stencil weights:
//   T_p += sum_g S_gp W_g / (c_v m_g),
// so that sum_p m_p c_v Delta T_p = sum_g W_g (sum_p m_p S_gp = m_g): the
// thermal energy gained equals the frictional work to round-off.
#include <vector>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// T_p += sum_g S_gp work_g / (c_v m_g) over the nodes with m_g > 0.
void friction_heat_to_particles(const Stencils& s, const NodeGrid& g, const std::vector<double>& work,
                                double specific_heat, Particles& p);

}  // namespace tephra
