#pragma once
// Node-centred arrays of one MPM material for one step (the `_NC` fields).
// Node (i,j,k), i = 0..n-1, sits at origin + (i,j,k) h; index i fastest.
#include <cstddef>
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeBox.h"

namespace tephra {

struct NodeGrid {
  Vec3 origin = Vec3::Zero();  // position of node (0,0,0)
  Vec3 h = Vec3::Ones();       // node spacing (the cell size)
  IntVec3 n = IntVec3::Ones(); // nodes per direction
  IntVec3 extra = IntVec3::Zero(); // node layers beyond each domain face: the domain's faces are
                                   // the node planes extra and n - 1 - extra. The deck's extra
                                   // cells, or in a periodic direction (no extra cells there)
                                   // the ghost layers below
  IntVec3 ghost = IntVec3::Zero(); // periodic ghost layers (included in extra): aliases of the
                                   // nodes one period away, which the wide stencils (gimp, cpdi,
                                   // B-splines) reach across a periodic face (mpm/PeriodicGrid.h)

  std::vector<double> mass;            // m_g = sum m_p S_gp                      (g.mass)
  std::vector<double> volume;          // V_g = sum V_p S_gp                      (g.volume)
  std::vector<Vec3> velocity;          // v_g = sum m_p v_p S_gp / m_g, after BCs  (g.velocity)
  std::vector<Vec3> velocity_star;     // v*_g = v_g + a_g dt, after BCs         (g.velocity_star)
  std::vector<Vec3> acceleration;      // a_g = (v*_g - v_g)/dt                   (g.acceleration)
  std::vector<Vec3> external_force;    // sum f_ext,p S_gp + sum m_p b S_gp       (g.externalforce)
  std::vector<Vec3> internal_force;    // -sum V_p sigma_p grad S_gp               (g.internalforce)
  std::vector<Mat3> stress;            // sum V_p sigma_p S_gp / V_g              (g.stressFS)
                                       // (empty when !node_stress)
  // g.stressFS is summed by P2G only when something reads it (the deck saves
  // it): otherwise `stress` stays empty (72 B per node and 9 of the 17 sums
  // per stencil entry of P2G saved). Nothing in the step reads it.
  bool node_stress = true;

  // The nodes the node-wise passes of a step visit (zeroing, v = p/m,
  // integration, grid BCs, symmetry folds, the MUSL node choices; loops in
  // mpm/NodeRuns.h). The whole grid unless `restricted`: on MPI ranks
  // MpmComponent::set_node_boxes restricts every material's grid to the
  // rank's node box closed under the symmetry mirrors (docs/parallel.md
  // "Session 23"). Outside it the arrays hold 0 (reset() zeroes what the
  // previous box held), as they did when every rank ran the passes over the
  // whole grid: a node outside the box gets no particle sum and no combine.
  NodeBox active;
  bool restricted = false;
  NodeBox cleared;  // restricted: the nodes the last reset() zeroed (the hull of the last two boxes)
  NodeBox active_box() const { return restricted ? active : NodeBox{IntVec3::Zero(), n}; }

  std::size_t count() const { return std::size_t(n[0]) * n[1] * n[2]; }
  std::size_t index(int i, int j, int k) const {
    return std::size_t(i) + std::size_t(n[0]) * (std::size_t(j) + std::size_t(n[1]) * k);
  }
  std::size_t index(const IntVec3& c) const { return index(c[0], c[1], c[2]); }
  Vec3 position(int i, int j, int k) const { return origin + Vec3(i * h[0], j * h[1], k * h[2]); }

  // Sizes every array to count() and sets it to zero (Vaango's grid reset).
  // Threaded (NodeGrid.cpp): zero is zero for any split, so the same bits.
  // Restricted: zeroes only the hull of this and the previous active box
  // (the rest is 0 already), unless the arrays change size.
  void reset();
};

}  // namespace tephra
