#pragma once
// Box arithmetic for per-rank output (session 25): which entries of a grid
// array each rank writes when several ranks' (or patches') boxes overlap.
#include <vector>

#include "core/io/OutputFrame.h"

namespace tephra {

// a minus the union of `minus`, as disjoint boxes (empty boxes dropped).
// Each subtraction cuts a box into at most 6 slabs: below / above the
// removed box along x, then along y, then along z, the remainder removed.
std::vector<ArrayBox> subtract_boxes(const ArrayBox& a, const std::vector<ArrayBox>& minus);

// Owner rule "the later box wins" (ICE: blocks written in patch order, the
// later patch overwriting a shared face): box n keeps boxes[n] minus every
// boxes[m], m > n.
std::vector<ArrayBox> kept_when_later_wins(const std::vector<ArrayBox>& boxes, std::size_t n);

// Owner rule "the earlier box wins" (MPM RankNodeSums::whole: each node from
// the lowest rank whose box holds it): boxes[n] minus every boxes[m], m < n.
std::vector<ArrayBox> kept_when_earlier_wins(const std::vector<ArrayBox>& boxes, std::size_t n);

}  // namespace tephra
