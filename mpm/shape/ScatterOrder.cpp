#include "mpm/shape/ScatterOrder.h"

#include <algorithm>

#ifdef _OPENMP
#include <omp.h>
#endif

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

// Stable counting sort of the keys, split among T threads (T = 1 below 4096
// particles). Thread t owns the contiguous index range [np t / T, np (t+1) / T).
// 1. Each thread counts the keys of its range: count[t][k].
// 2. Exclusive prefix sum in (key, thread) order:
//      first[t][k] = sum_{k' < k} sum_t' count[t'][k'] + sum_{t' < t} count[t'][k],
//    so key k's slots hold thread 0's particles, then thread 1's, ...
// 3. Each thread places its range in ascending index from first[t][k].
// Inside a key the particles of a lower thread have lower indices, so every
// key lists its particles in ascending index: the result is the serial
// stable sort, the same for any T (tested in test_mpm_scatter_order).
void ScatterOrder::finish() {
  const std::size_t np = key.size();
  const std::size_t keys = std::size_t(4) * blocks_y * blocks_z;
  int T = 1;
#ifdef _OPENMP
  if (np >= 4096) T = std::max(1, omp_get_max_threads());
#endif
  // count[t * (keys + 1) + k + 1] for thread t; becomes the slot start of (t, k).
  std::vector<std::uint32_t> count(std::size_t(T) * (keys + 1), 0);
  std::vector<std::uint32_t> start(keys + 1, 0);  // start[k]: first slot of key k (all threads)
  index.resize(np);
  std::size_t moved = 0;
#pragma omp parallel num_threads(T) reduction(+ : moved)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    const std::size_t lo = np * std::size_t(t) / std::size_t(T), hi = np * std::size_t(t + 1) / std::size_t(T);
    std::uint32_t* c = count.data() + std::size_t(t) * (keys + 1);
    for (std::size_t i = lo; i < hi; ++i) ++c[key[i] + 1];
#pragma omp barrier
#pragma omp single
    {
      // Serial over keys x threads (a few thousand entries): key-major, thread-minor prefix sum.
      std::uint32_t run = 0;
      for (std::size_t k = 0; k < keys; ++k) {
        start[k] = run;
        for (int u = 0; u < T; ++u) {
          std::uint32_t& slot = count[std::size_t(u) * (keys + 1) + k + 1];
          const std::uint32_t n = slot;
          slot = run;  // first slot of thread u's particles of key k
          run += n;
        }
      }
      start[keys] = run;
    }  // implicit barrier
    for (std::size_t i = lo; i < hi; ++i) index[c[key[i] + 1]++] = std::uint32_t(i);
#pragma omp barrier
#pragma omp for schedule(static)
    for (long j = 0; j < long(np); ++j) moved += index[std::size_t(j)] != std::uint32_t(j);
  }
  displaced = moved;
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

void ScatterOrder::sort_blocks_by_id(const long long* id) {
  if (particles == 0) return;
  const long blocks = long(block.size()) - 1;
  // finish() left index[j] == j everywhere (displaced == 0): then a block
  // already in ascending id keeps index[j] == j and adds nothing to `moved`.
  const bool identity = displaced == 0;
  std::size_t moved = 0;
#pragma omp parallel for schedule(static) reduction(+ : moved) if (particles >= 4096)
  for (long b = 0; b < blocks; ++b) {
    std::uint32_t* first = index.data() + block[std::size_t(b)];
    std::uint32_t* last = index.data() + block[std::size_t(b) + 1];
    // Most steps no particle changes block and the block is already in
    // ascending id: one read-only pass finds that, and the insertion sort
    // (which would move nothing) and the recount are skipped. Same result
    // either way: the insertion sort leaves an ascending block unchanged.
    bool ascending = true;
    long long prev = id[*first];
    for (const std::uint32_t* a = first + 1; a < last; ++a) {
      const long long k = id[*a];
      if (k < prev) { ascending = false; break; }
      prev = k;
    }
    if (ascending && identity) continue;
    if (!ascending) {
      for (std::uint32_t* a = first + 1; a < last; ++a) {
        const std::uint32_t v = *a;
        const long long key = id[v];
        std::uint32_t* c = a;
        for (; c > first && id[*(c - 1)] > key; --c) *c = *(c - 1);
        *c = v;
      }
    }
    for (std::uint32_t* a = first; a < last; ++a) moved += *a != std::uint32_t(a - index.data());
  }
  displaced = moved;
}

std::uint32_t ScatterOrder::run_start(int c, int u, int T) const {
  const std::uint32_t* first = block.data() + colour[std::size_t(c)];
  const std::uint32_t* last = block.data() + colour[std::size_t(c) + 1];
  if (u <= 0) return *first;
  if (u >= T) return *last;
  const std::size_t p0 = *first, n = std::size_t(*last) - p0;
  const std::size_t target = p0 + n * std::size_t(u) / std::size_t(T);
  // The first block start >= target, or the one before it when that is nearer
  // (a tie: the lower). first < last: a colour's starts end with the next
  // colour's first start (or np), and *first <= target <= *last.
  const std::uint32_t* at = std::lower_bound(first, last + 1, std::uint32_t(target));
  if (at > first && target - std::size_t(at[-1]) <= std::size_t(*at) - target) --at;
  return *at;
}

}  // namespace tephra
