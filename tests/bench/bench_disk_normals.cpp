// Contact normals of a disk (cylinder of radius R = 0.25, one cell thick) in a
// block, body-averaged (collinear) mass-gradient normals, against the exact
// radial direction at the nodes where both bodies have mass. Prints the
// min-mass weighted mean and the largest angle for a sweep of the cell size
// h (fixed particles per cell) and of the particles per cell (fixed h).
//   usage: bench_disk_normals [interpolator]
#include <cmath>
#include <cstdio>
#include <string>

#include "tests/support/DiskNormals.h"

using namespace tephra;

int main(int argc, char** argv) {
  const std::string interp = argc > 1 ? argv[1] : "linear";
  for (int res : {2, 4, 8})
    for (int cells : {24, 48, 96}) {
      if (res * cells > 400) continue;
      const DiskNormalError e = disk_normal_error(cells, res, interp);
      std::printf("%s h = R/%d, %d particles per cell and direction: %d nodes, mean angle %.5f rad, largest %.4f, "
                  "arc-averaged %.5f\n", interp.c_str(), cells / 4, res, e.nodes, e.mean, e.largest, e.arc_mean);
      std::fflush(stdout);
    }
  return 0;
}
