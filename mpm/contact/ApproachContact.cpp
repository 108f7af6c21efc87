// <type>approach</type>: Vaango's ApproachContact. Coulomb friction that acts
// only while the bodies approach, dv_n > 0 (no traction test), at both stages.
#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

void ApproachContact::exchange(ContactStage, ContactNodes& nodes) const {
  exchange_pairs(nodes, materials_, volume_constraint_, mu_,
                 [](const ContactPair& p) { return p.relative().dot(p.n) > 0.0; });
}

}  // namespace tephra
