#pragma once
// The extreme legs of planar directions, on any source of signs: one
// algorithm for direction_extremes (wrench_cone.cpp, exact signs, filtered)
// and enclosed::extremes (region_filter.cpp, certified signs on enclosures,
// the first open one abandoning the pre-test), so the two make the same
// decisions in the same order. No CGAL here.

#include <cstddef>

namespace fixel::internal {

// Over n directions v_0 … v_{n-1}, with orient(i, j) the sign of v_i ⊗ v_j
// (0 when i == j) and dot_sign(i, j) the sign of v_i · v_j: the indices of
// the first (clockwise-most) and last legs of the closed cone they span,
// when it is pointed (angle < π); false when it is not, or n == 0.
template <class Orient, class DotSign>
bool cone_extremes(std::size_t n, const Orient& orient, const DotSign& dot_sign, std::size_t& first,
                   std::size_t& last) {
  int s = -1, e = -1;
  for (std::size_t i = 0; i < n; ++i) {
    bool all_ccw = true, all_cw = true;
    for (std::size_t j = 0; j < n && (all_ccw || all_cw); ++j) {
      const int o = orient(i, j);
      all_ccw = all_ccw && o >= 0;
      all_cw = all_cw && o <= 0;
    }
    if (all_ccw && s < 0) s = static_cast<int>(i);
    if (all_cw && e < 0) e = static_cast<int>(i);
  }
  if (s < 0 || e < 0) return false;
  const auto si = static_cast<std::size_t>(s), ei = static_cast<std::size_t>(e);
  const int c = orient(si, ei);
  if (c < 0 || (c == 0 && dot_sign(si, ei) < 0)) return false;  // spans π or more
  // Anti-parallel legs inside (a span of exactly π) pass the test above when
  // the extremes are not among them; so every leg is checked against the
  // extremes (inside the cone, or along the first when the two are parallel).
  for (std::size_t j = 0; j < n; ++j) {
    const int a = orient(si, j);
    const bool inside = c == 0 ? a == 0 && dot_sign(si, j) > 0 : a >= 0 && orient(j, ei) >= 0;
    if (!inside) return false;
  }
  first = si;
  last = ei;
  return true;
}

}  // namespace fixel::internal
