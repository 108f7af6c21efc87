#pragma once
// Hooks through which a coupled component (MPMICE, mpmice/) takes part in
// the MPM step: MpmComponent::advance calls them, when set, at the three
// places where the coupled order of the Vaango theory manual sec. 26.1.3
// needs the grid (steps 1 -> 2-6, 7, 8-13 of docs/mpmice.md).
namespace tephra {

class MpmCoupling {
 public:
  virtual ~MpmCoupling() = default;
  // After P2G (m_g, v_g, stencils of every material), before the internal force.
  virtual void after_interpolate_to_grid(double t, double dt, int step) = 0;
  // After f_int,g of every material (add forces that depend on the particles).
  virtual void add_internal_forces() = 0;
  // After v*_g = v_g + a_g dt, before contact and the grid BCs: add velocity changes to v*_g.
  virtual void after_integrate_grid(double dt, int step) = 0;
};

}  // namespace tephra
