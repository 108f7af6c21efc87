#pragma once
// Per-rank checkpoints (issue 7 item 4, session 27). Under mpirun every rank
// writes its own part of the restart state and rank 0 writes a manifest last:
//   checkpoints/c<step>.r<rank>.h5   one per rank:
//     /          attrs format "tephra-checkpoint-rank-1", step, rank, ranks
//     /doubles/<name>, /ints/<name>  this rank's values (Fletcher-32), with
//                attrs part = "runs" (+ whole_size) or "rows" (+ key, width)
//                for a distributed array (ArchivePart, core/io/StateArchive.h);
//                arrays without the attr are whole (rank 0's file only)
//     /runs/<name>  the (offset, length) runs of a "runs" array, i64 [n][2]
//   checkpoints/c<step>.h5           the manifest: attrs format
//                "tephra-checkpoint-manifest-1", step, ranks; dataset
//                rank_file_bytes (i64, one per rank): written by rank 0 after
//                every rank file is renamed in place, so a checkpoint whose
//                manifest exists is complete, and a rank file truncated or
//                replaced later is detected by its size.
// Reading merges the rank files into the archive the one-file checkpoint of
// the same state holds (runs placed, rows put in ascending key), so a restart
// on any rank count goes through the same load_state.
#include <string>
#include <utility>

#include "core/io/StateArchive.h"

namespace tephra {

extern const char* const kCheckpointManifestFormat;  // "tephra-checkpoint-manifest-1"

// "c00010.r3.h5"; parse gives {10, 3}, or {-1, -1} for any other name.
std::string rank_checkpoint_file_name(int step, int rank);
std::pair<int, int> parse_rank_checkpoint_file_name(const std::string& name);

// This rank's part of `a` to `path` (the caller adds tmp+rename).
void write_rank_checkpoint_file(const std::string& path, int step, const StateArchive& a, int rank, int ranks);

// The manifest at `path` for the rank files in `dir` (the caller adds
// tmp+rename). Throws RuntimeFailure naming a rank file that is missing or
// not this checkpoint's.
void write_checkpoint_manifest(const std::string& path, const std::string& dir, int step, int ranks);

// The merged archive of the manifest at `path` (rank files beside it).
// RuntimeFailure naming the rank file that is missing, truncated or
// inconsistent.
StateArchive read_checkpoint_manifest(const std::string& path);

}  // namespace tephra
