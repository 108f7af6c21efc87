#pragma once
// The order in which the particle -> node scatters (P2G, internal force, the
// MUSL velocity) visit the particles, so that they run on several threads
// without per-thread node buffers and give the SAME BITS for any thread count.
//
// Blocks and colours. Let every particle's stencil touch the node rows
// y0..y0+span_y-1 and z0..z0+span_z-1 (y0, z0 its lowest node indices in y
// and z, span the largest footprint of any particle, 2 for linear, 3 for
// gimp / 3rdorderBS). With w = max(span - 1, 1) per axis, particle p belongs
// to block (by, bz) = (floor(y0 / w_y), floor(z0 / w_z)), of colour
// c = (by mod 2) + 2 (bz mod 2). A block touches the node rows
// [by w, (by + 1) w + span - 2] in y (likewise z); the next block of the
// same colour starts at (by + 2) w > (by + 1) w + span - 2 because
// w >= span - 1. So two blocks of one colour never touch the same node.
//
// The scatter runs the colours 0, 1, 2, 3 one after the other; the blocks of
// a colour in parallel (any thread, any order); inside a block the particles
// in increasing index. Each node is touched by at most one block per colour,
// so its sum is taken in the order: colour 0 particles (ascending index),
// colour 1, colour 2, colour 3. That order does not depend on the thread
// count, nor on which thread ran which block: the node sums are bit-for-bit
// the same with 1, 2 or any number of threads. Equivalently, the sums are
// those of a serial loop over the particles stably sorted by colour.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tephra {

struct ScatterOrder {
  std::size_t particles = 0;          // particle count it was built for (0: not built)
  std::vector<std::uint32_t> index;   // particle indices, grouped by block, colour-major, ascending within a block
  std::vector<std::uint32_t> block;   // block b holds index[block[b], block[b+1]) (non-empty blocks only)
  std::array<std::uint32_t, 5> colour{};  // colour c's blocks are [colour[c], colour[c+1])
  std::vector<std::uint32_t> key;     // scratch of the build: block key of each particle
  int width_y = 1, width_z = 1;       // block widths w in node rows
  int blocks_y = 1, blocks_z = 1;     // blocks per direction
  std::size_t displaced = 0;          // particles with index[j] != j (0: the storage is in scatter order)
  int span = 1;                       // widest footprint in node rows over x, y, z (mpm/PatchBand.h's reach)

  bool built_for(std::size_t np) const { return particles == np && index.size() == np && np > 0; }

  // Build, step 1: block widths for footprints of at most span_y x span_z
  // node rows on a grid of ny x nz node rows; key sized to np.
  void prepare(std::size_t np, int ny, int nz, int span_y, int span_z);
  // Step 2 (per particle, any thread): key[i] = block_key(y0, z0), y0 and z0
  // the particle's lowest stencil node rows. Colour-major block numbering.
  std::uint32_t block_key(int y0, int z0) const {
    const int by = y0 / width_y, bz = z0 / width_z;
    const int c = (by & 1) + 2 * (bz & 1);
    return std::uint32_t((c * blocks_z + bz) * blocks_y + by);
  }
  // Step 3: counting sort of the keys (stable: ascending index inside a
  // block) into index / block / colour, and the count `displaced`. O(np + blocks).
  void finish();
  // Inside every block, the particles in ascending id (insertion sort: O(n)
  // when the storage is nearly in that order already, as after a reorder),
  // and `displaced` again. The scatter order is then (colour, block, id):
  // it depends on the positions and ids only, not on the storage order, so
  // one process and any number of MPI ranks visit each patch's particles in
  // the same order (mpm/PatchBand.h). Still the same for any thread count.
  void sort_blocks_by_id(const long long* id);
  // The threaded scatter's split of colour c among T threads (for_each_scatter_particle):
  // thread u runs the slots [run_start(c, u, T), run_start(c, u + 1, T)) of
  // `index`, whole blocks. For 0 < u < T the start is the block start nearest
  // to the u/T point of the colour's particles, p0 + floor(n u / T) (a tie
  // takes the lower start); u = 0 and u = T are the colour's ends. The
  // targets grow with u, so the starts do: the runs tile the colour, each
  // block in exactly one run, and each run holds n/T particles up to half a
  // block at either end (the nearest start is at most half a block from its
  // target). The first start at or after the target (session 15's rule) gave
  // thread 0 up to a whole block more: 4.2 % over the even split in the sum
  // of the colours' longer runs on spheres.ups with GIMP (blocks of up to
  // 1,536 particles in colours of ~29,000), 2.5 % with the nearest start.
  std::uint32_t run_start(int c, int u, int T) const;
};

}  // namespace tephra

#ifdef _OPENMP
#include <omp.h>
#endif

namespace tephra {

// Calls body(i) for every particle i < np in the scatter order of `o`
// (ScatterOrder.h: colour by colour, the blocks of a colour split among the
// threads). Without an order built for np particles: a serial loop in
// particle order. Below min_parallel particles or with one thread: the same
// order, serially.
template <class Body>
void for_each_scatter_particle(const ScatterOrder& o, std::size_t np, Body&& body,
                               std::size_t min_parallel = 4096) {
  if (!o.built_for(np)) {
    for (std::size_t i = 0; i < np; ++i) body(i);
    return;
  }
  const std::uint32_t* index = o.index.data();
  int threads = 1;
#ifdef _OPENMP
  threads = np >= min_parallel ? omp_get_max_threads() : 1;
#endif
  // Columns stored in scatter order (mpm/ParticleReorder.h): index[j] == j,
  // the same visits without reading the index list.
  const bool in_order = o.displaced == 0;
  if (threads == 1) {
    if (in_order)
      for (std::size_t j = 0; j < np; ++j) body(j);
    else
      for (std::size_t j = 0; j < np; ++j) body(std::size_t(index[j]));
    return;
  }
  // Thread t takes a contiguous run of each colour's blocks holding about
  // 1/T of that colour's particles (split at block boundaries). The blocks
  // are numbered bz-major inside a colour, so a run is a slab in z, and
  // roughly the same slab in every colour: each thread keeps writing the node
  // rows it wrote in the previous colour (they stay in its core's cache). A
  // dynamic schedule handed neighbouring blocks to different threads, so the
  // node rows shared by the blocks of consecutive colours moved between the
  // cores at every colour. Which thread runs a block does not change the bits.
#pragma omp parallel num_threads(threads)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    for (int c = 0; c < 4; ++c) {
      // Whole blocks, about 1/T of the colour's particles (ScatterOrder::run_start).
      const std::uint32_t j0 = o.run_start(c, t, threads), j1 = o.run_start(c, t + 1, threads);
      if (in_order) {
        for (std::uint32_t j = j0; j < j1; ++j) body(std::size_t(j));
      } else {
        for (std::uint32_t j = j0; j < j1; ++j) body(std::size_t(index[j]));
      }
      // Colour c is complete before c + 1 starts.
#pragma omp barrier
    }
  }
}

}  // namespace tephra
