#pragma once
// J's region questions on enclosures (src/sustained_filter.cpp): the
// interval pre-test of the sustained target, so that a region segment's
// cone is tested against J without one exact number (docs/theory.md §10.5).
// Each answer replays the exact test's steps (sustained_target.cpp) on a
// certified sign, and counts the LP tests it stands for; any sign the
// enclosures leave open gives kUndecided and the exact test runs.
#include <cstddef>
#include <vector>

#include "fixel/internal/region_filter.h"
#include "fixel/internal/sustained_data.h"

namespace fixel::internal {

class JEnclosure {
 public:
  // J's rows in the body frame, enclosed. Only for an exact q* (Q(√d)):
  // with an enclosed q* the exact test itself runs on intervals. `d` must
  // outlive this (an open sign among J's rows is settled on them).
  explicit JEnclosure(const Data<Q2>& d);

  // cone_in_J of cone(gens): 1 in, 0 not in, kUndecided; `lp_tests` gets
  // the Fourier–Motzkin systems the exact test would count. `paired`:
  // gens (2k, 2k + 1) share their exact force part; `points` (or null):
  // each generator's control point (IntervalTarget::generator_points).
  int cone_in(const FGen* gens, std::size_t n, bool paired, const int* points, long& lp_tests) const;
  // cone_misses_J of cone(gens): 1 misses, 0 not, kUndecided; the same count.
  int cone_misses(const FGen* gens, std::size_t n, bool paired, const int* points, long& lp_tests) const;

 private:
  const Data<Q2>* data_;
  std::vector<FGen> k_rows_;
  FGen normaliser_;
  std::vector<std::vector<FGen>> jam_facets_;
};

}  // namespace fixel::internal
