#include "core/sim/TimeLoop.h"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "core/base/Errors.h"
#include "core/base/Log.h"
#include "core/base/PhaseTimers.h"
#include "core/io/OutputWriter.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"

namespace tephra {

namespace {

double wall_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

}  // namespace

TimeLoop::TimeLoop(Component& c, TimeParameters t, ArchiverParameters a, RunOptions o)
    : component_(c), time_(std::move(t)), archiver_(std::move(a)), options_(std::move(o)) {}

TimeLoop::~TimeLoop() = default;

// The end of the run: maxTime (or --end-time if earlier) and max_timesteps
// (or --max-steps if fewer).
bool TimeLoop::finished() const {
  double end = time_.max_time;
  if (options_.end_time) end = std::min(end, *options_.end_time);
  if (state_.time >= end) return true;
  long long max_steps = time_.max_timesteps;
  if (options_.max_steps && (max_steps < 0 || *options_.max_steps < max_steps)) max_steps = *options_.max_steps;
  return max_steps >= 0 && state_.step >= max_steps;
}

// dt = timestep_multiplier * (component's stable step), limited by
// max_delt_increase and delt_max, and cut to land on the end time when the
// deck asks for end_on_max_time_exactly. Below delt_min the run stops (exit 4).
double TimeLoop::next_timestep() const {
  double dt;
  if (state_.step == 0 && time_.delt_init) {
    dt = *time_.delt_init;
  } else {
    PhaseTimers::Scope scope(phase_timers(), "stable time step");
    double stable = component_.stable_timestep();
    if (!std::isfinite(stable) || stable <= 0.0)
      throw NumericalFailure("step " + std::to_string(state_.step + 1) + ", t = " + fmt(state_.time) +
                             ": the stable time step of " + component_.name() + " is " + fmt(stable));
    dt = time_.timestep_multiplier * stable;
  }
  if (time_.max_delt_increase && state_.step > 0)
    dt = std::min(dt, (1.0 + *time_.max_delt_increase) * state_.previous_dt);
  dt = std::min(dt, time_.delt_max);
  if (dt < time_.delt_min)
    throw NumericalFailure("step " + std::to_string(state_.step + 1) + ", t = " + fmt(state_.time) +
                           ": time step " + fmt(dt) + " is below delt_min = " + fmt(time_.delt_min));
  double end = time_.max_time;
  if (options_.end_time) end = std::min(end, *options_.end_time);
  if ((time_.end_exactly || options_.end_time) && state_.time + dt > end) dt = end - state_.time;
  return dt;
}

// Output times: init + k*outputInterval (k counted, not accumulated, so a
// restart lands on the same times), or every outputTimestepInterval steps.
bool TimeLoop::output_due() const {
  if (archiver_.output_timestep_interval)
    return state_.step % *archiver_.output_timestep_interval == 0;
  if (archiver_.output_interval)
    return state_.time >= time_.init_time + state_.outputs_done * *archiver_.output_interval;
  return false;
}

bool TimeLoop::checkpoint_due() const {
  if (!archiver_.checkpoint || state_.step == 0) return false;
  if (archiver_.checkpoint_timestep_interval)
    return state_.step % *archiver_.checkpoint_timestep_interval == 0;
  return state_.time >= time_.init_time + state_.checkpoints_done * *archiver_.checkpoint_interval;
}

void TimeLoop::write_output() {
  PhaseTimers::Scope scope(phase_timers(), "output");
  std::set<std::string> labels = archiver_.labels();
  // Every rank computes the reductions (collectives under mpirun); rank 0
  // writes the .dat rows. Frames: write_frame_of_state (one file per rank
  // under mpirun since session 25).
  auto reductions = component_.reductions(labels);
  if (writer_ && !reductions.empty()) writer_->append_reductions(state_.time, reductions);
  write_frame_of_state(static_cast<int>(state_.step), labels);
  last_output_step_ = state_.step;
  if (archiver_.output_interval) {
    // Advance to the first output time after now.
    while (time_.init_time + state_.outputs_done * *archiver_.output_interval <= state_.time)
      ++state_.outputs_done;
  }
}

// The frame of the current state. One rank: frames/t<step>.h5 as always.
// Under mpirun (session 25, core/io/RankFrameFile.h) the component's gathers
// keep each rank's own part (OutputPerRank, core/parallel/OutputGather.h):
// every rank writes frames/t<step>.r<rank>.h5, and after a barrier rank 0
// writes the index frames/t<step>.h5 and the XDMF entry. Rank 0 receives no
// frame data.
void TimeLoop::write_frame_of_state(int step, const std::set<std::string>& labels) {
  OutputFrame frame;
  frame.step = step;
  frame.time = state_.time;
  const Ranks ranks = world_ranks();
  if (ranks.size == 1) {
    component_.fill_output(labels, frame);
    if (writer_) writer_->write_frame(frame);
    return;
  }
  {
    OutputPerRank per_rank;
    component_.fill_output(labels, frame);
  }
  write_rank_frame(options_.output_dir, frame, ranks.rank, ranks.size);
  barrier();  // every rank file is in place before the index names it
  if (writer_) writer_->write_frame_index(step, state_.time, ranks.size);
}

void TimeLoop::write_checkpoint() {
  PhaseTimers::Scope scope(phase_timers(), "checkpoint");
  if (archiver_.checkpoint_interval) {
    while (time_.init_time + state_.checkpoints_done * *archiver_.checkpoint_interval <= state_.time)
      ++state_.checkpoints_done;
  }
  // One rank: checkpoints/c<step>.h5 as always. Under mpirun (session 27,
  // core/io/RankCheckpoint.h) the component's gathers keep each rank's own
  // part (OutputPerRank) and mark it (ArchivePart): every rank writes
  // c<step>.r<rank>.h5, and after a barrier rank 0 writes the manifest
  // c<step>.h5. Rank 0 receives no checkpoint data.
  const Ranks ranks = world_ranks();
  StateArchive archive;
  if (ranks.size == 1) {
    component_.save_state(archive);
  } else {
    OutputPerRank per_rank;
    component_.save_state(archive);
  }
  archive.put_scalar("timeloop.time", state_.time);
  archive.put_int("timeloop.step", state_.step);
  archive.put_scalar("timeloop.previous_dt", state_.previous_dt);
  archive.put_int("timeloop.outputs_done", state_.outputs_done);
  archive.put_int("timeloop.checkpoints_done", state_.checkpoints_done);
  const int step = static_cast<int>(state_.step);
  if (ranks.size == 1) {
    if (writer_) CheckpointStore(options_.output_dir, archiver_.checkpoint_cycle).write(step, archive);
    return;
  }
  CheckpointStore store(options_.output_dir, archiver_.checkpoint_cycle);
  store.write_rank_part(step, archive, ranks.rank, ranks.size);
  barrier();  // every rank file is in place before the manifest names it
  if (writer_) store.write_manifest(step, ranks.size);
}

void TimeLoop::run(const std::string& resolved_deck_xml) {
  wall_start_ = wall_seconds();
  if (world_ranks().is_root()) {  // under mpirun rank 0 writes the output of all ranks
    writer_ = std::make_unique<OutputWriter>(options_.output_dir, false);
    writer_->write_deck_copy(resolved_deck_xml);
  }
  barrier();  // the output directory exists before any rank reads or writes in it
  {
    PhaseTimers::Scope scope(phase_timers(), "initialize");
    component_.initialize();
  }
  state_ = LoopState{};
  state_.time = time_.init_time;
  if (archiver_.output_interval) state_.outputs_done = 0;
  if (archiver_.checkpoint_interval) state_.checkpoints_done = 1;  // first checkpoint after one interval
  write_output();  // the initial state, as Vaango writes timestep 0
  step_until_end();
}

void TimeLoop::restart(int checkpoint_step) {
  wall_start_ = wall_seconds();
  CheckpointStore store(options_.output_dir, archiver_.checkpoint_cycle);
  std::vector<int> steps = store.steps();
  if (steps.empty()) throw UsageError("no checkpoints in " + options_.output_dir + "/checkpoints");
  int chosen = checkpoint_step < 0 ? steps.back() : checkpoint_step;
  if (std::find(steps.begin(), steps.end(), chosen) == steps.end()) {
    std::ostringstream s;
    s << "no checkpoint at step " << chosen << " in " << options_.output_dir << "; available:";
    for (int st : steps) s << " " << st;
    throw UsageError(s.str());
  }
  StateArchive archive = store.read(chosen);
  {
    PhaseTimers::Scope scope(phase_timers(), "restore checkpoint");
    component_.load_state(archive);
  }
  state_.time = archive.scalar("timeloop.time");
  state_.step = archive.integer("timeloop.step");
  state_.previous_dt = archive.scalar("timeloop.previous_dt");
  state_.outputs_done = archive.integer("timeloop.outputs_done");
  state_.checkpoints_done = archive.integer("timeloop.checkpoints_done");
  barrier();  // every rank has read the checkpoint before rank 0 truncates the output after it
  if (world_ranks().is_root()) {
    writer_ = std::make_unique<OutputWriter>(options_.output_dir, true);
    writer_->truncate_after(static_cast<int>(state_.step), state_.time);
  }
  log::info("restarting from checkpoint at step " + std::to_string(state_.step) + ", t = " + fmt(state_.time));
  step_until_end();
}

void TimeLoop::step_until_end() {
  try {
    while (!finished()) {
      double dt = next_timestep();
      {
        PhaseTimers::Scope scope(phase_timers(), component_.name() + ": advance");
        component_.advance(state_.time, dt, static_cast<int>(state_.step + 1));
      }
      state_.time += dt;
      state_.step += 1;
      state_.previous_dt = dt;
      if (output_due()) write_output();
      if (checkpoint_due()) write_checkpoint();
      show_progress(false);
    }
  } catch (const NumericalFailure&) {
    // Write what there is, so the failure can be looked at, then stop (exit 4).
    show_progress(true);
    if (last_output_step_ != state_.step) {
      try {
        const int step = static_cast<int>(state_.step + 1);
        write_frame_of_state(step, archiver_.labels());
        log::warning("wrote the last state to " + options_.output_dir + " (frame " + std::to_string(step) + ")");
      } catch (const std::exception& e) {
        log::warning(std::string("could not write the last state: ") + e.what());
      }
    }
    throw;
  }
  show_progress(true);
}

void TimeLoop::show_progress(bool force) {
  if (!options_.show_progress || log::quiet() || !isatty(STDERR_FILENO)) return;
  double now = wall_seconds();
  if (!force && now - last_progress_ < 0.25) return;
  last_progress_ = now;
  double end = time_.max_time;
  if (options_.end_time) end = std::min(end, *options_.end_time);
  double wall = now - wall_start_;
  double frac = (state_.time - time_.init_time) / (end - time_.init_time);
  double left = frac > 1e-12 ? wall * (1.0 - frac) / frac : 0.0;
  std::fprintf(stderr, "\r  t = %-12.6g step %-8lld dt %-11.4g wall %8.1f s  left ~%8.1f s ",
               state_.time, state_.step, state_.previous_dt, wall, left);
  if (force) std::fprintf(stderr, "\n");
  std::fflush(stderr);
}

}  // namespace tephra
