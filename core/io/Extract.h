#pragma once
// `tephra extract`: prints a saved field as CSV with a header.
//   cell/node variables:  time,i,j,k,x,y,z,<values>
//   particle variables:   time,particle_id,x,y,z,<values>
//   reductions (.dat):    time,<values>
// A scalar is one column LABEL, a vector LABEL_x,LABEL_y,LABEL_z, a tensor
// LABEL_xx,LABEL_xy,...,LABEL_zz.
// Where, as Uintah users do with lineextract and puda:
//   at a point   grid labels: the one cell (or node) that holds the point
//                (nearest node for node labels); particle labels: the particle
//                nearest the point in each selected frame;
//   along a line grid labels: every cell (node) the segment passes through,
//                in order from its start; particle labels: the particles within
//                half a cell of the segment, ordered along it.
#include <optional>
#include <ostream>
#include <string>

#include "core/base/Types.h"

namespace tephra {

struct ExtractRequest {
  std::string dir;                  // output directory of a run
  std::string label;                // e.g. "p.stress", "press_CC", "KineticEnergy"
  std::optional<int> material;      // default: every material
  enum class When { Last, Step, Time, AllTimes } when = When::Last;
  int step = 0;                     // for When::Step
  double time = 0.0;                // for When::Time (nearest saved time)
  std::optional<Vec3> point;        // --point x,y,z
  std::optional<std::pair<Vec3, Vec3>> line;  // --line x0,y0,z0,x1,y1,z1
};

// Writes the CSV to `out`. Throws UsageError (exit 2) for an unknown label
// or step, RuntimeFailure for unreadable files.
void extract_csv(const ExtractRequest& request, std::ostream& out);

}  // namespace tephra
