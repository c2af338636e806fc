// fixel push (a constant push in Box2D) and fixel verify (the built-in suite).
#include <iostream>
#include <memory>

#include "cli.h"
#include "fixel/error.h"
#include "fixel/io.h"
#include "fixel/physics.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seated_pose.h"
#include "fixel/verify.h"

namespace fixel::cli {
namespace {

struct PushArgs {
  std::string scene_path, wrench_text, at_text, svg_path, time_text = "20";
  bool json = false;
  EngineArgs engine;
  RunOptions run;
};

int run_push(const PushArgs& a) {
  arm_run_control(a.run);
  check_writable(a.svg_path, "--svg");
  check_not_input(a.scene_path, a.svg_path, "--svg");
  const Scene scene = read_scene(a.scene_path);
  physics::PushOptions push_options;
  push_options.time = parse_rational(a.time_text, "--time");
  push_options.control = run_control();
  apply_engine_options(a.engine, push_options);
  if (push_options.time <= 0) throw InputError("--time", a.time_text, "must be > 0");
  if (a.wrench_text.empty() && a.at_text.empty()) throw InputError("--wrench", "missing", "or --at is required");
  physics::Wrench w;
  if (!a.at_text.empty()) {
    const auto at = physics::parse_curve_point(scene, a.at_text, "--at");
    const auto q = seated_pose(scene).approx;
    w = physics::push_wrench_at(scene, at.curve, at.u, {q[0], q[1], q[2]}, "--at");
  } else {
    w = physics::parse_wrench(a.wrench_text, scene.body.dof, "--wrench");
  }
  const auto r = physics::push(scene, w, push_options);
  std::cout << (a.json ? physics::push_json(scene, w, r) : physics::push_text(scene, w, r));
  if (!a.svg_path.empty()) {
    physics::write_push_svg(a.svg_path, scene, r, &w);
    if (!a.json) std::cout << "wrote " << a.svg_path << "\n";
  }
  return 0;
}

}  // namespace

Command add_push(CLI::App& app) {
  auto a = std::make_shared<PushArgs>();
  auto* cmd = app.add_subcommand("push", "Run a constant push in the Box2D physics engine (docs/physics.md)");
  cmd->add_option("scene", a->scene_path, "Scene file with a boundary (JSON, docs/formats.md); - reads standard input")
      ->required();
  auto* wrench_opt =
      cmd->add_option("--wrench", a->wrench_text, "World-frame wrench wx,wy,wm (force at the centre of mass)");
  cmd->add_option("--at", a->at_text, "Frictionless unit push at parameter U of curve K, at the seated pose: K:U")
      ->excludes(wrench_opt);
  cmd->add_option("--time", a->time_text, "Hold the wrench for T time steps h (default 20)");
  add_engine_options(cmd, a->engine);
  cmd->add_option("--svg", a->svg_path, "Draw the trajectory to this SVG file");
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout");
  add_run_options(cmd, a->run);
  return {cmd, [a] { return run_push(*a); }};
}

Command add_verify(CLI::App& app) {
  auto json = std::make_shared<bool>(false);
  auto* cmd = app.add_subcommand(
      "verify", "Run the built-in verification suite (the paper's Examples 1 and 2, and sustained-push checks)");
  cmd->add_flag("--json", *json, "Print one JSON document on stdout");
  return {cmd, [json] {
            const auto checks = run_verification();
            std::cout << (*json ? verification_json(checks) : verification_text(checks));
            for (const auto& c : checks)
              if (!c.passed) return 1;
            return 0;
          }};
}

}  // namespace fixel::cli
