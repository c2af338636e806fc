#pragma once
/// @file
/// SVG pictures (display only: coordinates are doubles).

#include <string>

#include <optional>

#include "fixel/guaranteed.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"

namespace fixel {

/// Draws the pushing region: the outline coloured by status, the fixels with
/// normals and friction cones, the centre of mass and a legend (left panel),
/// and the wrench directions on the unit sphere in a longitude/latitude
/// projection (right panel; docs/cli.md). Throws InputError if the file
/// cannot be written.
/// `region` must come from compute_region (it records its cone method,
/// resolution, pusher μ and target).
/// With a region against G, pass G to shade the wrench panel by G. Throws
/// InputError naming S or G, before writing, when they are not this scene's
/// (check_guaranteed_set_of).
void write_region_svg(const std::string& path, const Scene& scene, const SeatingSet& S, const Region& region,
                      const GuaranteedSet* G = nullptr);

/// The same picture for the sustained-push region against J: the seated
/// pose as a ghost outline beside the scene pose, and the wrench panel
/// shaded by J and by the jam cones. Throws InputError if the file cannot be
/// written, or, before writing, naming J when it is another scene's.
void write_sustained_region_svg(const std::string& path, const Scene& scene, const SustainedSet& J,
                                const Region& region);

/// The default slice of write_guaranteed_svg: p_θ of apex + Σ rays (N·m·s),
/// through S's interior. The apex's own p_θ cuts S at the apex alone when
/// every ray's p_θ has one sign, as on the paper's Example 2. dof 3.
Rational default_slice_theta(const SeatingSet& S);

/// Draws the slice p_θ = theta of S and G (dof 3): impulses in G, in S but
/// not in G, and outside S, each decided exactly on a display grid, with the
/// apex and an optional impulse marked; with G null, S alone. Throws
/// InputError if the file cannot be written or dof != 3, or, before
/// writing, naming S or G when they are not this scene's.
void write_guaranteed_svg(const std::string& path, const Scene& scene, const SeatingSet& S, const GuaranteedSet* G,
                          const Rational& theta, const std::optional<VectorQ>& impulse);

}  // namespace fixel
