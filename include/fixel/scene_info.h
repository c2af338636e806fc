#pragma once
/// @file
/// What a scene file means once read: derived mass properties, each
/// fixel's place on the outline and the fixel's own position, the seated
/// pose, and warnings (`fixel info`, docs/cli.md).

#include <optional>
#include <string>
#include <vector>

#include "fixel/on_boundary.h"
#include "fixel/scene.h"
#include "fixel/seated_pose.h"

namespace fixel {

/// The derived facts of a scene, computed once for the formatters.
struct SceneInfo {
  /// Per fixel: the fixel's own position f_i = p_i − ψ_i n_i (frame A, m).
  std::vector<Vec2> p_AoFixel_A;
  /// Per fixel, with a boundary: where its point lies on the outline.
  std::vector<BoundaryFit> on_outline;
  /// Enclosed area of the outline (m²), with a boundary.
  std::optional<Rational> area;
  /// The seated pose q*, when it can be computed; else the reason.
  std::optional<SeatedPose> seated;
  std::string seated_unavailable;
  /// Warnings for the user: defaulted mass, fixels marked off_boundary, and
  /// the analyses that refuse the scene (n_c ≠ dof, W_n singular; the
  /// sustained push needs dof 3 and 3 fixels).
  std::vector<std::string> warnings;
};

/// Computes the SceneInfo of a scene (never throws on a valid scene: a
/// seated pose that cannot be computed is reported in seated_unavailable).
SceneInfo scene_info(const Scene& scene);

}  // namespace fixel
