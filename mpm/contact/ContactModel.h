#pragma once
// MPM contact: corrections of the per-material node velocities so that
// bodies on separate velocity fields interact (Vaango theory manual §1.7).
// The step calls a contact model twice (Alg. 2 steps 4 and 7): on the
// interpolated velocities v_g after P2G and on the integrated velocities v*_g
// after the grid update. A model is called once per stage for all materials
// (virtual dispatch per stage, the node loop inside).
//
// Momentum: every correction is an exchange between two bodies at a node,
// Delta p on one and -Delta p on the other, with ONE normal per node and body
// pair, so sum_alpha m_alpha Delta v_alpha = 0 to round-off. (Vaango's
// friction models compute a normal per material; their corrections are equal
// and opposite only when the normals are.) The specified/rigid model is the
// exception by design: its master body is driven from outside.
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

class DeckNode;

enum class ContactStage { Interpolated, Integrated };

// The node data of all materials that a contact model reads and corrects.
// Index = material index; all arrays have NodeGrid::count() entries.
struct ContactNodes {
  std::vector<const NodeGrid*> grid;         // m_g, V_g, sigma_g, f_int of each material
  std::vector<std::vector<Vec3>*> velocity;  // the corrected field: v_g or v*_g
  // g^alpha = sum_p m_p grad S_gp, the mass gradient (eq. 1.107), pointing out
  // of the body. Filled when the model needs_normals().
  std::vector<std::vector<Vec3>> gradient;
  // x^alpha_g = sum_p m_p x_p S_gp / m_g (Vaango's gPosition), when needs_positions().
  std::vector<std::vector<Vec3>> position;
  // Each material's particles and their stencils of the step (read by
  // friction_LR's logistic-regression separation test).
  std::vector<const Particles*> particles;
  std::vector<const Stencils*> stencils;
  // <do_contact_friction_heating>: when not empty (one array of nodes() per
  // material), the Coulomb models (friction, friction_bard, approach,
  // friction_LR) add the frictional work of each slipping exchange here, in
  // joules, split between the two bodies (mpm/contact/FrictionHeating.h).
  std::vector<std::vector<double>> friction_work;
  // Periodic grids: canonical[g] is the representative of node g's alias set
  // (mpm/PeriodicGrid.h); null otherwise. Read by friction_LR, whose point
  // clouds gather the particles of all aliases.
  const std::vector<std::size_t>* canonical = nullptr;
  // Faces (0 x-, 1 x+, ... 5 z+) that are symmetry planes for material 0
  // (Vaango applies material 0's Symmetric BC to friction_LR's normal).
  std::array<bool, 6> symmetry_face{};
  Vec3 h = Vec3::Ones();  // cell size
  double t = 0.0;         // time at the start of the step
  double dt = 0.0;

  std::size_t materials() const { return grid.size(); }
  std::size_t nodes() const { return grid.empty() ? 0 : grid[0]->count(); }
  double cell_volume() const { return h[0] * h[1] * h[2]; }
};

class ContactModel {
 public:
  virtual ~ContactModel() = default;
  virtual std::string type() const = 0;
  virtual bool needs_normals() const { return false; }
  virtual bool needs_positions() const { return false; }
  virtual bool acts_on(ContactStage) const { return true; }
  // Corrects nodes.velocity in place.
  virtual void exchange(ContactStage stage, ContactNodes& nodes) const = 0;
};

using ContactModelP = std::unique_ptr<ContactModel>;

// Reads one <contact> element for a run with `material_count` MPM materials.
// Returns nullptr for <type>null</type> (no contact pass). DeckError on bad
// values, MissingFeature on valid options that are not implemented.
ContactModelP parse_contact(const DeckNode& contact, int material_count);

// Implemented Vaango contact types (`tephra --list contact`).
std::vector<std::string> contact_types();

}  // namespace tephra
