#pragma once
// A load curve of <PhysicalBC><MPM> (Vaango's LoadCurve<T>): points
// (t_k, L_k) with t_0 < t_1 < ..., read from
//   <load_curve> <id>1</id> <time_point><time>..</time><load>..</load></time_point> ... </load_curve>
// and evaluated by linear interpolation,
//   L(t) = L_{k-1} s + L_k (1 - s),  s = (t_k - t) / (t_k - t_{k-1}),  t_{k-1} <= t <= t_k,
// held constant after the last point (as Vaango) and before the first one
// (Vaango extrapolates the first segment backwards; a deck's curve starts at
// t = 0, so the difference never shows in a run starting at initTime >= t_0).
#include <vector>

namespace tephra {

class DeckNode;

template <class T>
struct LoadCurve {
  int id = 0;
  std::vector<double> time;
  std::vector<T> load;

  T at(double t) const {
    const std::size_t n = time.size();
    if (t >= time[n - 1]) return load[n - 1];
    if (t <= time[0]) return load[0];
    std::size_t k = 1;
    while (t > time[k]) ++k;
    const double s = (time[k] - t) / (time[k] - time[k - 1]);
    return load[k - 1] * s + load[k] * (1.0 - s);
  }
};

// Reads the <load_curve> child of `parent` (required): an <id> and at least
// one <time_point>, times strictly increasing. DeckError otherwise.
LoadCurve<double> parse_scalar_load_curve(const DeckNode& parent);

}  // namespace tephra
