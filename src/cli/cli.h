// Shared pieces of the command line: exit codes, run control, and one
// `add_*` per subcommand. Each registers its options on the app and returns
// the function that runs it; src/cli only parses arguments and calls the
// library.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/rational.h"
#include "fixel/scene.h"

namespace fixel::cli {

// Exit codes: 0 success, 1 a verification failed, 2 bad input or usage,
// 3 a bug in fixel, 4 --max-seconds reached, 130 interrupted (Ctrl-C).
constexpr int kExitBadInput = 2;
constexpr int kExitBug = 3;
constexpr int kExitTimeLimit = 4;
constexpr int kExitInterrupted = 130;

/// A registered subcommand and the function that runs it (returns the exit code).
struct Command {
  CLI::App* app;
  std::function<int()> run;
};

/// `--max-seconds` and `--quiet`, for the commands whose length comes from input.
struct RunOptions {
  double max_seconds = 0;
  bool quiet = false;
};
void add_run_options(CLI::App* cmd, RunOptions& options);

/// Arms the run's control block: deadline, progress on a terminal, Ctrl-C.
void arm_run_control(const RunOptions& options);
/// The run's control block (polled by the library's long loops).
RunControl* run_control();
/// Ends a progress line, if one was shown.
void end_progress();

/// Throws InputError naming `flag` unless `path` can be written (its folder
/// exists and is writable, and the file, if it exists, is writable); run
/// before any output, so that a bad path never follows a printed report.
// `renamed_over`: the file is written beside and renamed over the path
// (save_scene), so an existing FIFO or device there is refused too.
void check_writable(const std::string& path, const std::string& flag, bool renamed_over = false);
/// Throws InputError naming `flag_b` when `path_b` names the same file as
/// `path_a` (by its text, through links, or as the same existing file):
/// the second output would replace the first. Empty paths are not asked for.
void check_distinct_outputs(const std::string& path_a, const std::string& flag_a, const std::string& path_b,
                            const std::string& flag_b);
/// Throws InputError naming `flag` when the output `path` is the scene file
/// read (`scene_path`, not "-"): writing would replace the input.
void check_not_input(const std::string& scene_path, const std::string& path, const std::string& flag);
/// Throws InputError naming `flag` unless files can be made in the folder
/// `path`: an existing folder that is writable, or one that can be made
/// (its nearest existing ancestor is a writable folder).
void check_output_folder(const std::string& path, const std::string& flag);

/// A pusher μ, or an interval "lo,hi", judged at its upper end.
Rational parse_pusher_mu(const std::string& text);

/// Reads a scene file, or standard input for "-" (once per run).
Scene read_scene(const std::string& path);

/// Runs `run` once per scene path. One path: as is. Several: each report in
/// turn, the text under a "== PATH" line, or with `json` one compact JSON
/// line per scene (with "file"; a scene that fails gives {"file", "error"}
/// and the batch goes on). Returns the worst exit code.
int run_batch(const std::vector<std::string>& paths, bool json, const std::function<int(const std::string&)>& run);

/// The impulse the one-step commands act on: b₀ + p (seat --impulse,
/// simulate's step 1, solutions), as region adds b₀ to every push.
VectorQ with_background(const Scene& scene, const VectorQ& p);
/// The line that says so when b₀ is not zero (empty otherwise), naming the
/// scene; `total` is b₀ + p. Printed with the report, after every input
/// check: its first line in text, on stderr with --json (the JSON stays
/// one document).
std::string background_note(const Scene& scene, const VectorQ& total);
/// Prints background_note (if any) where the report's mode puts it.
void print_background_note(const Scene& scene, const VectorQ& total, bool json);

/// Help text of a positional list of scenes.
// Whole-number options are decimal, as exact numbers are (docs/formats.md:
// "010" is ten): CLI11 alone reads 010 as octal, 0x10 as hex and "" as 0.
// Checks the text is [+-]digits and strips leading zeros; else an error.
CLI::Validator decimal_integer();

// The engine's accuracy for push and region --validate (docs/physics.md,
// "Engine settings"): --steps-per-h, --velocity-iterations and
// --position-iterations, each needing `needs` (if given) on the command
// line. Their ranges are checked as they are parsed (CLI11 would clamp a
// long), and again by the library with the step limit (PushOptions'
// fields, mapped to the flags in main.cpp).
struct EngineArgs {
  long steps_per_h = physics::PushOptions{}.steps_per_h;
  int velocity_iterations = physics::PushOptions{}.velocity_iterations;
  int position_iterations = physics::PushOptions{}.position_iterations;
};
void add_engine_options(CLI::App* cmd, EngineArgs& engine, CLI::Option* needs = nullptr);
void apply_engine_options(const EngineArgs& engine, physics::PushOptions& options);

constexpr const char* kScenesHelp = "Scene file(s) (JSON, docs/formats.md); - reads standard input";

Command add_info(CLI::App& app);
Command add_seat(CLI::App& app);
Command add_dump(CLI::App& app);
Command add_simulate(CLI::App& app);
Command add_solutions(CLI::App& app);
Command add_region(CLI::App& app);
Command add_sample(CLI::App& app);
Command add_push(CLI::App& app);
Command add_verify(CLI::App& app);
Command add_design(CLI::App& app);
Command add_push_plan(CLI::App& app);

}  // namespace fixel::cli
