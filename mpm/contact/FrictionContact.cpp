// <type>friction</type>: Vaango's FrictionContact (Coulomb friction,
// Bardenhagen et al. 2001). Acts at both stages on a pair that approaches,
// dv_n > 0, and is not in tension, T_n <= 0: VT eq. 1.112 ("approaching and
// t.n < 0"), with the stress-free pair of first touch (T_n = 0) included.
// Vaango and Uintah act when "in compression OR stress free and
// approaching": a pair in compression that separates is pulled back
// together, a tensile normal impulse, and its Coulomb tangential impulse
// mu |dv_n| still brakes the slip, so friction exceeds mu times the net
// normal force (a block sliding under gravity: 2.9 % above mu g, Tephra's
// session 18, docs/mpm-contact.md). Tephra keeps the normal impulse
// compressive, as Coulomb's law needs.
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

void FrictionContact::exchange(ContactStage, ContactNodes& nodes) const {
  exchange_pairs(nodes, materials_, volume_constraint_, mu_, [](const ContactPair& p) {
    const double dvn = p.relative().dot(p.n);
    return dvn > 0.0 && p.traction <= 0.0;  // approach and no tension (VT eq. 1.112)
  });
}

}  // namespace tephra
