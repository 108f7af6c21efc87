#pragma once
// A simulation component (MPM, ICE, MPMICE) as the time loop sees it. The
// loop owns time, output and checkpoints; the component owns its state and
// physics. Virtual dispatch happens per step, never per particle or cell.
#include <map>
#include <set>
#include <string>
#include <vector>

#include "core/io/OutputFrame.h"
#include "core/io/StateArchive.h"

namespace tephra {

class Component {
 public:
  virtual ~Component() = default;
  virtual std::string name() const = 0;

  // Sets the state at initTime.
  virtual void initialize() = 0;

  // The largest stable time step of the current state (before the deck's
  // timestep_multiplier, which the loop applies).
  virtual double stable_timestep() const = 0;

  // Advances the state from t to t + dt. Throws NumericalFailure (exit 4)
  // naming the step, field and particle or cell when a value goes bad.
  virtual void advance(double t, double dt, int step) = 0;

  // Fills `frame` with the saved labels this component owns.
  virtual void fill_output(const std::set<std::string>& labels, OutputFrame& frame) const = 0;

  // Values of the reduction labels this component owns: scalar (1) or
  // vector (3) values keyed by label (e.g. "KineticEnergy", "TotalMomentum").
  virtual std::map<std::string, std::vector<double>> reductions(
      const std::set<std::string>& labels) const = 0;

  // Every label this component can save (validates <save label=...>).
  virtual std::set<std::string> known_labels() const = 0;

  // Restartable state.
  virtual void save_state(StateArchive& archive) const = 0;
  virtual void load_state(const StateArchive& archive) = 0;
};

}  // namespace tephra
