#include "mpmice/app/CommandLine.h"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

#include "core/base/Errors.h"
#include "core/base/Log.h"
#include "core/base/PhaseTimers.h"
#include "core/deck/DeckLoader.h"
#include "core/deck/Validate.h"
#include "core/grid/Loop.h"
#include "core/io/Extract.h"
#include "core/parallel/OutputGather.h"
#include "core/parallel/Ranks.h"
#include "core/sim/RunParameters.h"
#include "core/sim/TimeLoop.h"
#include "mpmice/ComponentFactory.h"

namespace tephra::app {

namespace {

const char* kUsage =
    "usage:\n"
    "  tephra DECK [--output DIR] [--max-steps N] [--end-time T] [--threads N] [--quiet]\n"
    "  tephra --validate DECK\n"
    "  tephra --restart DIR [--checkpoint N] [--max-steps N] [--end-time T] [--threads N] [--quiet]\n"
    "  tephra --list FAMILY\n"
    "  tephra extract DIR --var LABEL [--material M] [--step N|last | --time T | --all-times]\n"
    "                 [--point x,y,z | --line x0,y0,z0,x1,y1,z1]\n";

struct Arguments {
  std::vector<std::string> positional;
  std::optional<std::string> output, restart, list, validate, var, step, checkpoint, point, line;
  std::optional<long long> max_steps, material;
  std::optional<double> end_time, time;
  std::optional<int> threads;
  bool quiet = false, all_times = false;
};

long long to_integer(const std::string& flag, const std::string& v) {
  auto r = parse_integer(v);
  if (!r) throw UsageError(flag + " expects an integer, got '" + v + "'");
  return *r;
}

double to_number(const std::string& flag, const std::string& v) {
  auto r = parse_double(v);
  if (!r) throw UsageError(flag + " expects a number, got '" + v + "'");
  return *r;
}

Arguments parse(int argc, char** argv, int first) {
  Arguments a;
  for (int i = first; i < argc; ++i) {
    std::string arg = argv[i];
    auto value = [&](void) -> std::string {
      if (i + 1 >= argc) throw UsageError(arg + " needs a value");
      return argv[++i];
    };
    if (arg == "--output") a.output = value();
    else if (arg == "--restart") a.restart = value();
    else if (arg == "--list") a.list = value();
    else if (arg == "--validate") a.validate = value();
    else if (arg == "--var") a.var = value();
    else if (arg == "--step") a.step = value();
    else if (arg == "--checkpoint") a.checkpoint = value();
    else if (arg == "--point") a.point = value();
    else if (arg == "--line") a.line = value();
    else if (arg == "--material") a.material = to_integer(arg, value());
    else if (arg == "--max-steps") {
      a.max_steps = to_integer(arg, value());
      if (*a.max_steps < 0) throw UsageError("--max-steps must not be negative");
    } else if (arg == "--end-time") a.end_time = to_number(arg, value());
    else if (arg == "--time") a.time = to_number(arg, value());
    else if (arg == "--threads") {
      long long n = to_integer(arg, value());
      if (n < 1 || n > 1024) throw UsageError("--threads must be between 1 and 1024");
      a.threads = static_cast<int>(n);
    } else if (arg == "--quiet") a.quiet = true;
    else if (arg == "--all-times") a.all_times = true;
    else if (arg == "--help" || arg == "-h") throw UsageError("");
    else if (!arg.empty() && arg[0] == '-') throw UsageError("unknown option '" + arg + "'");
    else a.positional.push_back(arg);
  }
  return a;
}

// Everything a run needs, read and validated before step 1.
struct PreparedRun {
  std::unique_ptr<Deck> deck;
  std::unique_ptr<Component> component;
  TimeParameters time;
  ArchiverParameters archiver;
};

PreparedRun prepare(const std::string& deck_path) {
  PreparedRun r;
  r.deck = load_deck(deck_path);
  validate_deck(*r.deck);
  r.time = read_time_parameters(r.deck->root.require_child("Time"));
  r.archiver = read_archiver_parameters(r.deck->root.require_child("DataArchiver"));
  r.component = make_component(*r.deck);
  // Every saved label must be one the component can produce.
  std::set<std::string> known = r.component->known_labels();
  for (const DeckNode* s : r.deck->root.require_child("DataArchiver").children_named("save")) {
    std::string label = canonical_save_label(s->require_attribute("label"));
    if (!known.count(label)) s->missing_feature("saving label '" + label + "' with " + r.component->name());
  }
  return r;
}

// Under mpirun: what each rank sent and received in the gathers of the
// frames and checkpoints (core/parallel/OutputGather.h). Every rank takes
// part (one small all-gather); rank 0 prints.
void print_output_gather_traffic() {
  const Ranks r = world_ranks();
  if (r.size == 1) return;
  const OutputGatherTraffic t = output_gather_traffic();
  const std::vector<double> all =
      all_gather({double(t.calls), double(t.doubles_own), double(t.doubles_sent), double(t.doubles_received)});
  if (log::quiet()) return;
  std::cout << "\noutput gathers (frames and checkpoints), per rank: calls, MB own, MB sent, MB received\n";
  for (int s = 0; s < r.size; ++s) {
    char line[160];
    std::snprintf(line, sizeof line, "  rank %d: %.0f, %.3f, %.3f, %.3f\n", s, all[4 * s], all[4 * s + 1] * 8e-6,
                  all[4 * s + 2] * 8e-6, all[4 * s + 3] * 8e-6);
    std::cout << line;
  }
}

void print_phase_table(double wall) {
  print_output_gather_traffic();
  if (log::quiet()) return;
  std::cout << "\n" << phase_timers().table(wall);
}

double now_seconds() {
  using namespace std::chrono;
  return duration<double>(steady_clock::now().time_since_epoch()).count();
}

int run_deck(const Arguments& a) {
  if (a.positional.size() != 1) throw UsageError("expected exactly one deck");
  double start = now_seconds();
  PreparedRun r = prepare(a.positional[0]);
  RunOptions options;
  options.output_dir = a.output ? *a.output : r.archiver.filebase;
  options.max_steps = a.max_steps;
  options.end_time = a.end_time;
  log::info("running " + a.positional[0] + " with " + r.component->name() + "; output in " + options.output_dir);
  TimeLoop loop(*r.component, r.time, r.archiver, options);
  loop.run(to_xml(r.deck->root));
  log::info("finished at t = " + std::to_string(loop.state().time) + " after " +
            std::to_string(loop.state().step) + " steps; output in " + options.output_dir);
  print_phase_table(now_seconds() - start);
  return 0;
}

int run_restart(const Arguments& a) {
  if (!a.positional.empty()) throw UsageError("--restart takes no deck: it reads DIR/input.ups");
  double start = now_seconds();
  std::string dir = *a.restart;
  std::string deck_path = (std::filesystem::path(dir) / "input.ups").string();
  if (!std::filesystem::exists(deck_path))
    throw UsageError(dir + " is not a Tephra output directory (no input.ups)");
  PreparedRun r = prepare(deck_path);
  RunOptions options;
  options.output_dir = dir;
  options.max_steps = a.max_steps;
  options.end_time = a.end_time;
  TimeLoop loop(*r.component, r.time, r.archiver, options);
  int checkpoint = -1;
  if (a.checkpoint) checkpoint = static_cast<int>(to_integer("--checkpoint", *a.checkpoint));
  loop.restart(checkpoint);
  log::info("finished at t = " + std::to_string(loop.state().time) + " after " +
            std::to_string(loop.state().step) + " steps; output in " + dir);
  print_phase_table(now_seconds() - start);
  return 0;
}

int run_extract(const Arguments& a) {
  if (a.positional.size() != 1) throw UsageError("extract expects one output directory");
  if (!a.var) throw UsageError("extract needs --var LABEL");
  ExtractRequest q;
  q.dir = a.positional[0];
  q.label = *a.var;
  if (a.material) q.material = static_cast<int>(*a.material);
  int selectors = (a.step ? 1 : 0) + (a.time ? 1 : 0) + (a.all_times ? 1 : 0);
  if (selectors > 1) throw UsageError("give one of --step, --time, --all-times");
  if (a.step) {
    if (*a.step == "last") q.when = ExtractRequest::When::Last;
    else {
      q.when = ExtractRequest::When::Step;
      q.step = static_cast<int>(to_integer("--step", *a.step));
    }
  } else if (a.time) {
    q.when = ExtractRequest::When::Time;
    q.time = *a.time;
  } else if (a.all_times) {
    q.when = ExtractRequest::When::AllTimes;
  }
  auto numbers = [](const std::string& flag, const std::string& text, size_t count) {
    auto v = parse_number_list(text);
    if (!v || v->size() != count)
      throw UsageError(flag + " expects " + std::to_string(count) + " comma-separated numbers, got '" + text + "'");
    return *v;
  };
  if (a.point && a.line) throw UsageError("give --point or --line, not both");
  if (a.point) {
    auto v = numbers("--point", *a.point, 3);
    q.point = Vec3(v[0], v[1], v[2]);
  }
  if (a.line) {
    auto v = numbers("--line", *a.line, 6);
    q.line = std::make_pair(Vec3(v[0], v[1], v[2]), Vec3(v[3], v[4], v[5]));
  }
  extract_csv(q, std::cout);
  return 0;
}

}  // namespace

int run_command_line(int argc, char** argv) {
  try {
    if (argc < 2) throw UsageError("");
    if (std::string(argv[1]) == "extract") return run_extract(parse(argc, argv, 2));
    Arguments a = parse(argc, argv, 1);
    log::set_quiet(a.quiet || !world_ranks().is_root());  // under mpirun rank 0 speaks for all
    if (a.threads) set_thread_count(*a.threads);
    if (a.list) {
      if (!a.positional.empty()) throw UsageError("--list takes only a family name");
      for (const auto& key : registered_keys(*a.list)) std::cout << key << "\n";
      return 0;
    }
    if (a.validate) {
      if (!a.positional.empty()) throw UsageError("--validate takes one deck");
      PreparedRun r = prepare(*a.validate);
      std::cout << *a.validate << ": valid (" << r.component->name() << ")\n";
      return 0;
    }
    if (a.restart) return run_restart(a);
    return run_deck(a);
  } catch (const UsageError& e) {
    if (*e.what()) std::cerr << "tephra: " << e.what() << "\n";
    std::cerr << kUsage;
    return static_cast<int>(ExitCode::BadCommandLine);
  } catch (const TephraError& e) {
    const char* kind = e.code() == ExitCode::MissingFeature     ? "not supported yet"
                       : e.code() == ExitCode::NumericalFailure ? "numerical failure"
                                                                : "error";
    std::cerr << "\ntephra: " << kind << ": " << e.what() << "\n";
    abort_other_ranks(static_cast<int>(e.code()));
    return static_cast<int>(e.code());
  } catch (const std::exception& e) {
    std::cerr << "tephra: error: " << e.what() << "\n";
    abort_other_ranks(static_cast<int>(ExitCode::InvalidDeck));
    return static_cast<int>(ExitCode::InvalidDeck);
  }
}

}  // namespace tephra::app
