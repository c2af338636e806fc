// The derived facts of a scene for `fixel info`.
#include "fixel/scene_info.h"

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/lcp.h"
#include "fixel/sustained.h"

namespace fixel {

SceneInfo scene_info(const Scene& scene) {
  check_scene_values(scene);  // a scene built in code: a SceneError, not a crash
  SceneInfo info;
  const Body& b = scene.body;
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const Fixel& f = scene.fixels[i];
    info.p_AoFixel_A.push_back({f.p_AoF_A.x - f.gap * f.n_A.x, f.p_AoF_A.y - f.gap * f.n_A.y});
    if (b.boundary) info.on_outline.push_back(fit_to_boundary(*b.boundary, f.p_AoF_A, &f.n_A));
    if (f.off_boundary)
      info.warnings.push_back("fixels[" + std::to_string(i) +
                              "] is marked off_boundary: its point or normal is not checked against the outline");
  }
  if (b.boundary) info.area = b.boundary->mass.area;
  if (b.mass_from_area)
    info.warnings.push_back("body.mass is not given: it defaults to the enclosed area, " + to_string(b.mass) +
                            " kg (density 1 kg/m²); give \"mass\" for the real part");
  // The analyses that would refuse the scene, said here rather than only
  // when one of them is run, with their own reason.
  try {
    require_determined_fixture(scene);
    require_single_friction(scene);
  } catch (const InputError& e) {
    info.warnings.push_back(
        "the one-step analyses (seat, region, sample, simulate, solutions, push-plan, dump) refuse this scene: " +
        std::string(e.what()));
  }
  const std::string sustained =
      "the sustained-push analyses (seat --sustained, region --push sustained, dump --sustained) refuse "
      "this scene: ";
  bool sustained_fixture = true;
  try {
    require_sustained_fixture(scene);
  } catch (const InputError& e) {
    info.warnings.push_back(sustained + e.what());
    sustained_fixture = false;
  }
  try {
    info.seated = seated_pose(scene);
  } catch (const InputError& e) {
    info.seated_unavailable = e.what();
    if (sustained_fixture) info.warnings.push_back(sustained + e.what());
  }
  return info;
}

}  // namespace fixel
