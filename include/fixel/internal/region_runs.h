#pragma once
// Joins and runs of the pushing region's pieces (region_runs.cpp): the
// tangents where consecutive pieces meet, and the merging of consecutive
// intervals of equal status, with the IN magnitudes that wait for it.

#include <functional>
#include <vector>

#include "fixel/internal/filtered.h"
#include "fixel/internal/region_filter.h"
#include "fixel/region.h"

namespace fixel::internal {

// Where piece `next` starts after piece `prev` (in loop order): enclosures
// of the exact tangents on both sides (end_tangent(prev), start_tangent(next))
// and whether they make a corner (decided exactly).
struct Join {
  std::size_t prev, next;
  FVec2 t_in, t_out;
  bool corner;
};
std::vector<Join> joins(const Boundary& b);

// Limiting tangent directions at the ends of a Bézier piece: the first
// non-zero forward difference P_k − P_0 (resp. P_p − P_k); zero if none.
Vec2 start_tangent(const BezierPiece& p);
Vec2 end_tangent(const BezierPiece& p);

// Merges consecutive intervals of one curve with equal status, each starting
// where the last ended; their magnitudes intersect.
std::vector<RegionInterval> merge_runs(std::vector<RegionInterval> in);

// The corners of the raw list (in loop order; `corners` their indices)
// whose status differs from an IN or OUT neighbour's: there that
// neighbour's interval, merged or not, ends at a point of another status.
std::vector<RegionCorner> corner_ends(const std::vector<RegionInterval>& raw, const std::vector<std::size_t>& corners);

// An IN interval of the raw list whose exact magnitudes wait for the merge:
// raw[index] holds neutral_magnitudes() meanwhile.
struct Deferred {
  std::size_t index;
  MagnitudeBounds bounds;
  std::function<Magnitudes()> exact;  // the exact path's magnitudes
};

// [0, ∞) closed at 0: intersecting with it changes no magnitudes.
Magnitudes neutral_magnitudes();

// Gives the deferred intervals their exact magnitudes where they can matter:
// all of them without merging; with merging (runs as compute_region's
// merge forms them) only those whose enclosure may hold the run's largest
// lower or smallest upper end. The others keep the neutral value, which
// leaves the run's intersection exactly as with their own magnitudes.
void settle(std::vector<RegionInterval>& raw, const std::vector<Deferred>& deferred, bool merging);

}  // namespace fixel::internal
