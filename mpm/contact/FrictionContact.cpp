// <type>friction</type>: Vaango's FrictionContact (Coulomb friction,
// Bardenhagen et al. 2001). Acts at both stages on a pair that is in
// compression, T_n < 0, or stress free and approaching, dv_n > 0.
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

void FrictionContact::exchange(ContactStage, ContactNodes& nodes) const {
  exchange_pairs(nodes, materials_, volume_constraint_, mu_, [](const ContactPair& p) {
    const double dvn = p.relative().dot(p.n);
    return p.traction < 0.0 || (p.traction == 0.0 && dvn > 0.0);
  });
}

}  // namespace tephra
