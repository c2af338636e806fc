#pragma once
// The exact region along one Bézier piece (docs/theory.md §12), used by
// compute_region when RegionOptions::exact is set.

#include <vector>

#include "fixel/region.h"
#include "fixel/region_target.h"

namespace fixel::internal {

// The intervals tiling the piece's parameter range [u0, u1] (its start
// corner, if any, is the caller's): between consecutive real roots of the
// target's sign polynomials the status is constant and decided by one exact
// point test; a root where the tangent vanishes (a cusp) is a single
// partial point. Ends strictly inside the piece that are irrational carry
// exact_u0 / exact_u1.
std::vector<RegionInterval> exact_piece_intervals(const Scene& scene, RegionTarget& target, const BezierPiece& piece,
                                                  const Rational& mu, RegionStats& stats);

}  // namespace fixel::internal
