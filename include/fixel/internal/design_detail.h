#pragma once
// What the three files of fixture design share (design_candidates.cpp,
// design_score.cpp, design.cpp): the part's outline and its length, and the
// filter and score of one triple.

#include <array>
#include <vector>

#include "fixel/design.h"

namespace fixel::internal {

// The part's outline; SceneError when it has none.
const Boundary& boundary_of(const Scene& part);

// The summed parameter length of the outline's curves.
Rational total_length(const Boundary& b);

// A rational unit vector near the direction of n, and the angle between them.
Vec2 unit_near(const Vec2& n, double* angle_error);

enum class Verdict { kSingular, kNoFormClosure, kJEmpty, kScored };

// Filters and scores one triple by the ranking push model.
Verdict evaluate(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 const Rational& total, const std::array<int, 3>& f, DesignLayout& out);

}  // namespace fixel::internal
