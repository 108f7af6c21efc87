#pragma once
// Per-rank frame files (issue 7 item 4, session 25). Under mpirun every rank
// writes what it owns of a frame, and rank 0 writes a small index last:
//   frames/t<step>.r<rank>.h5   one per rank (rank in decimal):
//     /                      attrs: format "tephra-frame-rank-1", time, step, rank, ranks
//     /grid                  attrs as in the single frame file (lower, dx, cells, extra_cells)
//     /grid/mat<M>/<label>   a GROUP per field with attrs centering, first_index[3] and
//                            extent[3] of the WHOLE field (as the single file would store
//                            it), components; its datasets b0, b1, ... are this rank's
//                            pieces, [nk][nj][ni] or [nk][nj][ni][ncomp], each with attr
//                            offset[3] (i64): its first entry's offset in the whole field
//     /particles/mat<M>/...  this rank's particles, in ascending particle id, as in the
//                            single frame file
//   frames/t<step>.h5         the index: attrs format "tephra-frame-index-1", time, step,
//                            ranks. Written by rank 0 after every rank file is renamed in
//                            place, so a frame whose index exists is complete.
// Every entry of a grid field is in the pieces of at most one rank; an entry in
// none reads as 0 (GridFieldArray::pieces). Reading merges the ranks: grid
// fields assembled from the pieces, particles concatenated and put in
// ascending id -- the SavedFrame of the single file of the same state.
#include <string>
#include <utility>
#include <vector>

#include "core/io/FrameFile.h"

namespace tephra {

extern const char* const kFrameIndexFormat;  // "tephra-frame-index-1"

// "t00010.r3.h5".
std::string rank_frame_file_name(int step, int rank);
// Parses "t00010.r3.h5" -> {10, 3}; {-1, -1} for any other name.
std::pair<int, int> parse_rank_frame_file_name(const std::string& name);

// Writes this rank's part of `frame` to `path` (OutputWriter adds tmp+rename).
// Grid fields with `partial` set write their pieces; the others are whole
// arrays that every rank holds, written by rank 0 alone.
void write_rank_frame_file(const std::string& path, const OutputFrame& frame, int rank, int ranks);

// True when `path` is a frame index (false for a single frame file).
bool is_frame_index_file(const std::string& path);

// The index (attributes only).
void write_frame_index_file(const std::string& path, int step, double time, int ranks);

// The rank files of an index, in rank order (same folder). A missing or
// unreadable rank file throws RuntimeFailure naming it and the index.
std::vector<std::string> rank_files_of_index(const std::string& index_path);

// One rank file as it is: grid_fields are its pieces (dataset set, first_index
// and extent those of the piece), particles its own. Layout only (no values).
SavedFrame read_rank_file_layout(const std::string& path);

// The merged frame of an index (read_frame_file calls this).
SavedFrame read_rank_frames(const std::string& index_path, bool with_values, const std::string& only_label);

}  // namespace tephra
