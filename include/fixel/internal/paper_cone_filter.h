#pragma once
// The paper cone of a segment built on enclosures (src/paper_cone_filter.cpp,
// docs/theory.md §8), for the region's interval pre-test.

#include <vector>

#include "fixel/geometry.h"
#include "fixel/internal/enclosed_plane.h"
#include "fixel/internal/lazy_piece.h"

namespace fixel::internal {

namespace enclosed {

// The paper cone (paper(), wrench_cone.cpp) of the push directions enclosed
// by ds and de, with r the control points less the centre of mass and legs
// the control polygon's legs: appends (û_s, X_min), (û_s, X_max), (û_e,
// X_min), (û_e, X_max) to gens, the last two left out when û_e = û_s
// exactly, and û_s (and û_e) to forces; false when û_s, û_e span π (the
// exact path splits). Throws Open when a sign it needs is open.
bool paper_cone(const FVec2& ds, const FVec2& de, const FVecs& r, const LazyPiece::Enclosures& legs, FGens& gens,
                FVecs& forces);

}  // namespace enclosed

// The paper cone (segment_wrench_cone with ConeMethod::kPaper) of one edge
// family's push directions enclosed by ds and de, for a segment with
// control points and legs enclosed and centre of mass c, as the pre-test
// builds it: 1 with `gens` enclosing the exact generators in their order
// (the two of û_s only, when û_e = û_s exactly), 0 when the exact
// construction finds no cone (its unit directions span π), kUndecided when
// a sign it needs is not certified.
int paper_cone_enclosure(const FVec2& ds, const FVec2& de, const LazyPiece::Enclosures& control,
                         const LazyPiece::Enclosures& legs, const Vec2& c, std::vector<FGen>& gens);

}  // namespace fixel::internal
