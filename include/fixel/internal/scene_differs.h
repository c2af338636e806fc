#pragma once
// What a set (J, J′, G) or a region read of the scene it was built from, and
// the check that a scene given beside it agrees there (src/scene_differs.cpp).
#include <string>

#include "fixel/scene.h"

namespace fixel::internal {

/// The parts of a scene a result reads (bit flags).
enum SceneReads : unsigned {
  kReadsOutline = 1u,       ///< dof and the boundary's pieces
  kReadsMass = 2u,          ///< mass, inertia, centre of mass
  kReadsFixels = 4u,        ///< each fixel's point, normal, gap and friction (its upper end)
  kReadsFixelLowerMu = 8u,  ///< each fixel's friction lower end
  kReadsStep = 16u,         ///< dof, time step, velocity
  kReadsBackground = 32u,   ///< the background impulse b0
  kReadsPusher = 64u,       ///< the pusher's friction
  kReadsAll = 127u,
};

/// What a region against this target ("S", "G", "J", "J'") read: J's
/// parts for J and J′, else everything but the pusher's friction (the
/// region records the μ it used).
unsigned region_reads(const std::string& target);

/// The first field read that differs, with both values ("fixels[0].gap is
/// 1/5 here, 0 in the scene it was built from"); "" when none does.
std::string scene_difference(const Scene& built_from, const Scene& given, unsigned reads);

/// Throws InputError(set_name, "built from scene \"…\"", "belongs to another
/// scene than \"…\": <difference>; build it from this scene") when
/// scene_difference is not "". A null `built_from` (built by hand) passes.
void check_same_scene(const Scene* built_from, const Scene& given, unsigned reads, const std::string& set_name);

}  // namespace fixel::internal
