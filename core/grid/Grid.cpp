// make_grid: reads <Grid><Level><Box ...> into one rectangular patched grid.
//
// Forms found in Vaango decks (shared/decks): a Box with <resolution>, or a
// Box without it and the Level's <spacing>; <extraCells> and <patches> per
// Box; <periodic> per Level. Vaango computes cells = (upper-lower)/spacing and
// requires that to be a whole number; we accept it within 1e-6 relative.
#include "core/grid/Grid.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

const char* kAxis[3] = {"x", "y", "z"};

std::string vec_str(const Vec3& v) {
  std::ostringstream s;
  s.precision(17);
  s << "[" << v[0] << ", " << v[1] << ", " << v[2] << "]";
  return s.str();
}

struct BoxSpec {
  const DeckNode* node = nullptr;
  Vec3 lower, upper, dx;
  IntVec3 cells, extra, patches;
  IntVec3 offset = IntVec3::Zero();  // first cell in the level's index space
};

bool nearly_equal(double a, double b, double rel) {
  return std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

// x / step as a whole number, or -1 when it is not one within 1e-6 relative.
long long whole_ratio(double x, double step) {
  const double r = x / step;
  const double n = std::round(r);
  if (std::abs(r - n) > 1e-6 * std::max(1.0, std::abs(r))) return -1;
  return static_cast<long long>(n);
}

BoxSpec read_box(const DeckNode& box, const DeckNode* level_spacing) {
  BoxSpec b;
  b.node = &box;
  if (const DeckNode* ap = box.child("autoPatch")) ap->missing_feature("<autoPatch> (automatic patch layout)");
  b.lower = box.get_vec3("lower");
  b.upper = box.get_vec3("upper");
  for (int d = 0; d < 3; ++d)
    if (!(b.upper[d] > b.lower[d]))
      box.require_child("upper").fail(std::string("upper must exceed lower in ") + kAxis[d] +
                                      ": lower " + vec_str(b.lower) + ", upper " + vec_str(b.upper));
  const Vec3 extent = b.upper - b.lower;

  const DeckNode* res = box.child("resolution");
  if (res && level_spacing)
    res->fail("give either <resolution> in the Box or <spacing> in the Level, not both");
  if (res) {
    b.cells = res->as_int_vec3();
    for (int d = 0; d < 3; ++d)
      if (b.cells[d] < 1) res->fail(std::string("resolution must be >= 1 in ") + kAxis[d]);
  } else if (level_spacing) {
    const Vec3 h = level_spacing->as_vec3();
    for (int d = 0; d < 3; ++d) {
      if (!(h[d] > 0)) level_spacing->fail(std::string("spacing must be > 0 in ") + kAxis[d]);
      const long long n = whole_ratio(extent[d], h[d]);
      if (n < 1 || n > 1000000000LL)
        level_spacing->fail(std::string("spacing does not divide the box into whole cells in ") + kAxis[d] +
                            ": (upper - lower)/spacing = " + std::to_string(extent[d] / h[d]) +
                            " (box at line " + std::to_string(box.line) + ")");
      b.cells[d] = static_cast<int>(n);
    }
  } else {
    box.fail("a Box needs <resolution>, or its Level needs <spacing>");
  }
  b.dx = extent.cwiseQuotient(b.cells.cast<double>());

  b.extra = box.get_int_vec3("extraCells", IntVec3::Zero());
  for (int d = 0; d < 3; ++d)
    if (b.extra[d] < 0) box.require_child("extraCells").fail("extraCells must be >= 0");

  b.patches = box.get_int_vec3("patches", IntVec3::Ones());
  for (int d = 0; d < 3; ++d) {
    if (b.patches[d] < 1) box.require_child("patches").fail("patches must be >= 1");
    if (b.patches[d] > b.cells[d])
      box.require_child("patches").fail(std::string("more patches than cells in ") + kAxis[d] + ": " +
                                        std::to_string(b.patches[d]) + " patches, " +
                                        std::to_string(b.cells[d]) + " cells");
  }
  return b;
}

// Several Boxes are merged only when they share one spacing and extraCells,
// sit on one lattice and fill their bounding box without overlap.
void place_boxes(std::vector<BoxSpec>& boxes, Vec3& lower, Vec3& upper, IntVec3& cells) {
  const BoxSpec& first = boxes.front();
  lower = first.lower;
  upper = first.upper;
  for (const BoxSpec& b : boxes) {
    lower = lower.cwiseMin(b.lower);
    upper = upper.cwiseMax(b.upper);
    for (int d = 0; d < 3; ++d)
      if (!nearly_equal(b.dx[d], first.dx[d], 1e-6))
        b.node->missing_feature("multi-box levels whose boxes have different cell sizes");
    if (b.extra != first.extra)
      b.node->missing_feature("multi-box levels whose boxes have different extraCells");
  }
  long long covered = 0;
  for (BoxSpec& b : boxes) {
    for (int d = 0; d < 3; ++d) {
      const long long off = whole_ratio(b.lower[d] - lower[d], first.dx[d]);
      if (off < 0) b.node->missing_feature("multi-box levels whose boxes are not aligned on one lattice");
      b.offset[d] = static_cast<int>(off);
    }
    covered += 1LL * b.cells[0] * b.cells[1] * b.cells[2];
  }
  for (int d = 0; d < 3; ++d) {
    const long long n = whole_ratio(upper[d] - lower[d], first.dx[d]);
    if (n < 1) boxes.front().node->missing_feature("multi-box levels that do not tile one rectangle");
    cells[d] = static_cast<int>(n);
  }
  for (size_t a = 0; a < boxes.size(); ++a)
    for (size_t c = a + 1; c < boxes.size(); ++c) {
      const IndexRange ra{boxes[a].offset, boxes[a].offset + boxes[a].cells};
      const IndexRange rc{boxes[c].offset, boxes[c].offset + boxes[c].cells};
      if (!ra.intersect(rc).empty())
        boxes[c].node->missing_feature("multi-box levels with overlapping boxes");
    }
  if (covered != 1LL * cells[0] * cells[1] * cells[2])
    boxes.front().node->missing_feature("multi-box levels that do not tile one rectangle");
}

}  // namespace

