// The time loop against a component with an exact solution: y' = -k y, advanced
// with the exact propagator y(t+dt) = y(t) exp(-k dt), so every saved value is
// known in closed form. Checks dt control, output times, end conditions,
// delt_min failure, and that a restart reproduces the .dat files byte for byte.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/Errors.h"
#include "core/io/OutputWriter.h"
#include "core/sim/TimeLoop.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

class DecayComponent : public Component {
 public:
  double k = 2.0;            // decay rate [1/s]
  double y = 1.0;            // state
  double stable = 0.01;      // reported stable step [s]
  std::string name() const override { return "decay"; }
  void initialize() override { y = 1.0; }
  double stable_timestep() const override { return stable; }
  void advance(double, double dt, int step) override {
    y *= std::exp(-k * dt);
    if (!std::isfinite(y)) throw NumericalFailure("step " + std::to_string(step) + ": y is not finite");
  }
  void fill_output(const std::set<std::string>&, OutputFrame&) const override {}
  std::map<std::string, std::vector<double>> reductions(const std::set<std::string>& labels) const override {
    std::map<std::string, std::vector<double>> out;
    if (labels.count("TotalMass")) out["TotalMass"] = {y};
    return out;
  }
  std::set<std::string> known_labels() const override { return {"TotalMass"}; }
  void save_state(StateArchive& a) const override { a.put_scalar("decay.y", y); }
  void load_state(const StateArchive& a) override { y = a.scalar("decay.y"); }
};

TimeParameters time_params(double max_time) {
  TimeParameters t;
  t.max_time = max_time;
  t.delt_min = 1e-9;
  t.delt_max = 1.0;
  t.timestep_multiplier = 0.5;
  return t;
}

ArchiverParameters archiver(double interval) {
  ArchiverParameters a;
  a.filebase = "unused";
  a.output_interval = interval;
  a.saves.push_back({"TotalMass", std::nullopt});
  a.checkpoint = true;
  a.checkpoint_cycle = 2;
  a.checkpoint_interval = 0.1;
  return a;
}

std::vector<std::pair<double, double>> read_dat(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::pair<double, double>> rows;
  double t, v;
  while (in >> t >> v) rows.push_back({t, v});
  return rows;
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(TimeLoop, StepsWithMultiplierAndWritesExactValuesAtOutputTimes) {
  DecayComponent c;
  RunOptions o;
  o.output_dir = test::scratch_dir("timeloop_basic");
  o.show_progress = false;
  TimeLoop loop(c, time_params(0.5), archiver(0.1), o);
  loop.run("<Uintah_specification/>");
  // dt = 0.5 * 0.01 = 0.005; the loop runs until t >= 0.5: 100 steps.
  EXPECT_EQ(loop.state().step, 100);
  EXPECT_NEAR(loop.state().time, 0.5, 1e-12);
  auto rows = read_dat(o.output_dir + "/TotalMass.dat");
  // Output at t = 0 and at the first step reaching each multiple of 0.1.
  ASSERT_EQ(rows.size(), 6u);
  for (const auto& [t, v] : rows) EXPECT_NEAR(v, std::exp(-2.0 * t), 1e-14) << "t = " << t;
  EXPECT_EQ(rows.front().first, 0.0);
}

TEST(TimeLoop, EndsExactlyAtMaxTimeWhenAsked) {
  DecayComponent c;
  c.stable = 0.03;  // dt = 0.015: 0.1 is not a multiple
  RunOptions o;
  o.output_dir = test::scratch_dir("timeloop_exact");
  o.show_progress = false;
  TimeParameters t = time_params(0.1);
  t.end_exactly = true;
  TimeLoop loop(c, t, archiver(0.05), o);
  loop.run("<Uintah_specification/>");
  EXPECT_EQ(loop.state().time, 0.1);
  EXPECT_NEAR(c.y, std::exp(-0.2), 1e-15);
}

TEST(TimeLoop, StepBelowDeltMinStopsWithExit4) {
  DecayComponent c;
  c.stable = 1e-6;
  RunOptions o;
  o.output_dir = test::scratch_dir("timeloop_deltmin");
  o.show_progress = false;
  TimeParameters t = time_params(0.1);
  t.delt_min = 1e-3;
  TimeLoop loop(c, t, archiver(0.05), o);
  try {
    loop.run("<Uintah_specification/>");
    FAIL() << "expected NumericalFailure";
  } catch (const NumericalFailure& e) {
    EXPECT_EQ(e.code(), ExitCode::NumericalFailure);
    EXPECT_NE(std::string(e.what()).find("delt_min"), std::string::npos);
  }
}

TEST(TimeLoop, MaxStepsOverrideStops) {
  DecayComponent c;
  RunOptions o;
  o.output_dir = test::scratch_dir("timeloop_maxsteps");
  o.show_progress = false;
  o.max_steps = 7;
  TimeLoop loop(c, time_params(0.5), archiver(0.1), o);
  loop.run("<Uintah_specification/>");
  EXPECT_EQ(loop.state().step, 7);
}

TEST(TimeLoop, RestartReproducesDatFilesByteForByte) {
  // Uninterrupted run.
  RunOptions full;
  full.output_dir = test::scratch_dir("timeloop_full");
  full.show_progress = false;
  {
    DecayComponent c;
    c.stable = 0.0123;  // an awkward dt so that times are not round numbers
    TimeLoop loop(c, time_params(0.5), archiver(0.05), full);
    loop.run("<Uintah_specification/>");
  }
  // Interrupted run: stop at step 30, then restart from its newest checkpoint.
  RunOptions part;
  part.output_dir = test::scratch_dir("timeloop_part");
  part.show_progress = false;
  part.max_steps = 30;
  {
    DecayComponent c;
    c.stable = 0.0123;
    TimeLoop loop(c, time_params(0.5), archiver(0.05), part);
    loop.run("<Uintah_specification/>");
  }
  CheckpointStore store(part.output_dir, 2);
  ASSERT_FALSE(store.steps().empty());
  EXPECT_LT(store.steps().back(), 30);  // the restart really re-runs steps
  part.max_steps.reset();
  {
    DecayComponent c;
    c.stable = 0.0123;
    c.y = -1.0;  // garbage: the restart must overwrite it
    TimeLoop loop(c, time_params(0.5), archiver(0.05), part);
    loop.restart(-1);
  }
  std::string a = slurp(full.output_dir + "/TotalMass.dat");
  std::string b = slurp(part.output_dir + "/TotalMass.dat");
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, b);
}
