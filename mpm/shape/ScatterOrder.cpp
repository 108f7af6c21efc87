#include "mpm/shape/ScatterOrder.h"

#include <algorithm>

namespace tephra {

void ScatterOrder::prepare(std::size_t np, int ny, int nz, int span_y, int span_z) {
  // w >= span - 1 keeps two blocks of one colour apart (ScatterOrder.h).
  width_y = std::max(span_y - 1, 1);
  width_z = std::max(span_z - 1, 1);
  blocks_y = (std::max(ny, 1) + width_y - 1) / width_y;
  blocks_z = (std::max(nz, 1) + width_z - 1) / width_z;
  key.resize(np);
  particles = 0;
}

void ScatterOrder::finish() {
  const std::size_t np = key.size();
  const std::size_t keys = std::size_t(4) * blocks_y * blocks_z;
  // Counting sort: count per key, prefix sums, then place the particles in
  // ascending index (stable).
  std::vector<std::uint32_t> start(keys + 1, 0);
  for (std::size_t i = 0; i < np; ++i) ++start[key[i] + 1];
  for (std::size_t k = 0; k < keys; ++k) start[k + 1] += start[k];
  index.resize(np);
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < np; ++i) index[next[key[i]]++] = std::uint32_t(i);
  }
  displaced = 0;
  for (std::size_t j = 0; j < np; ++j) displaced += index[j] != j;
  // The non-empty blocks, colour-major (the key numbering is colour-major).
  const std::size_t per_colour = std::size_t(blocks_y) * blocks_z;
  block.clear();
  for (int c = 0; c < 4; ++c) {
    colour[c] = std::uint32_t(block.size());
    for (std::size_t k = c * per_colour; k < (c + 1) * per_colour; ++k)
      if (start[k + 1] > start[k]) block.push_back(start[k]);
  }
  colour[4] = std::uint32_t(block.size());
  block.push_back(std::uint32_t(np));
  particles = np;
}

}  // namespace tephra
