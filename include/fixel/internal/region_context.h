#pragma once
// One run of the pushing region (region.cpp: the subdivision; region_point.cpp:
// the point tests, the corners' and the sampling baseline's): its state and
// the helpers both units share.

#include <cstddef>
#include <memory>
#include <vector>

#include "fixel/internal/region_runs.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

struct RegionContext {
  const Scene& scene;
  RegionTarget& target;
  Rational mu;
  ConeMethod method;
  Rational resolution;
  RegionStats stats;
  RunControl* control = nullptr;
  // When set, IN answers whose magnitudes the enclosures bound wait here for
  // the merge (internal::settle); index kUnplaced until the interval is placed.
  std::vector<Deferred>* deferred = nullptr;
  // region_reaches: stop at the first interval that is not OUT.
  bool stop_at_reach = false;
};

constexpr std::size_t kUnplaced = static_cast<std::size_t>(-1);

// The edge families of a pusher with friction μ: the normal alone for 0.
const std::vector<EdgeFamily>& families(const Rational& mu);

// The scene checks every region run makes first: an outline, and dof 3
// (SceneError).
void check_region_scene(const Scene& scene);

// The checks every region run makes first (InputError, SceneError).
// `mu_from_scene`: mu is the scene's pusher friction (the caller gave
// none), so a target's refusal of it names the scene's field, pusher.mu.
void check_region_inputs(const Scene& scene, const Rational& mu, const RegionTarget& target,
                         bool mu_from_scene = false);

// A push is judged at the upper end of the pusher's friction interval: the
// set of push directions grows with μ_p, so the region shrinks
// (docs/theory.md §10).
Rational default_pusher_mu(const Scene& scene, const RegionTarget& target);

bool in_half_line(const RegionTarget& target, const RegionInterval& r);

std::unique_ptr<RegionTarget> step_target(const Scene& scene, const SeatingSet& S, const GuaranteedSet* G);

// The status of the point at parameter u of curve `curve`, with its
// magnitudes. `first`: no piece before it holds u (the caller knows; saves a
// scan of every piece per corner, which made long polylines quadratic).
RegionStatus status_at(RegionContext& ctx, const Boundary& b, const std::vector<Join>& js, int curve, const Rational& u,
                       Magnitudes* mags, std::vector<Magnitudes>* set = nullptr, std::size_t first = 0);

// compute_region with the joins of the scene's outline (joins(b)) made
// beforehand, or null to make them: a caller that runs many regions on one
// outline (fixture design) makes them once. InternalError when their count
// is not the outline's piece count. With `locate` false, region.places and
// outline_length (display: exact points at every end, arc lengths) stay
// empty, for a caller that reads only the intervals.
Region compute_region_joined(const Scene& scene, RegionTarget& target, const RegionOptions& options,
                             const std::vector<Join>* joins, bool locate = true);

// Whether compute_region(scene, target, options) would have an interval
// that is not OUT (IN, or PARTIAL at the resolution): the same subdivision
// in the same order, stopped at the first such interval. Design's form
// closure test asks only this. `joins` as for compute_region_joined.
bool region_reaches(const Scene& scene, RegionTarget& target, const RegionOptions& options,
                    const std::vector<Join>* joins = nullptr);

}  // namespace fixel::internal
