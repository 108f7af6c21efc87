#pragma once
// Ghost filling and node accumulation when the patches are spread over MPI
// ranks (issue 7). Same rules and same results as LocalHaloExchange
// (HaloExchange.h), entry for entry and bit for bit, whatever the rank
// layout: the fields given to each call hold only this rank's patches
// (PatchFields(grid, ghosts, own_patch_indices)).
//
// exchange(): each ghost entry is read from the patch that owns its level
//   index (core/grid/HaloIndex.h); a patch on this rank is copied, one on
//   another rank arrives by message. The plan (which entries each rank sends
//   to each other rank, in which order) is built once per field kind and
//   ghost width, then each call packs, exchanges (non-blocking) and unpacks.
// accumulate(): every stored copy of a physical node goes to the node's home
//   rank (the rank of the patch that owns it); the home rank adds the copies
//   in (patch index, storage position) order -- the order of the one-process
//   sum, so the bits match -- and sends the sum back to every copy.
#include <map>
#include <memory>
#include <vector>

#include "core/grid/HaloExchange.h"

namespace tephra {

class MpiHaloExchange final : public HaloExchange {
 public:
  // owner[p] = rank of grid.patches[p] (core/parallel/LoadBalancer); every
  // rank passes the same vector. The grid must outlive this object.
  MpiHaloExchange(const Grid& grid, std::vector<int> owner);
  ~MpiHaloExchange() override;

  void exchange(PatchFields<CellField<double>>& f) override;
  void exchange(PatchFields<CellField<Vec3>>& f) override;
  void exchange(PatchFields<NodeField<double>>& f) override;
  void exchange(PatchFields<NodeField<Vec3>>& f) override;

  void accumulate(PatchFields<NodeField<double>>& f) override;
  void accumulate(PatchFields<NodeField<Vec3>>& f) override;

  // A batch: one message per peer rank for all its fields, sent at begin,
  // received and unpacked at finish (HaloExchange.h).
  void begin_exchange(CellHaloBatch& b) override;
  void finish_exchange(CellHaloBatch& b) override;

  // The indices into grid.patches that this rank owns, ascending.
  const std::vector<int>& own_patches() const { return own_; }

  struct Plan;  // MpiHaloExchange.cpp

  // What this process has sent to other ranks so far (every exchange and
  // accumulate call of every instance): the figures of the scaling model,
  // docs/scaling.md (bytes = 8 doubles).
  struct Traffic {
    long long calls = 0, messages = 0, doubles = 0;
  };
  static Traffic traffic();

 private:
  template <class FieldT>
  void exchange_impl(PatchFields<FieldT>& f, bool nodes);
  template <class T>
  void accumulate_impl(PatchFields<NodeField<T>>& f);
  const Plan& plan(bool nodes, bool accumulate, int ghosts, const std::vector<int>& fields_patches);

  const Grid* grid_;
  std::vector<int> owner_;
  std::vector<int> own_;
  int rank_ = 0, size_ = 1;
  std::map<std::vector<int>, std::unique_ptr<Plan>> plans_;
};

}  // namespace tephra
