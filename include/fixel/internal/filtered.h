#pragma once
// Interval filters with exact fallback (fixel/filter.h): CGAL's Interval_nt
// without per-operation rounding protection, used inside one
// Protect_FPU_rounding scope per predicate, so the rounding mode is set once
// and restored on every exit (also by exceptions). Data stays rational; an
// interval enclosure of each value is made on demand (or cached by callers).
#include <CGAL/Interval_nt.h>
#include <gmp.h>

#include <array>
#include <cmath>
#include <limits>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/geometry.h"
#include "fixel/rational.h"

namespace fixel::internal {

// Arithmetic valid only while a Protect scope is alive.
using FI = CGAL::Interval_nt<false>;
// Rounds towards +∞ for its lifetime, then restores the caller's mode.
using Protect = CGAL::Protect_FPU_rounding<true>;

// Whether CGAL's intervals computed in rounding mode `mode` (a CGAL_FE_*
// constant) hold their values, by three operations whose results are not
// doubles: true for CGAL_FE_UPWARD on a processor that honours it, false in
// the other modes. directed_rounding_works() asks once, for upward.
bool intervals_enclose_in(CGAL::FPU_CW_t mode);

// Tests only: act as if directed rounding were ignored (as under
// valgrind), so that directed_rounding_works() is false until switched off.
void assume_directed_rounding_ignored(bool on);

// Counts one filtered decision (certified) or one exact fallback.
void record_filter(FilterSite site, bool certified);
// Adds a batch of decisions at once (one atomic update per counter).
void record_filter(FilterSite site, long certified, long fallbacks);

// An interval that certainly holds q: the point q when q is a dyadic
// rational of at most 53 significant bits (common here: coordinates and
// subdivision parameters), else mpq_get_d (which truncates) widened by one
// ulp each way; the whole line when q is out of double range. Needs no
// rounding mode.
inline FI to_interval(const Rational& q) {
  const auto& m = q.backend().data();
  const mpz_srcptr num = mpq_numref(m), den = mpq_denref(m);
  if (mpz_size(num) <= 1 && mpz_size(den) == 1) {
    // Numerator and denominator exact in double: one division, which in any
    // rounding mode lands within an ulp of q, so one ulp each way holds q.
    constexpr mp_limb_t kExact = mp_limb_t(1) << 53;
    const mp_limb_t n = mpz_getlimbn(num, 0), d = mpz_getlimbn(den, 0);
    if (n < kExact && d < kExact) {
      const double x = (mpz_sgn(num) < 0 ? -static_cast<double>(n) : static_cast<double>(n)) / static_cast<double>(d);
      if ((d & (d - 1)) == 0) return FI(x);  // a power of two: the division is exact
      constexpr double inf = std::numeric_limits<double>::infinity();
      return FI(std::nextafter(x, -inf), std::nextafter(x, inf));
    }
  }
  const double d = mpq_get_d(m);
  if (!(std::abs(d) < 1e300)) return FI::largest();
  const bool dyadic = mpz_popcount(mpq_denref(m)) == 1 && mpz_sizeinbase(mpq_denref(m), 2) < 900;
  if (dyadic && mpz_sizeinbase(mpq_numref(m), 2) <= 53) return FI(d);
  constexpr double inf = std::numeric_limits<double>::infinity();
  return FI(std::nextafter(d, -inf), std::nextafter(d, inf));
}

struct FVec2 {
  FI x, y;
};
inline FVec2 to_interval(const Vec2& v) { return {to_interval(v.x), to_interval(v.y)}; }

// Sign when the interval certifies it: -1, 0 (only the point 0) or +1;
// kUndecided otherwise.
constexpr int kUndecided = 2;
inline int certain_sign(const FI& x) {
  if (x.inf() > 0) return 1;
  if (x.sup() < 0) return -1;
  if (x.inf() == 0 && x.sup() == 0) return 0;
  return kUndecided;
}

// Sign of a ⊗ b from enclosures (kUndecided when they cannot tell).
inline int cross_sign(const FVec2& a, const FVec2& b) {
  Protect p;
  return certain_sign(a.x * b.y - a.y * b.x);
}

// Sign of a ⊗ b, filtered: the enclosures first, the exact product when
// they cannot decide or the exact path is forced.
inline int orientation_filtered(const Vec2& a, const FVec2& fa, const Vec2& b, const FVec2& fb) {
  if (!force_exact()) {
    const int s = cross_sign(fa, fb);
    record_filter(FilterSite::kOrientation, s != kUndecided);
    if (s != kUndecided) return s;
  }
  return sign(cross(a, b));
}

inline int orientation_filtered(const Vec2& a, const Vec2& b) {
  return orientation_filtered(a, to_interval(a), b, to_interval(b));
}

// Sign of a·p − c (the side of the half-space a·p ≥ c), filtered. Throws
// InputError when p and a differ in length.
inline int affine_sign_filtered(const VectorQ& a, const Rational& c, const VectorQ& p) {
  if (p.size() != a.size())
    throw InputError("p", std::to_string(p.size()) + " components",
                     "where " + std::to_string(a.size()) + " are needed");
  if (!force_exact()) {
    Protect guard;
    FI s = -to_interval(c);
    for (Eigen::Index i = 0; i < a.size(); ++i) s += to_interval(a[i]) * to_interval(p[i]);
    const int r = certain_sign(s);
    record_filter(FilterSite::kMembership, r != kUndecided);
    if (r != kUndecided) return r;
  }
  return sign(a.dot(p) - c);
}

// A semi-static filter for the sign of a dot product of 3-vectors, cheaper
// than intervals where one vector meets many (the pair bound's walk):
// doubles near each entry, valid only when each entry's enclosure is a
// point (an exact double) or lies within [2^-500, 2^500] in magnitude with
// a relative width of at most 2^-50. Then, in any rounding mode,
// |fl(â · ĝ) − a · g| ≤ 2^-48 · fl(Σ |â_i ĝ_i|) (docs/theory.md §10.6,
// "A static filter for the walk"), and 2^-46 of it is the margin used.
struct Near3 {
  std::array<double, 3> v{};
  bool valid = false;
};

inline Near3 near3(const std::array<FI, 3>& enclosure) {
  constexpr double kLow = 0x1p-500, kHigh = 0x1p500, kWidth = 0x1p-50;
  Near3 out;
  for (int i = 0; i < 3; ++i) {
    const double lo = enclosure[i].inf(), hi = enclosure[i].sup();
    out.v[i] = lo;
    if (lo == hi && std::abs(lo) <= kHigh && (lo == 0 || std::abs(lo) >= kLow)) continue;
    const double small = std::min(std::abs(lo), std::abs(hi));
    const bool same_sign = (lo > 0) == (hi > 0);
    if (!(same_sign && small >= kLow && std::max(std::abs(lo), std::abs(hi)) <= kHigh && hi - lo <= kWidth * small))
      return Near3{};  // NaN bounds fail every comparison above, so they end here too
  }
  out.valid = true;
  return out;
}

// Sign of a · g: −1, 0, +1 when the filter certifies it, else kUndecided.
// 0 only when every product is an exact zero.
inline int static_dot_sign(const Near3& a, const Near3& g) {
  if (!a.valid || !g.valid) return kUndecided;
  const double p0 = a.v[0] * g.v[0], p1 = a.v[1] * g.v[1], p2 = a.v[2] * g.v[2];
  const double magnitude = std::abs(p0) + std::abs(p1) + std::abs(p2);
  if (magnitude == 0) return 0;
  const double s = p0 + p1 + p2, margin = 0x1p-46 * magnitude;
  return s > margin ? 1 : s < -margin ? -1 : kUndecided;
}

}  // namespace fixel::internal
