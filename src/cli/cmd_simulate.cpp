// fixel simulate and fixel solutions: one impulse, stepped or enumerated.
#include <iostream>
#include <memory>

#include "cli.h"
#include "fixel/io.h"
#include "fixel/outcomes.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/stepper.h"

namespace fixel::cli {
namespace {

struct ImpulseArgs {
  std::string scene_path, impulse_text;
  int steps = 1;
  bool json = false;
  RunOptions run;
};

int run_simulate(const ImpulseArgs& a) {
  arm_run_control(a.run);
  const Scene scene = read_scene(a.scene_path);
  const VectorQ p = with_background(scene, parse_impulse(a.impulse_text, scene.body.dof));
  const auto sim = simulate(scene, {p}, a.steps, run_control());
  // Step 1's outcomes, for the report's count: a stop there is simulate's.
  OutcomeCount first;
  try {
    first = count_outcomes(enumerate_outcomes(scene, p, run_control()));
  } catch (const StoppedError& e) {
    const std::string how = e.reason() == StopReason::kInterrupted ? "interrupted" : "time limit reached";
    std::string inner = e.what();
    const std::string no_result = "; no result";  // said once, at the end
    if (inner.size() >= no_result.size() &&
        inner.compare(inner.size() - no_result.size(), no_result.size(), no_result) == 0)
      inner.resize(inner.size() - no_result.size());
    throw StoppedError(e.reason(),
                       "simulate: " + how + " after its " + std::to_string(a.steps) +
                           " step(s), while counting step 1's outcomes (" + inner + ")" + no_result,
                       e.done(), e.total());
  }
  end_progress();
  print_background_note(scene, p, a.json);
  std::cout << (a.json ? simulation_json(scene, sim, &first) : simulation_text(scene, sim, &first));
  return 0;
}

int run_solutions(const ImpulseArgs& a) {
  arm_run_control(a.run);
  const Scene scene = read_scene(a.scene_path);
  const VectorQ p = with_background(scene, parse_impulse(a.impulse_text, scene.body.dof));
  const auto outcomes = enumerate_outcomes(scene, p, run_control());
  end_progress();
  print_background_note(scene, p, a.json);
  std::cout << (a.json ? outcomes_json(scene, p, outcomes) : outcomes_text(scene, p, outcomes));
  return 0;
}

}  // namespace

Command add_simulate(CLI::App& app) {
  auto a = std::make_shared<ImpulseArgs>();
  auto* cmd = app.add_subcommand("simulate", "Time-step the part under an impulse with the exact LCP solver");
  cmd->add_option("scene", a->scene_path, "Scene file (JSON, docs/formats.md); - reads standard input")->required();
  cmd->add_option("--impulse", a->impulse_text, "External impulse of step 1: px,py[,ptheta] (b0 is added)")->required();
  cmd->add_option("--steps", a->steps, "Number of steps (default 1); later steps get no impulse")
      ->transform(decimal_integer());
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_simulate(*a); }};
}

Command add_solutions(CLI::App& app) {
  auto a = std::make_shared<ImpulseArgs>();
  auto* cmd = app.add_subcommand("solutions", "Every outcome of one step (all LCP solutions, by contact mode)");
  cmd->add_option("scene", a->scene_path, "Scene file (JSON, docs/formats.md); - reads standard input")->required();
  cmd->add_option("--impulse", a->impulse_text, "External impulse: px,py[,ptheta] (b0 is added)")->required();
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_solutions(*a); }};
}

}  // namespace fixel::cli
