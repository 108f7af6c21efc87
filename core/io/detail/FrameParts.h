#pragma once
// Pieces of the frame file format (core/io/FrameFile.cpp) shared with the
// per-rank frame files (core/io/RankFrameFile.cpp). Private to core/io: it
// includes hdf5.h through detail/H5.h.
#include <string>
#include <vector>

#include "core/io/FrameFile.h"
#include "core/io/detail/H5.h"

namespace tephra::frame_detail {

long long product(const IntVec3& n);
void check_label(const std::string& label, const std::string& what);
void check_components(const FieldArray& f);
// The stored extent of a whole-level grid array from its size (interior, or
// interior plus extra cells); std::invalid_argument when it fits neither.
SavedGridField locate(const GridFieldArray& g, const Grid& grid);
std::vector<long long> to_i64(const IntVec3& v);
IntVec3 to_ivec(const std::vector<long long>& v, const std::string& where);
std::string mat_group(int m);
int parse_mat_group(const std::string& name, const std::string& where);
int components_from(const std::vector<hsize_t>& dims, size_t scalar_rank);
GridLocation parse_location(const std::string& centering, const std::string& where);
// /grid with the geometry attributes (returned open), and its reader.
h5::Handle write_grid_geometry(hid_t file, const Grid& grid, const std::string& path);
void read_grid_geometry(hid_t grid_group, Grid& grid, const std::string& path);
// /particles/mat<M>/... as in the single frame file.
void write_particles(hid_t file, const OutputFrame& frame, const std::string& path);
void read_particles(hid_t file, SavedFrame& out, bool with_values, const std::string& only,
                    const std::string& path);

}  // namespace tephra::frame_detail
