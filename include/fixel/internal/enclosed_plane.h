#pragma once
// Plane vectors enclosed, as the region's interval pre-tests build them
// (src/region_filter.cpp, src/paper_cone_filter.cpp): every decision a
// certified sign, the first sign left open abandoning the pre-test by
// throwing enclosed::Open. Needs a Protect scope.

#include <array>
#include <boost/container/small_vector.hpp>
#include <cstddef>

#include "fixel/internal/filtered.h"

namespace fixel::internal {

// A wrench generator (f_x, f_y, moment about the centre of mass) enclosed.
using FGen = std::array<FI, 3>;

namespace enclosed {

// Small fixed-capacity vectors: no allocation for the usual few control
// points, generators and families.
using FVecs = boost::container::small_vector<FVec2, 8>;
using FGens = boost::container::small_vector<FGen, 8>;

// Thrown at the first sign the enclosures leave open.
struct Open {};

inline int sign_of(const FI& x) {
  const int s = certain_sign(x);
  if (s == kUndecided) throw Open{};
  return s;
}

inline FI fcross(const FVec2& a, const FVec2& b) { return a.x * b.y - a.y * b.x; }
inline FI fdot(const FVec2& a, const FVec2& b) { return a.x * b.x + a.y * b.y; }
inline FVec2 fsub(const FVec2& a, const FVec2& b) { return {a.x - b.x, a.y - b.y}; }
inline FVec2 frot90(const FVec2& v) { return {-v.y, v.x}; }

// is_zero(v) as 1 (certainly zero), 0 (certainly not) or kUndecided.
inline int zero_state(const FVec2& v) {
  const int sx = certain_sign(v.x), sy = certain_sign(v.y);
  if ((sx != 0 && sx != kUndecided) || (sy != 0 && sy != kUndecided)) return 0;
  return sx == 0 && sy == 0 ? 1 : kUndecided;
}

// direction_extremes (wrench_cone.cpp) on enclosures: the same decisions in
// the same order; the indices of the extremes. False when not pointed.
bool extremes(const FVecs& v, std::size_t& first, std::size_t& last);

}  // namespace enclosed

}  // namespace fixel::internal
