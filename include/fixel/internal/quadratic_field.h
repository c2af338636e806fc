#pragma once
// Exact arithmetic in one quadratic field Q(√d), for decisions at the seated
// pose q* (whose cos θ and sin θ solve a quadratic). CGAL's Sqrt_extension
// does the arithmetic and the exact signs; this header stays internal and is
// included only by the sustained-push sources.

#include <CGAL/Sqrt_extension.h>
#include <CGAL/boost_mp.h>

#include <array>
#include <utility>
#include <vector>

#include "fixel/rational.h"
#include "fixel/seated_pose.h"

namespace fixel::internal {

using Q2 = CGAL::Sqrt_extension<Rational, Rational, CGAL::Tag_true, CGAL::Tag_true>;
using V3 = std::array<Q2, 3>;

inline int sign(const Q2& x) { return static_cast<int>(CGAL::sign(x)); }

inline Q2 q2(const Rational& x) { return Q2(x); }

inline QuadraticIrrational to_public(const Q2& x) {
  if (!x.is_extended() || x.a1() == 0) return {x.a0(), Rational(0), Rational(0)};
  return {x.a0(), x.a1(), x.root()};
}

inline Q2 from_public(const QuadraticIrrational& x) {
  if (x.b == 0) return Q2(x.a);
  return Q2(x.a, x.b, x.d);
}

// Rational bounds lo < x < hi of x = a + b√d, about 2⁻⁶⁰ apart (an exact
// integer square root: no overflow however large d is; seated_pose.cpp).
std::pair<Rational, Rational> bounds(const QuadraticIrrational& x);

// The double nearest x, up to the bounds' width (display only).
double approx(const QuadraticIrrational& x);

inline Q2 dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

inline V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

inline V3 neg(const V3& a) { return {-a[0], -a[1], -a[2]}; }

inline V3 lift(const VectorQ& v) { return {Q2(v[0]), Q2(v[1]), Q2(v[2])}; }

inline bool is_zero(const V3& a) { return sign(a[0]) == 0 && sign(a[1]) == 0 && sign(a[2]) == 0; }

}  // namespace fixel::internal
