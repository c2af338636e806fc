// fixel info: what a scene file means once read (derived values, fixels on
// the outline, the seated configuration, warnings).
#include <iostream>
#include <memory>

#include "cli.h"
#include "fixel/io_info.h"
#include "fixel/scene.h"
#include "fixel/scene_info.h"

namespace fixel::cli {
namespace {

struct InfoArgs {
  std::vector<std::string> scene_paths;
  bool json = false;
  RunOptions run;
};

int run_info(const std::string& path, bool json) {
  const Scene scene = read_scene(path);
  const SceneInfo info = scene_info(scene);
  std::cout << (json ? scene_info_json(scene, info) : scene_info_text(scene, info));
  return 0;
}

}  // namespace

Command add_info(CLI::App& app) {
  auto a = std::make_shared<InfoArgs>();
  auto* cmd =
      app.add_subcommand("info", "What a scene means: derived mass, centre of mass, inertia, fixels, seated pose");
  cmd->add_option("scene", a->scene_paths, kScenesHelp)->required();
  cmd->add_flag("--json", a->json, "Print one JSON document on stdout (one line per scene for several)");
  add_run_options(cmd, a->run);
  return {cmd, [a] {
            arm_run_control(a->run);
            return run_batch(a->scene_paths, a->json, [a](const std::string& p) { return run_info(p, a->json); });
          }};
}

}  // namespace fixel::cli
