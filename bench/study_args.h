#pragma once
// The study programs' options: pairs "--name value". --help, an unknown
// name or a name without its value prints the usage and exits (0, or 2 on a
// mistake), so a typo never starts a long run with the defaults.

#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/rational.h"

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

// A mistaken value also stops the study before it runs: exit 2 with the
// option and the value named (atoi read "1e4" as 1 and "x" as 0).
[[noreturn]] inline void study_value_error(const char* name, const char* text, const std::string& wanted) {
  std::cerr << name << ": '" << text << "' is not " << wanted << "\n";
  std::exit(2);
}

// The whole text a whole number from lo to hi.
inline long long study_int(const char* name, const char* text, long long lo, long long hi) {
  long long v = 0;
  const char* end = text + std::strlen(text);
  const auto [at, ec] = std::from_chars(text, end, v);
  if (ec != std::errc() || at != end || v < lo || v > hi)
    study_value_error(name, text, "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return v;
}

// A seed: the whole text a number from 0 to 2^64 − 1.
inline std::uint64_t study_seed(const char* name, const char* text) {
  std::uint64_t v = 0;
  const char* end = text + std::strlen(text);
  const auto [at, ec] = std::from_chars(text, end, v);
  if (ec != std::errc() || at != end) study_value_error(name, text, "a whole number from 0 to 2^64 - 1");
  return v;
}

// An exact rational ("20", "1/2", "0.25"), positive.
inline fixel::Rational study_positive_rational(const char* name, const char* text) {
  try {
    const fixel::Rational r = fixel::parse_rational(text, name);
    if (r > 0) return r;
  } catch (const fixel::Error&) {
  }
  study_value_error(name, text, "a positive exact number (as 20, 1/2 or 0.25)");
}

// A count of samples, pushes, parts or candidates.
inline constexpr long long kMaxStudyCount = 1000000;

// A count option's value: a whole number from `least` (0 unless the
// study cannot run with fewer, as validate_region's pushes) to
// kMaxStudyCount.
inline int study_count(const char* name, const char* text, int least = 0) {
  return static_cast<int>(study_int(name, text, least, kMaxStudyCount));
}

// The engine's accuracy, as `fixel push` takes it (docs/physics.md, "Engine
// settings"): pass kEngineArgs to check_study_args beside a study's own
// names, then read them into its PushOptions. Each value is checked here,
// and then the whole PushOptions (the step limit time · steps_per_h) by
// check_push_options, so a study never starts with settings its first push
// would refuse.
inline const std::vector<std::string> kEngineArgs = {"--steps-per-h", "--velocity-iterations", "--position-iterations"};
inline const char* const kEngineUsage = " [--steps-per-h N] [--velocity-iterations N] [--position-iterations N]";

// The whole PushOptions, as the first push would check them; a study that
// takes no engine options calls it too (its --time).
template <class PushOptions>
void check_study_push_options(const PushOptions& options) {
  try {
    check_push_options(options);  // found by argument-dependent lookup: fixel::physics
  } catch (const fixel::Error& e) {
    std::cerr << e.what() << "\n";
    std::exit(2);
  }
}

template <class PushOptions>
void read_engine_args(int argc, char** argv, PushOptions& options) {
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    // Whole numbers here; their ranges are check_push_options' below.
    auto whole = [&] {
      int v = 0;
      const char *text = argv[i + 1], *end = text + std::strlen(text);
      const auto [at, ec] = std::from_chars(text, end, v);
      if (ec != std::errc() || at != end) study_value_error(argv[i], text, "a whole number (as 1000)");
      return v;
    };
    if (a == "--steps-per-h") options.steps_per_h = whole();
    if (a == "--velocity-iterations") options.velocity_iterations = whole();
    if (a == "--position-iterations") options.position_iterations = whole();
  }
  check_study_push_options(options);
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
