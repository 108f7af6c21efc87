#pragma once
// The XDMF index (tephra.xdmf) that lets ParaView and VisIt open the HDF5
// frames. Written by hand to the XDMF 3 model (xdmf.org, "XDMF Model and
// Format"): a Temporal collection of per-frame Spatial collections, each
// holding a 3DCoRectMesh for the grid fields and one Polyvertex grid per
// particle material. The heavy data stay in the .h5 files; DataItems point
// at them as "frames/t00010.h5:/grid/mat0/press_CC".
#include <string>
#include <utility>
#include <vector>

#include "core/io/FrameFile.h"

namespace tephra {

// The <Grid CollectionType="Spatial"> element of one frame; `h5_relpath` is
// the frame file relative to the XDMF file ("frames/t00010.h5").
std::string xdmf_frame_grid(const SavedFrame& layout, const std::string& h5_relpath);

// A multi-rank frame (core/io/RankFrameFile.h): one Spatial collection holding
// every rank file's pieces (meshes named r<rank>_grid..., particle grids
// r<rank>_particles_mat<M>), each DataItem pointing into its rank file.
// `ranks[r]` is rank r's read_rank_file_layout and its path relative to the
// XDMF file ("frames/t00010.r1.h5").
std::string xdmf_rank_frame_grid(const std::vector<std::pair<SavedFrame, std::string>>& ranks);

// The complete document around the per-frame elements, in the given order.
std::string xdmf_document(const std::vector<std::string>& frame_grids);

}  // namespace tephra
