#pragma once
// The study programs' options: pairs "--name value". --help, an unknown
// name or a name without its value prints the usage and exits (0, or 2 on a
// mistake), so a typo never starts a long run with the defaults.

#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

namespace fixel::bench {

inline void check_study_args(int argc, char** argv, const std::string& usage, const std::vector<std::string>& names) {
  for (int i = 1; i < argc; i += 2) {
    const std::string a = argv[i];
    const bool help = a == "--help" || a == "-h";
    bool known = false;
    for (const auto& n : names) known = known || a == n;
    if (help) {
      std::cout << usage << "\n";
      std::exit(0);
    }
    if (!known || i + 1 >= argc) {
      std::cerr << (known ? "missing value for " : "unknown option ") << a << "\n" << usage << "\n";
      std::exit(2);
    }
  }
}

// The engine's accuracy, as `fixel push` takes it (docs/physics.md, "Engine
// settings"): pass kEngineArgs to check_study_args beside a study's own
// names, then read them into its PushOptions. The value is checked by
// physics::check_push_options when the first push runs.
inline const std::vector<std::string> kEngineArgs = {"--steps-per-h", "--velocity-iterations", "--position-iterations"};
inline const char* const kEngineUsage = " [--steps-per-h N] [--velocity-iterations N] [--position-iterations N]";

template <class PushOptions>
void read_engine_args(int argc, char** argv, PushOptions& options) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--steps-per-h") options.steps_per_h = std::atoi(argv[i + 1]);
    if (a == "--velocity-iterations") options.velocity_iterations = std::atoi(argv[i + 1]);
    if (a == "--position-iterations") options.position_iterations = std::atoi(argv[i + 1]);
  }
}

// Names plus the engine's, for check_study_args.
inline std::vector<std::string> with_engine_args(std::vector<std::string> names) {
  names.insert(names.end(), kEngineArgs.begin(), kEngineArgs.end());
  return names;
}

// One line naming the settings a study ran with, so that its output says.
template <class PushOptions>
std::string engine_line(const PushOptions& o) {
  return "engine: dt = h/" + std::to_string(o.steps_per_h) + ", " + std::to_string(o.velocity_iterations) +
         " velocity and " + std::to_string(o.position_iterations) + " position iterations per step";
}

}  // namespace fixel::bench