std::vector<int> split_evenly(int n, int parts) {
  if (parts < 1 || parts > n) throw std::logic_error("split_evenly: need 1 <= parts <= n");
  std::vector<int> b(parts + 1, 0);
  const int base = n / parts, rem = n % parts;
  for (int p = 0; p < parts; ++p) b[p + 1] = b[p] + base + (p < rem ? 1 : 0);
  return b;
}

void Grid::set_patch_extra_cells() {
  for (Patch& p : patches)
    for (int d = 0; d < 3; ++d) {
      p.extra_lo[d] = p.lo[d] == 0 ? -extra_cells[d] : p.lo[d];
      p.extra_hi[d] = p.hi[d] == cells[d] ? cells[d] + extra_cells[d] : p.hi[d];
    }
}

void Grid::index_patches() {
  for (int d = 0; d < 3; ++d) {
    std::vector<int>& c = cuts_[d];
    c.assign({0, cells[d]});
    for (const Patch& p : patches) {
      if (p.lo[d] < 0 || p.hi[d] > cells[d] || p.lo[d] >= p.hi[d])
        throw std::logic_error("Grid::index_patches: patch " + std::to_string(p.id) + " outside the domain");
      c.push_back(p.lo[d]);
      c.push_back(p.hi[d]);
    }
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  const int nb0 = int(cuts_[0].size()) - 1, nb1 = int(cuts_[1].size()) - 1, nb2 = int(cuts_[2].size()) - 1;
  block_owner_.assign(size_t(nb0) * nb1 * nb2, -1);
  auto block_of = [&](int d, int cell) {
    return int(std::upper_bound(cuts_[d].begin(), cuts_[d].end(), cell) - cuts_[d].begin()) - 1;
  };
  for (size_t n = 0; n < patches.size(); ++n) {
    const Patch& p = patches[n];
    for (int bk = block_of(2, p.lo[2]); bk < block_of(2, p.hi[2] - 1) + 1; ++bk)
      for (int bj = block_of(1, p.lo[1]); bj < block_of(1, p.hi[1] - 1) + 1; ++bj)
        for (int bi = block_of(0, p.lo[0]); bi < block_of(0, p.hi[0] - 1) + 1; ++bi) {
          int& owner = block_owner_[(size_t(bk) * nb1 + bj) * nb0 + bi];
          if (owner != -1) throw std::logic_error("Grid::index_patches: patches overlap");
          owner = int(n);
        }
  }
  for (int o : block_owner_)
    if (o == -1) throw std::logic_error("Grid::index_patches: patches leave cells uncovered");
}

int Grid::patch_owning_cell(const IntVec3& c) const {
  if (!interior_cells().contains(c) || block_owner_.empty()) return -1;
  int b[3];
  for (int d = 0; d < 3; ++d)
    b[d] = int(std::upper_bound(cuts_[d].begin(), cuts_[d].end(), c[d]) - cuts_[d].begin()) - 1;
  const size_t nb0 = cuts_[0].size() - 1, nb1 = cuts_[1].size() - 1;
  return block_owner_[(size_t(b[2]) * nb1 + b[1]) * nb0 + b[0]];
}

Grid make_grid(const DeckNode& grid_section) {
  const auto levels = grid_section.children_named("Level");
  if (levels.empty()) grid_section.fail("<Grid> needs a <Level>");
  if (levels.size() > 1) levels[1]->missing_feature("several Levels (AMR)");
  const DeckNode& level = *levels.front();
  if (const DeckNode* s = level.child("Stretch")) s->missing_feature("stretched grids (<Stretch>)");

  const DeckNode* spacing = level.child("spacing");
  const auto box_nodes = level.children_named("Box");
  if (box_nodes.empty()) level.fail("a <Level> needs at least one <Box>");
  std::vector<BoxSpec> boxes;
  for (const DeckNode* b : box_nodes) boxes.push_back(read_box(*b, spacing));

  Grid g;
  if (boxes.size() == 1) {
    g.lower = boxes[0].lower;
    g.upper = boxes[0].upper;
    g.cells = boxes[0].cells;
  } else {
    place_boxes(boxes, g.lower, g.upper, g.cells);
  }
  g.dx = (g.upper - g.lower).cwiseQuotient(g.cells.cast<double>());
  g.extra_cells = boxes[0].extra;

  if (const DeckNode* per = level.child("periodic")) {
    g.periodic = per->as_int_vec3();
    for (int d = 0; d < 3; ++d) {
      if (g.periodic[d] != 0 && g.periodic[d] != 1) per->fail("periodic entries must be 0 or 1");
      if (g.periodic[d] == 1 && g.extra_cells[d] != 0)
        per->missing_feature(std::string("extraCells in the periodic direction ") + kAxis[d]);
    }
  }

  // Patches: each Box is split on its own; ids run x fastest, Box by Box.
  for (const BoxSpec& b : boxes) {
    std::vector<int> cut[3];
    for (int d = 0; d < 3; ++d) cut[d] = split_evenly(b.cells[d], b.patches[d]);
    for (int pk = 0; pk < b.patches[2]; ++pk)
      for (int pj = 0; pj < b.patches[1]; ++pj)
        for (int pi = 0; pi < b.patches[0]; ++pi) {
          Patch p;
          p.id = int(g.patches.size());
          p.lo = b.offset + IntVec3(cut[0][pi], cut[1][pj], cut[2][pk]);
          p.hi = b.offset + IntVec3(cut[0][pi + 1], cut[1][pj + 1], cut[2][pk + 1]);
          g.patches.push_back(p);
        }
  }
  g.set_patch_extra_cells();
  g.index_patches();
  return g;
}

}  // namespace tephra
