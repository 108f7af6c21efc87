// Step redo with dt/2 (core/sim/StepRedo.h).
#include "core/sim/StepRedo.h"

#include <sstream>

#include "core/base/Errors.h"
#include "core/base/Log.h"

namespace tephra {

void advance_with_redo(StepRedo& r, double t, double dt, int step, int depth) {
  const std::function<void()> restore = r.snapshot();
  try {
    r.attempt(t, dt);
    return;
  } catch (const StepRedoRequest& q) {
    std::ostringstream os;
    os.precision(6);
    if (depth >= kMaxStepHalvings) {
      os << r.who << " step " << step << " at t = " << t << " s, dt = " << dt << " s: " << q.why << "; still failing after "
         << depth << " halvings of the time step (the limit)";
      throw NumericalFailure(os.str());
    }
    os << r.who << " step " << step << " at t = " << t << " s: " << q.why << "; redoing it as two steps of dt/2 = "
       << 0.5 * dt << " s";
    log::warning(os.str());
  }
  restore();
  ++r.redos;
  advance_with_redo(r, t, 0.5 * dt, step, depth + 1);
  advance_with_redo(r, t + 0.5 * dt, 0.5 * dt, step, depth + 1);
}

}  // namespace tephra
