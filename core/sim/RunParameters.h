#pragma once
// The <Time> and <DataArchiver> sections of a deck: what the time loop needs
// to step, to end, to save and to checkpoint. Defaults are Vaango's.
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tephra {

class DeckNode;

struct TimeParameters {
  double init_time = 0.0;          // <initTime>
  double max_time = 0.0;           // <maxTime>
  long long max_timesteps = -1;    // <max_timesteps> / <max_Timesteps>; -1: no limit
  bool end_exactly = false;        // <end_on_max_time_exactly> / <end_at_max_time_exactly>
  double delt_min = 0.0;           // <delt_min>: a smaller stable step stops the run (exit 4)
  double delt_max = 0.0;           // <delt_max>
  std::optional<double> delt_init;         // <delt_init>: the first step's dt
  std::optional<double> max_delt_increase; // <max_delt_increase>: dt_n <= (1+r) dt_{n-1}
  double timestep_multiplier = 1.0;        // <timestep_multiplier> (CFL-like factor)
};

// A <save label> as the components name it: Uintah's relocated particle
// labels "p.x+", "p.mass+", ... (the end-of-step values) are saved as "p.x", ...
std::string canonical_save_label(const std::string& label);

struct SaveRequest {
  std::string label;       // <save label="...">
  std::optional<std::string> material;  // material="..." attribute
};

struct ArchiverParameters {
  std::string filebase;                       // <filebase>
  std::optional<double> output_interval;      // <outputInterval> (simulated time)
  std::optional<int> output_timestep_interval;// <outputTimestepInterval>
  bool output_initial = true;                 // the initial state is always written
  std::vector<SaveRequest> saves;
  std::set<std::string> labels() const;

  // <checkpoint cycle=... interval=...|timestepInterval=...>
  bool checkpoint = false;
  int checkpoint_cycle = 2;
  std::optional<double> checkpoint_interval;
  std::optional<int> checkpoint_timestep_interval;
};

TimeParameters read_time_parameters(const DeckNode& time_section);
ArchiverParameters read_archiver_parameters(const DeckNode& archiver_section);

}  // namespace tephra
