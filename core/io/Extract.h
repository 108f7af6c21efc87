#pragma once
// `tephra extract`: prints a saved field as CSV with a header.
//   cell/node variables:  time,i,j,k,x,y,z,<values>
//   particle variables:   time,particle_id,x,y,z,<values>
//   reductions (.dat):    time,<values>
// A scalar is one column LABEL, a vector LABEL_x,LABEL_y,LABEL_z, a tensor
// LABEL_xx,LABEL_xy,...,LABEL_zz.
#include <optional>
#include <ostream>
#include <string>

namespace tephra {

struct ExtractRequest {
  std::string dir;                  // output directory of a run
  std::string label;                // e.g. "p.stress", "press_CC", "KineticEnergy"
  std::optional<int> material;      // default: every material
  enum class When { Last, Step, Time, AllTimes } when = When::Last;
  int step = 0;                     // for When::Step
  double time = 0.0;                // for When::Time (nearest saved time)
};

// Writes the CSV to `out`. Throws UsageError (exit 2) for an unknown label
// or step, RuntimeFailure for unreadable files.
void extract_csv(const ExtractRequest& request, std::ostream& out);

}  // namespace tephra
