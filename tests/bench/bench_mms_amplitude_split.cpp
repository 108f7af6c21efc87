// The AxisAligned error split by its dependence on the amplitude A
// (docs/mpm-convergence.md, "Session 24"). The discrete solution is a smooth
// function of A, so the end error of each particle is
//   e_p(A) = A e1_p + A^2 e2_p + O(A^3),
// where e1 is the error of the linearised (small-strain) problem and the
// rest comes from the large strain (|F_ii - 1| <= A pi). Two runs on the same
// particles (ids 0..n-1, same seeding), at A and at a small As, give
//   linear part    L_p = (A / As) e_p(As)           = A e1_p + A As e2_p + ...
//   large-strain   N_p = e_p(A) - (A / As) e_p(As)  = A (A - As) e2_p + ...
// (the linear estimate carries As / A of the quadratic part; As = A/20 by
// default: 5 %). Printed: the L2 norms (unweighted particle mean, = the
// V0-weighted one for the uniform seeding) of e(A), L and N per resolution,
// their orders log2(norm_h / norm_{h/2}), and N by region (the band within 2
// cells of a face, the rest).
// Usage: bench_mms_amplitude_split INTERP PPC CELLS [END] [A] [As] [MULT]
//   e.g. bench_mms_amplitude_split gimp 2 8,16,32 0.005 0.05 0.0025
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/MmsRun.h"

namespace {
std::vector<int> split_ints(const std::string& s) {
  std::vector<int> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');) out.push_back(std::atoi(item.c_str()));
  return out;
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 4) {
    std::fprintf(stderr, "usage: %s INTERP PPC CELLS [END] [A] [As] [MULT]\n", argv[0]);
    return 2;
  }
  tephra::test::MmsRunOptions o;
  o.interpolator = argv[1];
  o.particles_per_cell_dir = std::atoi(argv[2]);
  const std::vector<int> cells = split_ints(argv[3]);
  o.end_time = argc > 4 ? std::atof(argv[4]) : 0.005;
  const double A = argc > 5 ? std::atof(argv[5]) : 0.05;
  const double As = argc > 6 ? std::atof(argv[6]) : A / 20;
  o.timestep_multiplier = argc > 7 ? std::atof(argv[7]) : 0.0;
  o.keep_particle_errors = true;
  struct Row {
    int cells;
    double E, L, N, N_band, N_rest, seconds;
  };
  std::vector<Row> rows;
  for (int n : cells) {
    o.cells = n;
    o.amplitude = A;
    const auto big = tephra::test::run_axis_aligned(o);
    o.amplitude = As;
    const auto small = tephra::test::run_axis_aligned(o);
    if (big.particle_errors.size() != small.particle_errors.size()) {
      std::fprintf(stderr, "particle counts differ\n");
      return 1;
    }
    const double s = A / As;
    double e2 = 0, l2 = 0, n2 = 0, nb = 0, nr = 0, cb = 0, cr = 0;
    const std::size_t np = big.particle_errors.size();
    for (std::size_t i = 0; i < np; ++i) {
      const tephra::Vec3 lin = s * small.particle_errors[i];
      const tephra::Vec3 non = big.particle_errors[i] - lin;
      e2 += big.particle_errors[i].squaredNorm(), l2 += lin.squaredNorm(), n2 += non.squaredNorm();
      const tephra::Vec3& X = big.particle_X[i];
      const double dist = std::min(X.minCoeff(), 1.0 - X.maxCoeff()) * n;  // cells to the nearest face
      if (dist < 2) nb += non.squaredNorm(), cb += 1;
      else nr += non.squaredNorm(), cr += 1;
    }
    Row r{n, std::sqrt(e2 / np), std::sqrt(l2 / np), std::sqrt(n2 / np), cb > 0 ? std::sqrt(nb / cb) : 0.0,
          cr > 0 ? std::sqrt(nr / cr) : 0.0, big.seconds + small.seconds};
    rows.push_back(r);
    std::printf("%s ppc %d cells %3d  A %.4g: E %.4e (check %.4e)  As %.4g: %.4e  L %.4e  N %.4e  "
                "N band %.4e rest %.4e  (%ld particles, %d steps, %.1f s)\n",
                o.interpolator.c_str(), o.particles_per_cell_dir, n, A, r.E, big.error, As, small.error, r.L, r.N,
                r.N_band, r.N_rest, big.particles, big.steps, r.seconds);
    std::fflush(stdout);
  }
  for (std::size_t k = 0; k + 1 < rows.size(); ++k)
    std::printf("orders %3d -> %3d: E %.2f  L %.2f  N %.2f  N band %.2f  N rest %.2f\n", rows[k].cells,
                rows[k + 1].cells, std::log2(rows[k].E / rows[k + 1].E), std::log2(rows[k].L / rows[k + 1].L),
                std::log2(rows[k].N / rows[k + 1].N), std::log2(rows[k].N_band / rows[k + 1].N_band),
                std::log2(rows[k].N_rest / rows[k + 1].N_rest));
  return 0;
}
