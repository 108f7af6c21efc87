#pragma once
// Redo of a time step with dt/2 (Uintah's "recompute time step": a task that
// cannot finish the step asks the controller to discard it and run it again
// with a smaller delT; ICE::recomputeDelT gives 0.75 delT, MPMICE's gives
// delT/2). In Tephra the time loop owns dt, so the component covers the same
// interval [t, t + dt] with two steps of dt/2, each of which may be redone in
// turn. One mechanism for ICE and MPMICE (docs/algorithms/ice.md "Step redo").
#include <functional>
#include <string>

namespace tephra {

// Thrown by a phase of a step that cannot be completed with this dt (an
// implicit pressure solve that does not converge, a non-positive Lagrangian
// specific volume). `why` names the cause and the cell.
struct StepRedoRequest {
  std::string why;
};

// At most this many halvings of one step (dt / 16); a request at the deepest
// level is a NumericalFailure (exit 4) naming the step and the why.
constexpr int kMaxStepHalvings = 4;

struct StepRedo {
  // Saves the state a failed attempt must put back; returns the restore.
  std::function<std::function<void()>()> snapshot;
  // One attempt at [t, t + dt]; may throw StepRedoRequest.
  std::function<void(double t, double dt)> attempt;
  std::string who;  // "ICE", "MPMICE": names the component in messages
  int redos = 0;    // steps redone so far (each redo counts once)
};

// Advances [t, t + dt] of step `step` with attempt(); on a StepRedoRequest
// restores the snapshot and runs two halves, recursively (depth = halvings
// so far). Every redo is logged as a warning with the why and the new dt.
void advance_with_redo(StepRedo& r, double t, double dt, int step, int depth = 0);

}  // namespace tephra
