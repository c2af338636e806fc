// fixel push-plan: how hard to push at one boundary point, per model.
#include <iostream>
#include <memory>

#include "cli.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/push_plan.h"
#include "fixel/scene_json.h"

namespace fixel::cli {
namespace {

struct PlanArgs {
  std::string scene_path, at_text;
  bool json = false, guaranteed = false;
  RunOptions run;
};

int run_push_plan(const PlanArgs& a) {
  arm_run_control(a.run);
  const Scene scene = read_scene(a.scene_path);
  const auto at = physics::parse_curve_point(scene, a.at_text, "--at");
  const PushPlan plan = plan_push(scene, at.curve, at.u, a.guaranteed, run_control());
  std::cout << (a.json ? push_plan_json(scene, plan) : push_plan_text(scene, plan));
  return 0;
}

}  // namespace

Command add_push_plan(CLI::App& app) {
  auto a = std::make_shared<PlanArgs>();
  auto* cmd = app.add_subcommand("push-plan", "How hard to push at one boundary point: magnitude windows per model");
  cmd->add_option("scene", a->scene_path, "Scene file with a boundary (JSON, docs/formats.md); - reads standard input")
      ->required();
  cmd->add_option("--at", a->at_text, "The boundary point: parameter U of curve K, as K:U (exact numbers)")->required();
  cmd->add_flag("--guaranteed", a->guaranteed, "Also the window in G (every one-step outcome seats; dof 3)");
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_push_plan(*a); }};
}

}  // namespace fixel::cli
