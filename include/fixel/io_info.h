#pragma once
/// @file
/// `fixel info`: a scene's derived facts as text and JSON (docs/formats.md).

#include <string>

#include "fixel/scene.h"
#include "fixel/scene_info.h"

namespace fixel {

/// The report of `fixel info` (exact values with decimals and units).
std::string scene_info_text(const Scene& scene, const SceneInfo& info);

/// `fixel info --json`: {"scene", "description", "dof", "time_step", "mass",
/// "center_of_mass", "inertia", "velocity", "area", "fixels", "pusher_mu",
/// "background_impulse", "seated_pose", "warnings"} (docs/formats.md).
std::string scene_info_json(const Scene& scene, const SceneInfo& info);

}  // namespace fixel
