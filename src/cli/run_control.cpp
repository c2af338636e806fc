// Progress, deadline and Ctrl-C for the long commands.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

#include "cli.h"
#include "fixel/error.h"
#include "fixel/internal/file_write.h"

namespace fixel::cli {
namespace {

// The run's control block; the SIGINT handler only sets its lock-free flag.
RunControl g_run;
bool g_progress_shown = false;
int g_progress_width = 0;  // of the line shown, to blank a longer one's tail

extern "C" void on_sigint(int) {
  g_run.cancel.store(true);
  std::signal(SIGINT, SIG_DFL);  // a second Ctrl-C ends the process at once
}

// Progress on stderr, rewriting one line (only installed on a terminal).
void show_progress(const char* task, long done, long total, const char* unit) {
  const double seconds = std::chrono::duration<double>(RunControl::Clock::now() - g_run.start).count();
  char line[512];
  if (total > 0)
    std::snprintf(line, sizeof line, "%s: %ld of %ld %s (%.1f%%), %.0f s", task, done, total, unit,
                  100.0 * done / total, seconds);
  else
    std::snprintf(line, sizeof line, "%s: %ld %s, %.0f s", task, done, unit, seconds);
  const int width = static_cast<int>(std::strlen(line));
  std::fprintf(stderr, "\r%s%*s", line, std::max(0, g_progress_width - width), "");
  g_progress_width = width;
  std::fflush(stderr);
  g_progress_shown = true;
}

}  // namespace

void add_run_options(CLI::App* cmd, RunOptions& options) {
  cmd->add_option("--max-seconds", options.max_seconds, "Stop with exit 4 after this many seconds (default: no limit)")
      ->check(CLI::Validator(
          [](std::string& text) {
            double x = 0;
            if (text.find_first_of("xXpP") != std::string::npos)  // std::stod reads hex floats: 0x10 is 16
              return text + " is not a decimal number of seconds";
            try {
              x = std::stod(text);
            } catch (const std::exception&) {
              return text + " is not a number of seconds";
            }
            // inf, and any limit of 10^9 s or more, sets none (RunControl::set_time_limit).
            return x > 0 ? std::string() : text + " must be a positive number of seconds";
          },
          "SECONDS > 0"));
  cmd->add_flag("--quiet", options.quiet,
                "No progress line on stderr (shown on a terminal after 1 s, also while loading a huge part)");
}

void arm_run_control(const RunOptions& options) {
  if (options.max_seconds != 0) g_run.set_time_limit(options.max_seconds, "--max-seconds", g_run.start);
  if (!options.quiet && isatty(STDERR_FILENO)) g_run.on_progress = show_progress;
  std::signal(SIGINT, on_sigint);
  // The exact steps inside one library call poll it too (building J and J',
  // one LCP): for the rest of the command, on this thread.
  static const ControlScope scope(&g_run);
}

RunControl* run_control() { return &g_run; }

void end_progress() {
  if (g_progress_shown) std::fputs("\n", stderr);
  g_progress_shown = false;
  g_progress_width = 0;
}

void check_writable(const std::string& path, const std::string& flag, bool renamed_over) {
  if (path.empty()) return;  // not asked for
  internal::check_writable(path, flag,
                           renamed_over ? internal::SpecialFile::kRefuse : internal::SpecialFile::kWriteDirectly);
}

namespace {

// The file `path` names, through links (also a dangling one, whose target
// a write would make); a loop ends after 40 links, as the kernel's does.
std::filesystem::path file_named(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path p = fs::absolute(path, ec);
  for (int link = 0; link < 40; ++link) {
    p = fs::weakly_canonical(p, ec);  // the links of the part that exists
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    const fs::path target = fs::read_symlink(p, ec);
    if (ec) break;
    p = target.is_absolute() ? target : p.parent_path() / target;
  }
  return p.lexically_normal();
}

}  // namespace

void check_distinct_outputs(const std::string& path_a, const std::string& flag_a, const std::string& path_b,
                            const std::string& flag_b) {
  namespace fs = std::filesystem;
  if (path_a.empty() || path_b.empty()) return;
  std::error_code ec;
  const bool same_file = fs::exists(path_a, ec) && fs::exists(path_b, ec) && fs::equivalent(path_a, path_b, ec);
  if (path_a == path_b || file_named(path_a) == file_named(path_b) || (same_file && !ec))
    throw InputError(flag_b, path_b,
                     "names the same file as " + flag_a + ": give two files, or the second would replace the first");
}

void check_not_input(const std::string& scene_path, const std::string& path, const std::string& flag) {
  if (scene_path == "-") return;  // standard input: no file to replace
  check_distinct_outputs(scene_path, "the scene file read", path, flag);
}

void check_output_folder(const std::string& path, const std::string& flag) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path == "-") throw InputError(flag, path, "is not an output folder: give a folder name (./- for one named -)");
  fs::path p = path.empty() ? fs::path(".") : fs::path(path);
  if (fs::exists(p, ec) && !fs::is_directory(p, ec)) throw InputError(flag, path, "is not a folder");
  if (fs::is_symlink(fs::symlink_status(p, ec)) && !fs::exists(p, ec))
    throw InputError(flag, path, "is a link to a folder that does not exist");
  // The folder, or the nearest ancestor that exists (the rest is made).
  while (!fs::exists(p, ec) && p.has_parent_path() && p.parent_path() != p) p = p.parent_path();
  if (!fs::exists(p, ec)) p = ".";
  if (!fs::is_directory(p, ec)) throw InputError(flag, path, "cannot be made: " + p.string() + " is not a folder");
  if (access(p.c_str(), W_OK | X_OK) != 0)
    throw InputError(flag, path, "cannot be written: no permission to make files in " + p.string());
}

// The region shrinks as the pusher's μ grows (docs/theory.md §10), so an
// interval is judged at its upper end.
Rational parse_pusher_mu(const std::string& text) {
  const auto mu = parse_rational_list(text, "--pusher-mu");
  if (mu.size() > 2) throw InputError("--pusher-mu", text, "must be M or lo,hi");
  if (mu.size() == 2 && mu[1] < mu[0]) throw InputError("--pusher-mu", text, "has lo > hi");
  if (mu[0] < 0) throw InputError("--pusher-mu", text, "must be >= 0");
  return mu.back();
}

}  // namespace fixel::cli
