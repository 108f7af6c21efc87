#pragma once
// The time loop: steps a Component from initTime to maxTime (or max_timesteps),
// with the stable time step from the component, writes output frames and
// reduction rows at the deck's output times, checkpoints, and restarts from a
// checkpoint bit for bit. It owns no physics.
#include <memory>
#include <optional>
#include <string>

#include "core/sim/Component.h"
#include "core/sim/RunParameters.h"

namespace tephra {

class OutputWriter;

struct RunOptions {
  std::string output_dir;                 // where everything goes
  std::optional<long long> max_steps;     // --max-steps (overrides the deck's limit when smaller)
  std::optional<double> end_time;         // --end-time (overrides maxTime when smaller)
  bool show_progress = true;              // a progress line on a terminal
};

// The loop's own restartable state.
struct LoopState {
  double time = 0.0;
  long long step = 0;
  double previous_dt = 0.0;
  long long outputs_done = 0;       // output times passed: next at init + (outputs_done)*interval
  long long checkpoints_done = 0;   // likewise for checkpoints
};

class TimeLoop {
 public:
  TimeLoop(Component& component, TimeParameters time, ArchiverParameters archiver, RunOptions options);
  ~TimeLoop();

  // Fresh run: initialize the component, write the deck copy and the initial output, step.
  void run(const std::string& resolved_deck_xml);

  // Continue from checkpoint `checkpoint_step` of options.output_dir (-1: the newest).
  void restart(int checkpoint_step);

  const LoopState& state() const { return state_; }

 private:
  void step_until_end();
  double next_timestep() const;
  bool output_due() const;
  bool checkpoint_due() const;
  void write_frame_of_state(int step, const std::set<std::string>& labels);
  void write_output();
  void write_checkpoint();
  bool finished() const;
  void show_progress(bool force);

  Component& component_;
  TimeParameters time_;
  ArchiverParameters archiver_;
  RunOptions options_;
  LoopState state_;
  std::unique_ptr<OutputWriter> writer_;
  double wall_start_ = 0.0;
  double last_progress_ = -1.0;
  long long last_output_step_ = -1;
};

}  // namespace tephra
