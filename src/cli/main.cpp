// The fixel command line: parses arguments, runs the chosen subcommand, and
// turns the library's typed errors into messages and exit codes.
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <new>
#include <vector>

#include "cli.h"
#include "fixel/error.h"
#include "fixel/filter.h"

namespace {

constexpr const char* kReportLine =
    "fixel: this is a bug in fixel, please report it with the command line and the scene file\n";

// Test hook for the exit-3 path: FIXEL_TEST_FAULT=internal or =std.
void maybe_inject_fault() {
  const char* fault = std::getenv("FIXEL_TEST_FAULT");
  if (!fault) return;
  if (std::string(fault) == "internal") throw fixel::InternalError("injected by FIXEL_TEST_FAULT=internal");
  if (std::string(fault) == "std") throw std::runtime_error("injected by FIXEL_TEST_FAULT=std");
}

// The library names API fields; a user of the command line knows the flags.
std::string user_message(const fixel::InputError& e) {
  static const std::map<std::string, std::string> kFlagOf = {
      {"RegionOptions.resolution", "--resolution"},
      {"RegionOptions.resolution_length", "--resolution-length"},
      {"RegionOptions.pusher_mu", "--pusher-mu"},
      {"RegionOptions.digits", "--digits"},
      {"RegionOptions.exact", "--exact"},
      {"sample_region(points_per_curve)", "--points"},
      {"simulate(steps)", "--steps"},
      {"PushOptions.time", "--time"},
      {"PushOptions.steps_per_h", "--steps-per-h"},
      {"PushOptions.velocity_iterations", "--velocity-iterations"},
      {"PushOptions.position_iterations", "--position-iterations"},
      {"push(wrench)", "--wrench"},
      {"validate_region(pushes)", "--validate"},
      {"dump_off(length)", "--length"},
      {"dump_off(directory)", "--off"},
      {"dump_sustained_off(directory)", "--off"},
      {"svg(path)", "--svg"},
      {"save_scene(path)", "--scene-out"},
      {"boundary_candidates(spacing)", "--spacing"},
      {"load_candidates(path)", "--candidates"},
      {"DesignOptions.resolution", "--resolution"},
      {"DesignOptions.mu", "--mu"},
      {"DesignOptions.pusher_mu", "--pusher-mu"},
      {"DesignOptions.gap", "--gap"},
      {"DesignOptions.top", "--top"},
      {"DesignOptions.jobs", "--jobs"},
  };
  const std::string what = e.what();
  const auto it = kFlagOf.find(e.field());
  if (it == kFlagOf.end() || what.compare(0, e.field().size(), e.field()) != 0) return what;
  return it->second + what.substr(e.field().size());
}

// FIXEL_FILTER_STATS=1: the filter counters on stderr after the run.
void maybe_print_filter_stats() {
  const char* v = std::getenv("FIXEL_FILTER_STATS");
  if (!v || !*v || std::string(v) == "0") return;
  const fixel::FilterStats st = fixel::filter_stats();
  std::cerr << "fixel: filters (certified/exact fallbacks):";
  for (int k = 0; k < static_cast<int>(fixel::FilterSite::kCount); ++k)
    std::cerr << " " << fixel::to_string(static_cast<fixel::FilterSite>(k)) << " " << st.site[k].certified << "/"
              << st.site[k].fallbacks;
  if (!fixel::directed_rounding_works())
    std::cerr << " (exact only: this machine ignores the rounding mode, as valgrind does)\n";
  else
    std::cerr << (fixel::force_exact() ? " (exact only)\n" : "\n");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace fixel::cli;
  // Past a file-size limit (ulimit -f) a write fails with EFBIG, which the
  // writers report and clean up after, instead of the signal killing fixel
  // with a temporary file left behind.
  std::signal(SIGXFSZ, SIG_IGN);
  // The report is written at the end in one piece (up to 1 MiB) when it
  // goes to a file or pipe, so that a failed write is seen at the final
  // flush, with its reason in errno.
  // (glibc ignores the size unless given the buffer.)
  static char stdout_buffer[1 << 20];
  if (!isatty(STDOUT_FILENO)) std::setvbuf(stdout, stdout_buffer, _IOFBF, sizeof stdout_buffer);
  CLI::App app{"fixel: exact one-push part seating against a fixture (Egan, Berard & Trinkle)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("fixel 0.1.0"));

  const std::vector<Command> commands = {add_seat(app),   add_dump(app),      add_simulate(app), add_solutions(app),
                                         add_region(app), add_sample(app),    add_push(app),     add_verify(app),
                                         add_design(app), add_push_plan(app), add_info(app)};
  bool exact_only = false;
  for (const auto& command : commands)
    command.app->add_flag("--exact-only", exact_only,
                          "Turn the floating-point filters off: every decision in exact rationals (same output, "
                          "slower; also FIXEL_FORCE_EXACT=1)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    // fixel's own error format; an unknown first word is named as such.
    std::string what = e.what();
    if (argc > 1 && argv[1][0] != '-') {
      std::string names;
      bool known = false;
      for (const auto& command : commands) {
        known = known || command.app->get_name() == argv[1];
        names += (names.empty() ? "" : ", ") + command.app->get_name();
      }
      if (!known) what = std::string(argv[1]) + ": is not a fixel command (" + names + ")";
    }
    std::cerr << "fixel: error: " << fixel::escape_control(what) << "\nRun with --help for more information.\n";
    return kExitBadInput;
  }

  // An option given an empty value (a script's unset "$VAR") would read as
  // not given: refused instead.
  for (const auto& command : commands)
    if (command.app->parsed())
      for (const CLI::Option* option : command.app->get_options())
        for (const std::string& value : option->results())
          if (value.empty()) {
            std::cerr << "fixel: error: " << fixel::escape_control(option->get_name())
                      << ": \"\" is empty (an unset variable?)\n";
            return kExitBadInput;
          }

  try {
    maybe_inject_fault();
    if (exact_only) fixel::set_force_exact(true);
    for (const auto& command : commands)
      if (command.app->parsed()) {
        const int code = command.run();
        maybe_print_filter_stats();
        // A full disk or a closed pipe must not pass as success: the answer is lost.
        errno = 0;  // the stream keeps no reason; the failed write(2) leaves it in errno
        std::cout.flush();
        if (!std::cout) {
          const int error = errno;
          std::cerr << "fixel: error: standard output: cannot be written"
                    << (error != 0 ? std::string(" (") + std::strerror(error) + ")" : std::string())
                    << " (the answer was lost)\n";
          return kExitBadInput;
        }
        return code;
      }
    return kExitBadInput;
  } catch (const fixel::StoppedError& e) {
    end_progress();
    std::cerr << "fixel: stopped: " << e.what() << "\n";
    return e.reason() == fixel::StopReason::kInterrupted ? kExitInterrupted : kExitTimeLimit;
  } catch (const fixel::InternalError& e) {
    end_progress();
    std::cerr << "fixel: internal error: " << e.what() << "\n" << kReportLine;
    return kExitBug;
  } catch (const fixel::InputError& e) {
    end_progress();
    std::cerr << "fixel: error: " << user_message(e) << "\n";
    return kExitBadInput;
  } catch (const fixel::Error& e) {
    end_progress();
    std::cerr << "fixel: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::bad_alloc&) {
    end_progress();
    std::cerr << "fixel: error: out of memory: the input is too large for this machine\n";
    return kExitBadInput;
  } catch (const std::exception& e) {
    end_progress();
    std::cerr << "fixel: internal error: " << e.what() << "\n" << kReportLine;
    return kExitBug;
  }
}
