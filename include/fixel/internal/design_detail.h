#pragma once
// What the three files of fixture design share (design_candidates.cpp,
// design_score.cpp, design.cpp): the part's outline and its length, and the
// filter and score of one triple.

#include <array>
#include <memory>
#include <vector>

#include "fixel/design.h"
#include "fixel/internal/region_runs.h"
#include "fixel/region_target.h"

namespace fixel::internal {

// The part's outline; SceneError when it has none.
const Boundary& boundary_of(const Scene& part);

// The summed parameter length of the outline's curves.
Rational total_length(const Boundary& b);

// The cross product of two wrenches (three entries each), exact.
VectorQ cross3(const VectorQ& a, const VectorQ& b);

// The triple after f (increasing candidate indices) in lexicographic order
// among n candidates; f must not be the last.
inline void next_triple(std::array<int, 3>& f, long n) {
  if (f[2] + 1 < n) {
    ++f[2];
  } else if (f[1] + 2 < n) {
    ++f[1];
    f[2] = f[1] + 1;
  } else {
    ++f[0];
    f[1] = f[0] + 1;
    f[2] = f[0] + 2;
  }
}

// A rational unit vector near the direction of n, and the angle between them.
Vec2 unit_near(const Vec2& n, double* angle_error);

// The form-closure filter's region target for the fixels' normal wrenches
// W_n (each fixel's (n, r ⊗ n)): a boundary point is IN when a frictionless
// push there and W_n are in form closure. Null when W_n is singular. It
// answers the region's interval pre-test too.
std::unique_ptr<RegionTarget> form_closure_target(const std::array<VectorQ, 3>& Wn);

// The target "a · w > 0" alone, for a frictionless finger: the open
// half-space of one row (the pair bound, design_bound.h).
std::unique_ptr<RegionTarget> open_half_space_target(const VectorQ& a);

// The target "a_k · w ≥ 0 for every row" (a closed cone; no rows: all of
// R³), for a frictionless finger: the pair bound's jam cones.
std::unique_ptr<RegionTarget> closed_cone_target(std::vector<VectorQ> rows);

// Test switch: the most triple bounds DesignSearch::start keeps (default
// 2^25, half a gigabyte); with more, the run scores every triple. Set it
// before a run, not during one.
void set_design_kept_limit(long limit);

// layout_scene's checks: indices in range, three distinct points, each
// candidate the part's own (check_candidates). InputError naming
// `layout[k]` or `candidates[i]`.
void check_layout(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f);

// How many of the layout's three contacts touch a curved piece (degree
// above 1) on either side of the point, whichever curve names it.
int curved_contacts(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f);

// layout_scene without its checks, for the search's own triples (design()
// and design_batch check the whole candidate list once).
Scene build_layout_scene(const Scene& part, const std::vector<DesignCandidate>& cands, const std::array<int, 3>& f,
                         const DesignOptions& o, bool step, double* angle_error = nullptr);

enum class Verdict { kSingular, kNoFormClosure, kJEmpty, kScored };

// Filters and scores one triple by the ranking push model. `joins`: those
// of the part's outline (internal::joins), made once for many triples, or
// null.
Verdict evaluate(const Scene& part, const std::vector<DesignCandidate>& cands, const DesignOptions& o,
                 const Rational& total, const std::array<int, 3>& f, DesignLayout& out,
                 const std::vector<Join>* joins = nullptr);

}  // namespace fixel::internal
