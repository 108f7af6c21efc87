#pragma once
// Grid fields of one patch: contiguous arrays (i fastest, then j, then k) that
// hold the patch's own entries, the extra (boundary) cells it owns on domain
// faces, and a ghost layer of a given width. operator()(i,j,k) takes GLOBAL
// indices, so kernels never translate between patch-local and level indices.
//
// Where a value lives is in the type (DESIGN.md §2.5):
//   CellField<T>        cell (i,j,k) = [lower + (i,j,k) dx, +dx)
//   NodeField<T>        node (i,j,k) at lower + (i,j,k) dx; a patch of cells
//                       lo..hi-1 has nodes lo..hi (one more than cells)
//   FaceField<T, Dir>   face (i,j,k) = the low face of cell (i,j,k) normal to
//                       Dir; a patch has faces lo..hi in Dir, lo..hi-1 across
//
// Ranges handed out (all [lo, hi), hi exclusive):
//   interior()    the entries this patch computes (its cells, its nodes ...)
//   with_extra()  interior plus the extra cells/nodes on domain faces
//   with_ghosts() everything stored: the smallest box holding with_extra()
//                 and interior() grown by the ghost width
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <vector>

#include "core/grid/Grid.h"
#include "core/grid/IndexRange.h"

namespace tephra {

// Storage shared by the three field kinds: a box of indices and its values.
template <class T>
class GridArray {
 public:
  using value_type = T;

  GridArray() = default;
  GridArray(int patch_id, const IndexRange& interior, const IndexRange& with_extra, int ghosts)
      : patch_id_(patch_id), ghosts_(ghosts), interior_(interior), with_extra_(with_extra) {
    assert(ghosts >= 0);
    // Stored box: the extra-cell box grown by the ghost width. On a domain
    // face with extraCells >= ghosts the extra cells already serve as ghosts.
    storage_ = {with_extra.lo.cwiseMin(interior.lo - IntVec3::Constant(ghosts)),
                with_extra.hi.cwiseMax(interior.hi + IntVec3::Constant(ghosts))};
    n_ = storage_.extent();
    // Every value starts at zero: an Eigen vector's default constructor leaves
    // its entries uninitialised, and cells no phase writes (extra cells of a
    // source field, say) would otherwise reach the output as garbage.
    data_.assign(static_cast<size_t>(storage_.size()), zero_value());
  }

  T& operator()(int i, int j, int k) { return data_[offset(i, j, k)]; }
  const T& operator()(int i, int j, int k) const { return data_[offset(i, j, k)]; }
  T& operator()(const IntVec3& c) { return (*this)(c[0], c[1], c[2]); }
  const T& operator()(const IntVec3& c) const { return (*this)(c[0], c[1], c[2]); }

  const IndexRange& interior() const { return interior_; }
  const IndexRange& with_extra() const { return with_extra_; }
  const IndexRange& with_ghosts() const { return storage_; }
  int ghost_width() const { return ghosts_; }
  int patch_id() const { return patch_id_; }

  void fill(const T& value) { std::fill(data_.begin(), data_.end(), value); }
  T* data() { return data_.data(); }
  const T* data() const { return data_.data(); }
  size_t size() const { return data_.size(); }

  // Position of (i,j,k) in data(): i fastest.
  size_t offset(int i, int j, int k) const {
    assert(storage_.contains(i, j, k));
    return (static_cast<size_t>(k - storage_.lo[2]) * n_[1] + static_cast<size_t>(j - storage_.lo[1])) * n_[0] +
           static_cast<size_t>(i - storage_.lo[0]);
  }

 private:
  int patch_id_ = 0;
  int ghosts_ = 0;
  IndexRange interior_, with_extra_, storage_;
  IntVec3 n_ = IntVec3::Zero();
  static T zero_value() {
    if constexpr (requires { T::Zero(); }) return T::Zero();
    else return T(0);
  }

  std::vector<T> data_;
};

enum class FieldLocation { Cell, Node, FaceX, FaceY, FaceZ };

template <class T>
class CellField : public GridArray<T> {
 public:
  static constexpr FieldLocation location = FieldLocation::Cell;
  CellField() = default;
  CellField(const Patch& p, int ghosts) : GridArray<T>(p.id, p.cells(), p.cells_with_extra(), ghosts) {}
};

template <class T>
class NodeField : public GridArray<T> {
 public:
  static constexpr FieldLocation location = FieldLocation::Node;
  NodeField() = default;
  NodeField(const Patch& p, int ghosts)
      : GridArray<T>(p.id, {p.lo, p.hi + IntVec3::Ones()}, {p.extra_lo, p.extra_hi + IntVec3::Ones()}, ghosts) {}
};

template <class T, int Dir>
class FaceField : public GridArray<T> {
  static_assert(Dir >= 0 && Dir < 3, "FaceField direction is 0 (x), 1 (y) or 2 (z)");

 public:
  static constexpr FieldLocation location = static_cast<FieldLocation>(2 + Dir);
  FaceField() = default;
  FaceField(const Patch& p, int ghosts)
      : GridArray<T>(p.id, {p.lo, p.hi + IntVec3::Unit(Dir)}, {p.extra_lo, p.extra_hi + IntVec3::Unit(Dir)},
                     ghosts) {}
};

// One field per patch of a grid, in the grid's patch order (field n belongs
// to grid.patches[n]), or the fields of a subset of the patches (an MPI
// rank's own; patch_index(n) says which).
template <class FieldT>
class PatchFields {
 public:
  using field_type = FieldT;
  using value_type = typename FieldT::value_type;

  PatchFields() = default;
  PatchFields(const Grid& grid, int ghosts) : grid_(&grid), ghosts_(ghosts) {
    fields_.reserve(grid.patches.size());
    for (const Patch& p : grid.patches) fields_.emplace_back(p, ghosts);
    // Patch::id is the patch's index in the level's list (make_grid); a
    // rank-local copy of the grid that keeps only its own patches keeps their
    // ids, so patch_index() stays the index into the whole level's patches.
    for (const Patch& p : grid.patches) patch_index_.push_back(p.id);
  }
  // The fields of some patches only (an MPI rank's own patches, in the order
  // given): field n belongs to grid.patches[patch_indices[n]].
  PatchFields(const Grid& grid, int ghosts, const std::vector<int>& patch_indices)
      : grid_(&grid), ghosts_(ghosts), patch_index_(patch_indices) {
    fields_.reserve(patch_indices.size());
    for (int p : patch_indices) fields_.emplace_back(grid.patches[size_t(p)], ghosts);
  }

  FieldT& operator[](size_t n) { return fields_[n]; }
  const FieldT& operator[](size_t n) const { return fields_[n]; }
  size_t size() const { return fields_.size(); }
  auto begin() { return fields_.begin(); }
  auto end() { return fields_.end(); }
  auto begin() const { return fields_.begin(); }
  auto end() const { return fields_.end(); }

  const Grid& grid() const { return *grid_; }
  int ghost_width() const { return ghosts_; }
  // Index into grid.patches of field n.
  int patch_index(size_t n) const { return patch_index_[n]; }
  // True when the fields cover every patch of the grid in grid order.
  bool holds_all_patches() const { return grid_ && fields_.size() == grid_->patches.size() &&
                                           std::is_sorted(patch_index_.begin(), patch_index_.end()); }
  void fill(const value_type& v) {
    for (FieldT& f : fields_) f.fill(v);
  }

 private:
  const Grid* grid_ = nullptr;
  int ghosts_ = 0;
  std::vector<FieldT> fields_;
  std::vector<int> patch_index_;
};

}  // namespace tephra
