#pragma once
// The implemented contact models (one .cpp each; parsed in ContactRegistry.cpp).
// `materials` are the material indices that take part (<materials>, default all).
#include <limits>
#include <utility>
#include <vector>

#include "mpm/contact/ContactModel.h"

namespace tephra {

class SingleVelocityContact final : public ContactModel {
 public:
  explicit SingleVelocityContact(std::vector<int> materials) : materials_(std::move(materials)) {}
  std::string type() const override { return "single_velocity"; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  std::vector<int> materials_;
};

// Common parameters of the Coulomb-friction family.
struct FrictionParameters {
  std::vector<int> materials;
  double mu = 0.0;                 // <mu>, Coulomb friction coefficient
  double volume_constraint = 0.0;  // <volume_constraint>: act only where sum V_g / V_cell exceeds it
};

class FrictionContact final : public ContactModel {
 public:
  explicit FrictionContact(const FrictionParameters& p)
      : materials_(p.materials), mu_(p.mu), volume_constraint_(p.volume_constraint) {}
  std::string type() const override { return "friction"; }
  bool needs_normals() const override { return true; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  std::vector<int> materials_;
  double mu_, volume_constraint_;
};

class FrictionBardContact final : public ContactModel {
 public:
  FrictionBardContact(const FrictionParameters& p, double separation_factor, int one_or_two_step)
      : materials_(p.materials), mu_(p.mu), volume_constraint_(p.volume_constraint),
        separation_factor_(separation_factor), steps_(one_or_two_step) {}
  std::string type() const override { return "friction_bard"; }
  bool needs_normals() const override { return true; }
  bool needs_positions() const override { return separation_factor_ < 9e99; }
  bool acts_on(ContactStage s) const override { return steps_ == 2 || s == ContactStage::Integrated; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  std::vector<int> materials_;
  double mu_, volume_constraint_;
  double separation_factor_;  // Vaango's default 9.9e99: no separation test
  int steps_;                 // 2: both stages, 1: integrated only
};

class ApproachContact final : public ContactModel {
 public:
  explicit ApproachContact(const FrictionParameters& p)
      : materials_(p.materials), mu_(p.mu), volume_constraint_(p.volume_constraint) {}
  std::string type() const override { return "approach"; }
  bool needs_normals() const override { return true; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  std::vector<int> materials_;
  double mu_, volume_constraint_;
};

// <type>friction_LR</type>: Coulomb friction where a logistic-regression
// plane through the particles near the node separates the bodies
// (FrictionLRContact.cpp).
class FrictionLRContact final : public ContactModel {
 public:
  FrictionLRContact(const FrictionParameters& p, int one_or_two_step)
      : materials_(p.materials), mu_(p.mu), volume_constraint_(p.volume_constraint), steps_(one_or_two_step) {}
  std::string type() const override { return "friction_LR"; }
  bool acts_on(ContactStage s) const override { return steps_ == 2 || s == ContactStage::Integrated; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  std::vector<int> materials_;
  double mu_, volume_constraint_;
  int steps_;  // <one_or_two_step>, Vaango's default 2
};

// The unit normal n (from the points labelled -1 towards those labelled +1)
// of the logistic-regression plane through points x (relative to the node),
// VT eqs. 1.132-1.144 with penalties (lambda_n, lambda_n, lambda_n, 0).
Vec3 logistic_regression_normal(const std::vector<Vec3>& x, const std::vector<double>& label, double lambda_n);

// Vaango's Symmetric BC on friction_LR's normal: at a node on the plane of a
// face with symmetry_face[f] (faces 0 x-, 1 x+, ..., 5 z+; the plane is the
// first interior node layer, g.extra from the edge), the component of n along
// that face's axis is zeroed and n renormalised (zero if nothing is left).
void symmetric_normal(const NodeGrid& g, std::size_t node, const std::array<bool, 6>& symmetry_face, Vec3& n);

// <type>nodal_svf</type>: drag between two materials (NodalSvfContact.cpp).
class NodalSvfContact final : public ContactModel {
 public:
  NodalSvfContact(int alpha, int beta, double myu, bool use_svf)
      : alpha_(alpha), beta_(beta), myu_(myu), use_svf_(use_svf) {}
  std::string type() const override { return "nodal_svf"; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;

 private:
  int alpha_, beta_;  // the two materials (<materials>, default 0 and 1)
  double myu_;        // <myu> [N s/m^4]
  bool use_svf_;      // <use_svf>
};

// <type>specified</type> (alias rigid): a master material whose node velocity
// is prescribed, acting at the integrated stage only (VT eq. 1.110, 3.1).
struct SpecifiedParameters {
  std::vector<int> materials;  // always includes the master
  int master = 0;              // <master_material>, default 0
  IntVec3 direction = IntVec3(0, 0, 1);  // <direction>: components imposed on the other materials
  bool normal_only = false;    // <normal_only>: impose only the approaching normal component
  double volume_constraint = 0.0;
  double stop_time = std::numeric_limits<double>::max();
  Vec3 velocity_after_stop = Vec3::Zero();
  std::vector<std::pair<double, Vec3>> profile;  // <filename>: rows t vx vy vz, t increasing
};

class SpecifiedContact final : public ContactModel {
 public:
  explicit SpecifiedContact(SpecifiedParameters p) : p_(std::move(p)) {}
  std::string type() const override { return "specified"; }
  bool needs_normals() const override { return p_.normal_only; }
  bool acts_on(ContactStage s) const override { return s == ContactStage::Integrated; }
  void exchange(ContactStage stage, ContactNodes& nodes) const override;
  // The prescribed velocity at time t, or false when the master keeps its
  // own (interpolated) node velocity ("rigid velocity": t <= stop_time, no file).
  bool imposed_velocity(double t, Vec3& v) const;

 private:
  SpecifiedParameters p_;
};

}  // namespace tephra
