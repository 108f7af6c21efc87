// <type>single_velocity</type>: Vaango's SingleVelContact. At every node where
// two or more of the contacting materials have mass, each of them takes the
// centre-of-mass velocity v_cm = sum m_a v_a / sum m_a (eqs. 1.105, 1.109):
// sum m_a v_a is unchanged, so momentum is conserved to round-off.
#include "mpm/contact/ContactTypes.h"

namespace tephra {

void SingleVelocityContact::exchange(ContactStage, ContactNodes& nodes) const {
  const std::size_t count = nodes.nodes();
  for (std::size_t g = 0; g < count; ++g) {
    double mass = 0.0;
    int with_mass = 0;
    Vec3 momentum = Vec3::Zero();
    for (int m : materials_) {
      const double mg = nodes.grid[m]->mass[g];
      if (mg > 0.0) {
        ++with_mass;
        mass += mg;
        momentum += mg * (*nodes.velocity[m])[g];
      }
    }
    if (with_mass < 2) continue;
    const Vec3 vcm = momentum / mass;
    for (int m : materials_)
      if (nodes.grid[m]->mass[g] > 0.0) (*nodes.velocity[m])[g] = vcm;
  }
}

}  // namespace tephra
