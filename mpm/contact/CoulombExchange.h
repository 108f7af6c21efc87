#pragma once
// The two-body Coulomb exchange shared by the friction, friction_bard and
// approach contact models (Bardenhagen et al. 2001; VT eqs. 1.111-1.115), and
// the node loop that applies it with one normal per body pair. Internal to
// mpm/contact.
#include <vector>

#include "core/base/Types.h"
#include "mpm/contact/ContactModel.h"

namespace tephra {

// One body pair at one node: body a (one material) against body b (the lump
// of the other contacting materials at the node).
struct ContactPair {
  double ma = 0.0, mb = 0.0;
  Vec3 va = Vec3::Zero(), vb = Vec3::Zero();
  Vec3 n = Vec3::UnitZ();    // unit normal, out of a towards b
  double traction = 0.0;     // T_n = n . sigma . n of the pair (negative: compression)
  Vec3 xa = Vec3::Zero(), xb = Vec3::Zero();  // mass-weighted particle positions (when computed)

  // Delta v_a = v_a - v_cm (eq. 1.114); its normal part dv_n > 0 means approach (1.112).
  Vec3 relative() const { return mb / (ma + mb) * (va - vb); }
};

// Momentum Delta p given to body a (b receives -Delta p), eqs. 1.113-1.115:
//   dv = v_a - v_cm, dv_n = dv.n, dv_t = |dv - dv_n n|, t = (dv - dv_n n)/dv_t,
//   stick  (dv_t <= mu |dv_n|):  Delta p = -m_a dv           (v_a -> v_cm)
//   slip   (dv_t >  mu |dv_n|):  Delta p = -m_a (dv_n n + mu |dv_n| t)
// i.e. the tangential impulse is at most mu times the normal one (Coulomb).
// Vaango's limiter then scales the change so that the imposed strain
// |Delta v_i| dt / h_i (times max(1, m_a/m_b)) stays <= 0.5; the factor is the
// same seen from a or from b, so the exchange stays equal and opposite.
Vec3 coulomb_exchange(const ContactPair& p, double mu, const Vec3& h, double dt);

// Frictional work [J] of one exchange (<do_contact_friction_heating>). With
// Delta p given to a and -Delta p to b, J_t = Delta p - (Delta p . n) n the
// tangential impulse on a and w_t the tangential part of the slip velocity
// after the exchange, v'_a - v'_b,
//   Q = -J_t . w_t >= 0,
// the friction force J_t/dt times the slip distance |w_t| dt of the step
// (the particles move with the corrected node velocities). Zero when the
// pair sticks (w_t = 0) or mu = 0 (J_t = 0). For a slipping pair without the
// strain limiter this is Vaango's rule (FrictionContact, ApproachContact):
// each body gets m mu |dv_n| (|dv_t| - mu |dv_n|), dv its velocity relative
// to v_cm; the two add up to Q, a's share m_b/(m_a + m_b), b's m_a/(m_a + m_b).
// The relative kinetic energy the tangential impulse removes is
// Q + |J_t|^2 / (2 m_eff), m_eff = m_a m_b/(m_a + m_b): the heat misses the
// last term, which is O(dt^2) per step for a force-driven slip (O(dt) in all).
double friction_work(const ContactPair& p, const Vec3& dp);

// Adds Q of the exchange at `node` to nodes.friction_work: m_b/(m_a + m_b) of
// it to material a, the rest to the materials of the lump in proportion to
// their node mass (they take the same velocity change). Nothing when the
// friction work is not recorded.
void record_friction_work(ContactNodes& nodes, std::size_t node, int a, const std::vector<int>& lump,
                          const ContactPair& p, const Vec3& dp);

// The node loop of the pairwise models. At each node where at least two of
// `materials` have mass and sum V_g (scaled for boundary nodes as Vaango's
// NC_CCweight does) / V_cell > volume_constraint, each contacting material
// but the last is exchanged in turn against the lump of the others:
//   pair normal: Vaango's rule, the mass gradient of larger magnitude wins,
//     n = g_a/|g_a| or -g_b/|g_b|, so a and b see the same plane;
//   pair traction: T_n = n . sigma . n with sigma the mass-weighted stress
//     of the pair (symmetric in a and b);
//   decide(pair) says whether to apply coulomb_exchange with mu (every
//     Coulomb model asks for approach, dv_n > 0, so the normal impulse is
//     compressive and the friction at most mu times it).
// Every exchange adds Delta p to a and -Delta p to the lump (a uniform
// velocity change of the lump), so momentum is conserved to round-off.
template <class Decide>
void exchange_pairs(ContactNodes& nodes, const std::vector<int>& materials, double volume_constraint,
                    double mu, Decide&& decide);

}  // namespace tephra

#include "mpm/contact/CoulombExchangeLoop.h"
