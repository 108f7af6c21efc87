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
//
// A CellHaloBatch fills the ghosts of several cell fields together (issue 7
// item 1): begin_exchange() sends the owned values of every field of the
// batch (over MPI: one message per peer rank for the whole batch, not one
// per field), finish_exchange() receives and writes the ghosts. Work done
// between the two overlaps the messages; it must not read the batch's ghosts,
// and owned values it writes after begin_exchange() are not in this exchange.
// The ghosts after finish_exchange() are those exchange() gives each field
// alone, bit for bit.
#include <memory>
#include <vector>

#include "core/base/Types.h"
#include "core/grid/Fields.h"

namespace tephra {

struct CellHaloBatch {
  CellHaloBatch& add(PatchFields<CellField<double>>& f) {
    scalars.push_back(&f);
    return *this;
  }
  CellHaloBatch& add(PatchFields<CellField<Vec3>>& f) {
    vectors.push_back(&f);
    return *this;
  }
  std::vector<PatchFields<CellField<double>>*> scalars;
  std::vector<PatchFields<CellField<Vec3>>*> vectors;
  std::shared_ptr<void> in_flight;  // the implementation's messages between begin and finish
};

class HaloExchange {
 public:
  virtual ~HaloExchange() = default;

  // In one process: every field's exchange() at begin, nothing at finish.
  virtual void begin_exchange(CellHaloBatch& b) {
    for (auto* f : b.scalars) exchange(*f);
    for (auto* f : b.vectors) exchange(*f);
  }
  virtual void finish_exchange(CellHaloBatch&) {}
  void exchange_now(CellHaloBatch& b) {
    begin_exchange(b);
    finish_exchange(b);
  }

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
