// Frictional contact against Coulomb's law (tests/support/FrictionScenes.h):
// a block sliding on a held slab (mu = 0.3, u0 = 1 m/s, flat) and a block
// released on an incline of theta = 0.3 rad (mu = 0, 0.15, 0.5), for every
// Coulomb contact type and two resolutions. Prints the measured acceleration
// of the block against the closed form. Not a ctest; figures for docs/mpm-contact.md.
//   usage: bench_friction_slide [type ...] [--refine N] [--interp NAME] [--extra N] [--slide-only]
//          [--incline-only] [--mu MU] (one incline mu instead of 0, 0.15, 0.5)
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "tests/support/FrictionScenes.h"

using namespace tephra;

int main(int argc, char** argv) {
  std::vector<std::string> types;
  std::vector<int> refines = {1, 2};
  std::string interp = "linear";
  bool slide_only = false, incline_only = false;
  std::vector<double> mus = {0.0, 0.15, 0.5};
  int extra = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--refine") && i + 1 < argc) refines = {std::atoi(argv[++i])};
    else if (!std::strcmp(argv[i], "--interp") && i + 1 < argc) interp = argv[++i];
    else if (!std::strcmp(argv[i], "--slide-only")) slide_only = true;
    else if (!std::strcmp(argv[i], "--incline-only")) incline_only = true;
    else if (!std::strcmp(argv[i], "--mu") && i + 1 < argc) mus = {std::atof(argv[++i])};
    else if (!std::strcmp(argv[i], "--extra") && i + 1 < argc) extra = std::atoi(argv[++i]);
    else types.push_back(argv[i]);
  }
  if (types.empty()) types = {"friction", "friction_bard", "friction_LR", "approach"};
  const double g = kFrictionSceneG;
  for (const std::string& type : types)
    for (int refine : refines) {
      if (!incline_only) {
      FrictionScene s;
      s.contact = type, s.refine = refine, s.interpolator = interp, s.extra_cells = extra;
      s.mu = 0.3, s.u0 = 1.0, s.heating = true;
      FrictionRun r = run_friction_scene(s);
      const double Q = s.mu * r.mass * g * r.distance;
      std::printf("%-13s h=0.025/%d slide: decel %.5f (mu g %.5f) u(T) %.5f (exact %.5f) heat/(mu M g d) %.5f KE lost/heat %.5f\n",
                  type.c_str(), refine, -r.slope(0.0), s.mu * g, r.u.back(), s.u0 - s.mu * g * s.end_time, r.heat / Q,
                  r.ke_lost / r.heat);
      std::fflush(stdout);
      }
      if (slide_only) continue;
      for (double mu : mus) {
        FrictionScene q;
        q.contact = type, q.refine = refine, q.interpolator = interp, q.extra_cells = extra;
        q.mu = mu, q.theta = 0.3, q.u0 = 0.0;
        FrictionRun ri = run_friction_scene(q);
        const double exact = mu >= std::tan(q.theta) ? 0.0 : g * (std::sin(q.theta) - mu * std::cos(q.theta));
        std::printf("%-13s h=0.025/%d incline mu=%.2f: accel %.5f (exact %.5f) u(T) %.5f (exact %.5f)\n", type.c_str(),
                    refine, mu, ri.slope(0.0), exact, ri.u.back(), exact * q.end_time);
        std::fflush(stdout);
      }
    }
  return 0;
}
