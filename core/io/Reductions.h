#pragma once
// Reduction files <Label>.dat: one "time v1 [v2 v3]" row per output time,
// numbers printed with %.17g, which round-trips every double exactly
// (17 significant digits suffice for IEEE binary64, Goldberg 1991 /
// IEEE 754-2008 sec. 5.12.2). The labels a run has written are listed, one
// per line, in tephra-reductions.txt, so that a fresh run removes only the
// .dat files Tephra wrote and extract can list the saved labels.
#include <string>
#include <vector>

namespace tephra {

struct ReductionRow {
  double time = 0.0;
  std::vector<double> values;
};

inline const char* kReductionManifest = "tephra-reductions.txt";

std::string reduction_file(const std::string& dir, const std::string& label);  // dir/<label>.dat
std::string format_reduction_row(double time, const std::vector<double>& values);

// Parses every complete row; RuntimeFailure naming file:line on a malformed row.
std::vector<ReductionRow> read_reduction_file(const std::string& path);

// Labels listed in the manifest of `dir` (empty if there is none).
std::vector<std::string> read_reduction_labels(const std::string& dir);

}  // namespace tephra
