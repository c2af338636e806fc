// Scene inputs of the command line: `-` for standard input, and batches of
// several scene files (one report per scene; one JSON line each with --json).
#include <iostream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.h"
#include "fixel/error.h"
#include "fixel/scene_json.h"

namespace fixel::cli {

namespace {

Scene read_scene_polled(const std::string& path) {
  if (path != "-") return load_scene(path, run_control());
  static bool consumed = false;
  if (consumed) throw InputError("SCENE", "-", "is given twice: standard input can be read only once");
  consumed = true;
  return read_scene(std::cin, "stdin", run_control());
}

}  // namespace

CLI::Validator decimal_integer() {
  return CLI::Validator(
      [](std::string& text) {
        std::size_t k = text.empty() || (text[0] != '+' && text[0] != '-') ? 0 : 1;
        const std::size_t digits_from = k;
        for (; k < text.size(); ++k)
          if (text[k] < '0' || text[k] > '9') return text + " is not a whole decimal number";
        if (digits_from == text.size()) return "'" + text + "' is not a whole decimal number";
        std::size_t first = digits_from;
        while (first + 1 < text.size() && text[first] == '0') ++first;  // "010" is ten
        text = text.substr(0, digits_from) + text.substr(first);
        return std::string();
      },
      "INTEGER");
}

namespace {

// After decimal_integer: the same range message as the library's, before
// CLI11 converts the text (it clamps a long past its range, and names an
// int past its range only as "Could not convert").
CLI::Validator whole_in(long long lo, long long hi, const std::string& rule) {
  return CLI::Validator(
      [lo, hi, rule](std::string& text) {
        long long x = 0;
        try {
          x = std::stoll(text);
        } catch (const std::exception&) {
          return text + " " + rule;  // past long long: out of range too
        }
        return x >= lo && x <= hi ? std::string() : text + " " + rule;
      },
      rule);
}

}  // namespace

void add_engine_options(CLI::App* cmd, EngineArgs& engine, CLI::Option* needs) {
  const std::string with = needs != nullptr ? "With --validate: " : "";
  const std::string steps = needs != nullptr ? "engine steps" : "Engine steps";
  CLI::Option* added[] = {cmd->add_option("--steps-per-h", engine.steps_per_h,
                                          with + steps + " per time step h, at least 1000 (default 1000: dt = h/1000)")
                              ->transform(decimal_integer())
                              ->check(whole_in(1000, 2147483647, "must be 1000 to 2147483647 (dt <= h/1000)")),
                          cmd->add_option("--velocity-iterations", engine.velocity_iterations,
                                          with + "Box2D velocity iterations per step, 1 to 1000 (default 20)")
                              ->transform(decimal_integer())
                              ->check(whole_in(1, physics::kMaxSolverIterations, "must be 1 to 1000")),
                          cmd->add_option("--position-iterations", engine.position_iterations,
                                          with + "Box2D position iterations per step, 1 to 1000 (default 10)")
                              ->transform(decimal_integer())
                              ->check(whole_in(1, physics::kMaxSolverIterations, "must be 1 to 1000"))};
  if (needs != nullptr)
    for (CLI::Option* o : added) o->needs(needs);
}

void apply_engine_options(const EngineArgs& engine, physics::PushOptions& options) {
  options.steps_per_h = engine.steps_per_h;
  options.velocity_iterations = engine.velocity_iterations;
  options.position_iterations = engine.position_iterations;
}

// Loading polls the run's control block: a huge part shows a "load: ..."
// progress line on a terminal and obeys --max-seconds and Ctrl-C.
Scene read_scene(const std::string& path) {
  Scene scene = read_scene_polled(path);
  end_progress();
  return scene;
}

VectorQ with_background(const Scene& scene, const VectorQ& p) {
  return scene.background_impulse.isZero() ? p : VectorQ(scene.background_impulse + p);
}

std::string background_note(const Scene& scene, const VectorQ& total) {
  if (scene.background_impulse.isZero()) return "";
  std::string b0, sum;
  for (int k = 0; k < total.size(); ++k) {
    b0 += (k ? ", " : "") + to_string(scene.background_impulse[k]);
    sum += (k ? ", " : "") + to_string(total[k]);
  }
  return "note: scene \"" + escape_control(scene.name) + "\" has background_impulse b0 = (" + b0 +
         "), added: the impulse used is b0 + p = (" + sum + ")\n";
}

void print_background_note(const Scene& scene, const VectorQ& total, bool json) {
  // In the text report itself: the report shows only b0 + p, which a reader
  // who drops stderr would take for the impulse typed.
  (json ? std::cerr : std::cout) << background_note(scene, total);
}

namespace {

// Restores std::cout's buffer when a batch item ends, also on an exception.
struct CoutCapture {
  std::ostringstream text;
  std::streambuf* saved;
  CoutCapture() : saved(std::cout.rdbuf(text.rdbuf())) {}
  ~CoutCapture() { std::cout.rdbuf(saved); }
};

}  // namespace

int run_batch(const std::vector<std::string>& paths, bool json, const std::function<int(const std::string&)>& run) {
  if (paths.size() == 1) return run(paths.front());
  int worst = 0;
  for (const auto& path : paths) {
    std::string output, error;
    int code = 0;
    {
      CoutCapture capture;
      try {
        code = run(path);
      } catch (const InputError& e) {
        error = e.what();
        code = kExitBadInput;
      }
      output = capture.text.str();
    }
    worst = std::max(worst, code);
    if (json) {
      // One line per scene: the report compacted, or the error.
      nlohmann::ordered_json line;
      if (error.empty()) {
        line = nlohmann::ordered_json::parse(output);
        line["file"] = path;
      } else {
        line = {{"file", path}, {"error", error}};
      }
      std::cout << line.dump() << "\n";
    } else {
      std::cout << "== " << path << "\n";
      if (error.empty())
        std::cout << output;
      else if (error.rfind(path + ":", 0) == 0 || path == "-")  // names the path (or "-") already
        std::cerr << "fixel: error: " << error << "\n";
      else
        std::cerr << "fixel: error: " << path << ": " << error << "\n";
    }
  }
  return worst;
}

}  // namespace fixel::cli
