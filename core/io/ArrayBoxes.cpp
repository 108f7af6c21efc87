#include "core/io/ArrayBoxes.h"

namespace tephra {
namespace {

// Pieces of `a` outside `b` (disjoint; a itself when they do not meet).
void cut(const ArrayBox& a, const ArrayBox& b, std::vector<ArrayBox>& out) {
  const ArrayBox meet{a.lo.cwiseMax(b.lo), a.hi.cwiseMin(b.hi)};
  if (a.empty()) return;
  if (meet.empty()) {
    out.push_back(a);
    return;
  }
  ArrayBox rest = a;  // shrinks to `meet` one direction at a time
  for (int d = 0; d < 3; ++d) {
    ArrayBox below = rest, above = rest;
    below.hi[d] = meet.lo[d];
    above.lo[d] = meet.hi[d];
    if (!below.empty()) out.push_back(below);
    if (!above.empty()) out.push_back(above);
    rest.lo[d] = meet.lo[d];
    rest.hi[d] = meet.hi[d];
  }
}

}  // namespace

std::vector<ArrayBox> subtract_boxes(const ArrayBox& a, const std::vector<ArrayBox>& minus) {
  std::vector<ArrayBox> pieces;
  if (!a.empty()) pieces.push_back(a);
  for (const ArrayBox& b : minus) {
    if (b.empty()) continue;
    std::vector<ArrayBox> next;
    for (const ArrayBox& p : pieces) cut(p, b, next);
    pieces.swap(next);
  }
  return pieces;
}

std::vector<ArrayBox> kept_when_later_wins(const std::vector<ArrayBox>& boxes, std::size_t n) {
  return subtract_boxes(boxes.at(n), std::vector<ArrayBox>(boxes.begin() + long(n) + 1, boxes.end()));
}

std::vector<ArrayBox> kept_when_earlier_wins(const std::vector<ArrayBox>& boxes, std::size_t n) {
  return subtract_boxes(boxes.at(n), std::vector<ArrayBox>(boxes.begin(), boxes.begin() + long(n)));
}

}  // namespace tephra
