#pragma once
// What the one-step targets S (seating_target.cpp) and G
// (guaranteed_target.cpp) share.

#include <vector>

#include "fixel/region.h"

namespace fixel::internal {

// Certified inner bound of the common Euclidean magnitudes (docs/theory.md
// §8): generators g_j with force parts f_j in cone(d_first, d_last) and
// exact T(g_j). Any m in the result has b0 + m w ∈ S for every wrench w of
// the cone whose force part is a unit vector.
Magnitudes common_magnitudes(const std::vector<VectorQ>& gens, const std::vector<Magnitudes>& T, const Vec2& d_first,
                             const Vec2& d_last);

}  // namespace fixel::internal
