// <type>friction_bard</type>: Vaango's FrictionContactBard. Contact when the
// pair approaches (dv_n > 0) and is not in tension (T_n <= 0), VT eq. 1.112
// as friction (FrictionContact.cpp; Vaango: "T_n < -1e-12 or approaching",
// which lets a compressed, separating pair take a tensile normal impulse
// and its friction), and, with <separation_factor> f, only when the
// mass centres of the two bodies at the node are closer than f V_cell^(1/3):
//   |x_b - x_a| < f h   (Vaango: (M/(M - m_a)) |x_cm - x_a|, the same thing).
// <one_or_two_step> 1 skips the interpolated stage.
#include <cmath>

#include "mpm/contact/ContactTypes.h"
#include "mpm/contact/CoulombExchange.h"

namespace tephra {

void FrictionBardContact::exchange(ContactStage, ContactNodes& nodes) const {
  const double separation = separation_factor_ * std::cbrt(nodes.cell_volume());
  exchange_pairs(nodes, materials_, volume_constraint_, mu_, [&](const ContactPair& p) {
    if (!((p.xb - p.xa).norm() < separation)) return false;
    return p.relative().dot(p.n) > 0.0 && p.traction <= 0.0;
  });
}

}  // namespace tephra
