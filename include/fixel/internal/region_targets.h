#pragma once
// What the one-step targets S (seating_target.cpp) and G
// (guaranteed_target.cpp) share.

#include <array>
#include <cstddef>
#include <vector>

#include "fixel/internal/filtered.h"
#include "fixel/region.h"

namespace fixel::internal {

// Certified inner bound of the common Euclidean magnitudes (docs/theory.md
// §8): generators g_j with force parts f_j in cone(d_first, d_last) and
// exact T(g_j). Any m in the result has b0 + m w ∈ S for every wrench w of
// the cone whose force part is a unit vector.
Magnitudes common_magnitudes(const std::vector<VectorQ>& gens, const std::vector<Magnitudes>& T, const Vec2& d_first,
                             const Vec2& d_last);

// The candidate directions of a "met" certificate (docs/theory.md §8), as
// enclosures of exact combinations d = Σ w_j g_j with w ≥ 0 exact: the
// generators' sum, then each pair at weights (16 − m, m), m = 1..15. True at
// the first d for which `certified(d)` is; at most 1 + 15·n(n−1)/2 calls.
template <typename Certified>
bool some_combination(const std::array<FI, 3>* gens, std::size_t n, Certified certified) {
  if (n == 0) return false;
  std::array<FI, 3> d;
  {
    Protect guard;
    d = gens[0];
    for (std::size_t j = 1; j < n; ++j)
      for (int i = 0; i < 3; ++i) d[i] += gens[j][i];
  }
  if (certified(d)) return true;
  for (std::size_t p = 0; p < n; ++p)
    for (std::size_t q = p + 1; q < n; ++q)
      for (int m = 1; m < 16; ++m) {
        {
          Protect guard;
          for (int i = 0; i < 3; ++i) d[i] = FI(16 - m) * gens[p][i] + FI(m) * gens[q][i];
        }
        if (certified(d)) return true;
      }
  return false;
}

// Throws InputError unless S and b0 are a rigid body's (dof 3, rows and b0
// of three components): the one-step targets read them as such.
void check_rigid_seating_set(const SeatingSet& S, const VectorQ& b0);

}  // namespace fixel::internal
