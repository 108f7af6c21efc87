#pragma once
// Filling ghost entries from the patches that own them, and summing node
// contributions that several patches made to one node.
//
// The interface is what the steps call; LocalHaloExchange does it for all
// patches held in one process. An MPI implementation (one rank per group of
// patches) implements the same calls with messages.
//
// exchange(): every stored entry of a patch outside its with_extra() range
//   (its ghosts) receives the value of the patch that owns that index. The
//   owner of a cell is the patch whose cells_with_extra() holds it; a node
//   shared by patches is read from any of them (they agree after
//   accumulate()). In a periodic direction index c stands for c mod cells
//   (node cells == node 0). Ghosts beyond the extra cells of a non-periodic
//   face have no owner and are left unchanged: boundary conditions fill them.
//
// accumulate() (MPM after particle-to-grid): every physical node receives
//   the sum of the values that all patches hold for it -- interior, shared
//   boundary nodes and ghost nodes alike, with periodic images counted as the
//   same node -- and every stored copy of it is set to that sum. So a kernel
//   that scatters into ghost nodes must start from a zeroed field. Values in
//   ghost nodes beyond the extra nodes of a non-periodic face belong to no
//   node and are dropped (no particle may be there; the MPM step checks).
#include <memory>

#include "core/base/Types.h"
#include "core/grid/Fields.h"

namespace tephra {

class HaloExchange {
 public:
  virtual ~HaloExchange() = default;

  virtual void exchange(PatchFields<CellField<double>>& f) = 0;
  virtual void exchange(PatchFields<CellField<Vec3>>& f) = 0;
  virtual void exchange(PatchFields<NodeField<double>>& f) = 0;
  virtual void exchange(PatchFields<NodeField<Vec3>>& f) = 0;

  virtual void accumulate(PatchFields<NodeField<double>>& f) = 0;
  virtual void accumulate(PatchFields<NodeField<Vec3>>& f) = 0;
};

// All patches in this process: plain copies, no messages.
class LocalHaloExchange final : public HaloExchange {
 public:
  explicit LocalHaloExchange(const Grid& grid) : grid_(&grid) {}

  void exchange(PatchFields<CellField<double>>& f) override;
  void exchange(PatchFields<CellField<Vec3>>& f) override;
  void exchange(PatchFields<NodeField<double>>& f) override;
  void exchange(PatchFields<NodeField<Vec3>>& f) override;

  void accumulate(PatchFields<NodeField<double>>& f) override;
  void accumulate(PatchFields<NodeField<Vec3>>& f) override;

 private:
  const Grid* grid_;
};

}  // namespace tephra
