#pragma once
// One output frame as an HDF5 file (frames/t<step>.h5), and its reader.
//
// Layout (dataset shapes are row-major, the last index fastest):
//   /                      attrs: time (f64), step (i64), format "tephra-frame-1"
//   /grid                  attrs: lower[3], dx[3] (f64), cells[3], extra_cells[3] (i64)
//   /grid/mat<M>/<label>   [nk][nj][ni] or [nk][nj][ni][ncomp], i fastest;
//                          attrs: centering "Cell"|"Node"|"FaceX|Y|Z", first_index[3] (i64):
//                          the (i,j,k) of element [0][0][0] (0, or -extra_cells
//                          when the field includes the extra cells)
//   /particles/mat<M>/position    [n][3] f64
//   /particles/mat<M>/particleID  [n] i64
//   /particles/mat<M>/<label>     [n] or [n][ncomp] f64
// ncomp is 3 (vector) or 9 (tensor, row-major xx,xy,xz,yx,...,zz).
// The grid geometry is stored so that extract can print positions without
// the deck.
#include <map>
#include <string>
#include <vector>

#include "core/io/OutputFrame.h"

namespace tephra {

struct SavedGridField {
  GridFieldArray field;                        // values empty for a layout-only read
  IntVec3 first_index = IntVec3::Zero();       // (i,j,k) of the first stored element
  IntVec3 extent = IntVec3::Zero();            // stored elements per direction
  std::string dataset;                         // a piece of a rank file: its HDF5 path (else empty)
};

struct SavedParticles {
  ParticleBlock block;                         // position/id/values empty for a layout-only read
  long long count = 0;
};

struct SavedFrame {
  int step = 0;
  double time = 0.0;
  bool has_grid = false;
  Grid grid;                                   // lower, upper, dx, cells, extra_cells
  std::vector<SavedGridField> grid_fields;     // sorted by (material, label)
  std::vector<SavedParticles> particles;       // sorted by material; fields by label
};

// "t00010.h5": the step zero-padded to at least five digits.
std::string frame_file_name(int step);

// Parses "t00010.h5" -> 10; -1 for any other name (tmp files, foreign files).
int parse_frame_file_name(const std::string& name);

// The frame files of an output directory (dir/frames/t*.h5), by step.
std::map<int, std::string> list_frame_files(const std::string& output_dir);

// Writes `frame` to `path` directly (OutputWriter adds the tmp+rename).
// Throws std::invalid_argument for an inconsistent frame (array sizes that
// match neither the interior nor the interior+extra cells, components not in
// {1,3,9}, a label with '/'), RuntimeFailure for I/O failures.
void write_frame_file(const std::string& path, const OutputFrame& frame);

// Reads a frame file back. A multi-rank frame (its t<step>.h5 is the small
// index of core/io/RankFrameFile.h) is read from its rank files and merged:
// the same SavedFrame as the single file of the same state, bit for bit. With `with_values` false only names, shapes and
// geometry are read (for the XDMF index). With `only_label` set, values are
// read only for fields of that label (and positions and ids only for the
// particle sets that hold it). RuntimeFailure names the file.
SavedFrame read_frame_file(const std::string& path, bool with_values = true,
                           const std::string& only_label = "");

}  // namespace tephra
