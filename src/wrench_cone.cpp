#include "fixel/wrench_cone.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost_mp.h>
#include <CGAL/convex_hull_2.h>

#include <cmath>

#include "fixel/cone.h"
#include "fixel/error.h"
#include "fixel/internal/cone_extremes.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/wrench_cone_detail.h"

namespace fixel {

namespace {

using Kernel = CGAL::Simple_cartesian<Rational>;  // exact hull predicates

Vec2 rot90(const Vec2& v) { return {-v.y, v.x}; }

VectorQ wrench(const Vec2& d, const Rational& moment) {
  VectorQ w(3);
  w << d.x, d.y, moment;
  return w;
}

}  // namespace

bool direction_extremes(const std::vector<Vec2>& v, Vec2& first, Vec2& last) {
  // Every sign below is filtered (intervals first, exact products when they
  // cannot decide); the enclosures are made once per vector.
  std::vector<internal::FVec2> f;
  f.reserve(v.size());
  for (const auto& x : v) f.push_back(internal::to_interval(x));
  // Equal vectors (a frictionless push's fan repeats its one direction)
  // are parallel without a product: no interval can certify that zero.
  auto orient = [&](std::size_t i, std::size_t j) {
    return i == j || (v[i].x == v[j].x && v[i].y == v[j].y) ? 0
                                                            : internal::orientation_filtered(v[i], f[i], v[j], f[j]);
  };
  std::size_t s = 0, e = 0;
  if (!internal::cone_extremes(
          v.size(), orient, [&](std::size_t i, std::size_t j) { return sign(dot(v[i], v[j])); }, s, e))
    return false;
  first = v[s];
  last = v[e];
  return true;
}

namespace {

// floor(x · 2^20) / 2^20 for a finite double |x| <= 2 (callers pass
// normalised values only, so the cast cannot overflow).
Rational to_dyadic_floor(double x) {
  const double scale = 1048576.0;  // 2^20
  if (!(std::abs(x) <= 2)) x = 0;  // also catches NaN
  return Rational(static_cast<long long>(std::floor(x * scale)), 1048576);
}

// v scaled by an exact positive factor so that its largest entry is ±1:
// the same direction, and safe to convert to double.
Vec2 normalised(const Vec2& v) {
  const Rational m = std::max(boost::multiprecision::abs(v.x), boost::multiprecision::abs(v.y));
  return m == 0 ? v : Vec2{v.x / m, v.y / m};
}

// Facets are optional: region classification only needs the generators.
WrenchCone finish(std::vector<VectorQ> gens, bool with_facets) {
  WrenchCone cone;
  cone.generators = std::move(gens);
  if (with_facets) cone.facets = cone_facet_normals(cone.generators, 3);
  return cone;
}

// min_k and max_k of r_k ⊗ d over the points, r_k = point_k − c. Filtered:
// the enclosures name the candidates for each extreme, and only those are
// computed exactly (one candidate each in the generic case).
void moment_extremes(const std::vector<Vec2>& pts, const std::vector<internal::FVec2>& fr, const Vec2& c, const Vec2& d,
                     Rational& lo, Rational& hi) {
  const std::size_t n = pts.size();
  auto exact = [&](std::size_t k) { return cross({pts[k].x - c.x, pts[k].y - c.y}, d); };
  if (fr.size() == n && n <= 16) {
    const internal::FVec2 fd = internal::to_interval(d);
    internal::FI m[16];
    double min_sup = 0, max_inf = 0;
    {
      internal::Protect guard;
      for (std::size_t k = 0; k < n; ++k) {
        m[k] = fr[k].x * fd.y - fr[k].y * fd.x;
        min_sup = k == 0 ? m[k].sup() : std::min(min_sup, m[k].sup());
        max_inf = k == 0 ? m[k].inf() : std::max(max_inf, m[k].inf());
      }
    }
    int lo_n = 0, hi_n = 0;
    for (std::size_t k = 0; k < n; ++k) {
      lo_n += m[k].inf() <= min_sup;
      hi_n += m[k].sup() >= max_inf;
    }
    internal::record_filter(FilterSite::kCone, lo_n == 1 && hi_n == 1);
    bool lo_set = false, hi_set = false;
    for (std::size_t k = 0; k < n; ++k) {
      const bool lo_cand = m[k].inf() <= min_sup, hi_cand = m[k].sup() >= max_inf;
      if (!lo_cand && !hi_cand) continue;
      const Rational v = exact(k);
      if (lo_cand && (!lo_set || v < lo)) lo = v, lo_set = true;
      if (hi_cand && (!hi_set || v > hi)) hi = v, hi_set = true;
    }
    return;
  }
  for (std::size_t k = 0; k < n; ++k) {
    const Rational m = exact(k);  // r ⊗ d, linear in r
    if (k == 0 || m < lo) lo = m;
    if (k == 0 || m > hi) hi = m;
  }
}

WrenchCone tight(const SegmentBounds& b, const Vec2& p_AoCm_A, const Vec2& ds, const Vec2& de, bool with_facets) {
  std::vector<internal::FVec2> fr;
  if (!force_exact()) {
    const internal::FVec2 fc = internal::to_interval(p_AoCm_A);
    internal::Protect guard;
    for (const auto& p : b.hull) {
      const internal::FVec2 fp = internal::to_interval(p);
      fr.push_back({fp.x - fc.x, fp.y - fc.y});
    }
  }
  std::vector<VectorQ> gens;
  for (const Vec2& d : {ds, de}) {
    Rational lo = 0, hi = 0;
    moment_extremes(b.hull, fr, p_AoCm_A, d, lo, hi);
    gens.push_back(wrench(d, lo));
    gens.push_back(wrench(d, hi));
  }
  return finish(std::move(gens), with_facets);
}

// in_cone (geometry.h) with each cross-product sign filtered.
bool in_cone_filtered(const Vec2& d, const Vec2& a, const Vec2& b) {
  using internal::orientation_filtered;
  if (orientation_filtered(a, b) == 0) return orientation_filtered(a, d) == 0 && dot(a, d) >= 0;
  return orientation_filtered(a, d) >= 0 && orientation_filtered(d, b) >= 0;
}

std::optional<WrenchCone> paper(const SegmentBounds& b, const Vec2& p_AoCm_A, const Vec2& ds, const Vec2& de,
                                bool with_facets) {
  const Vec2 us = internal::unit_direction_outward(ds, true), ue = internal::unit_direction_outward(de, false);
  const int span = internal::orientation_filtered(us, ue);
  if (span < 0 || (span == 0 && dot(us, ue) < 0)) return std::nullopt;  // rounding reached π
  std::vector<Rational> X;
  for (const auto& p : b.hull) {
    const Vec2 r{p.x - p_AoCm_A.x, p.y - p_AoCm_A.y};
    X.push_back(cross(r, us));
    X.push_back(cross(r, ue));
    // The extra ⊥ angle: X = r ⊗ d is ±|r| where d ⊥ r.
    if (!is_zero(r)) {
      const Rational bound = internal::sqrt_upper(dot(r, r));
      if (in_cone_filtered(rot90(r), us, ue)) X.push_back(bound);
      if (in_cone_filtered(Vec2{-rot90(r).x, -rot90(r).y}, us, ue)) X.push_back(-bound);
    }
  }
  Rational xmin = X[0], xmax = X[0];
  for (const auto& x : X) {
    xmin = x < xmin ? x : xmin;
    xmax = x > xmax ? x : xmax;
  }
  // A unit d in the arc is α u_s + β u_e with 1 <= α + β <= 1/cos(Δ/2). The
  // corner generators cover it only if a positive lower bound (negative upper
  // bound) is shrunk by a factor c <= cos(Δ/2) = sqrt((1 + u_s·u_e)/2).
  const Rational shrink = internal::sqrt_lower((1 + dot(us, ue)) / 2);
  if (xmin > 0) xmin *= shrink;
  if (xmax < 0) xmax *= shrink;
  return finish({wrench(us, xmin), wrench(us, xmax), wrench(ue, xmin), wrench(ue, xmax)}, with_facets);
}

}  // namespace

namespace internal {

long unit_grid_guess(double x, double y, bool flip) {
  const double theta = std::atan2(y, x);
  const double half = (flip ? (theta > 0 ? theta - M_PI : theta + M_PI) : theta) / 2;
  const double k = std::floor(std::tan(half) * 1048576.0);  // 2^20
  // Only a start: NaN (from NaN input) and values far off the grid's
  // useful range (|τ| <= 1 give the whole half-plane) are clamped.
  return !(k > -kUnitGridLimit) ? -kUnitGridLimit : k > kUnitGridLimit ? kUnitGridLimit : static_cast<long>(k);
}

Vec2 unit_direction_outward(const Vec2& d_raw, bool cw) {
  // u(τ) = ((1 − τ²), 2τ) / (1 + τ²) covers the angles (−π, π) with
  // τ = tan(θ/2), and is monotone in τ; a direction of the left half-plane
  // uses −u(τ) with θ − π instead. The answer is the grid point τ = k/2^20
  // nearest d on the requested side (d itself when it is on the grid),
  // found from a guess in doubles by exact side tests, so it does not
  // depend on how the platform rounds atan2 and tan.
  const Vec2 d = normalised(d_raw);
  const bool flip = d.x < 0;
  const FVec2 fd = to_interval(d);
  const long outward = cw ? -1 : 1;  // τ increases counter-clockwise
  long k = unit_grid_guess(to_double(d.x), to_double(d.y), flip);
  Vec2 u;
  auto on_side = [&](long j, Vec2& out) {
    const Rational t(j, 1048576);
    const Rational n = 1 + t * t;
    out = {(1 - t * t) / n, 2 * t / n};
    if (flip) out = {-out.x, -out.y};
    const FVec2 fu = to_interval(out);
    return (cw ? orientation_filtered(out, fu, d, fd) : orientation_filtered(d, fd, out, fu)) >= 0;
  };
  int steps = 0;
  for (; !on_side(k, u); k += outward)  // outward until on the side
    if (++steps > kUnitGridSteps)
      throw InternalError("unit_direction_outward: no grid direction within the step bound");
  for (Vec2 inner; on_side(k - outward, inner); k -= outward) {  // inward while still on it
    u = inner;
    if (++steps > kUnitGridSteps)
      throw InternalError("unit_direction_outward: no grid direction within the step bound");
  }
  return u;
}

Rational cos_half_angle_lower(const Vec2& a_raw, const Vec2& b_raw) {
  // cos(Δ/2) >= c  ⇔  cos Δ >= k = 2c² − 1  ⇔  P >= k √Q with P = a·b, Q = |a|²|b|².
  const Vec2 a = normalised(a_raw), b = normalised(b_raw);  // same angle, doubles in range
  const Rational P = dot(a, b), Q = dot(a, a) * dot(b, b);
  const double cos_delta = to_double(P) / std::sqrt(to_double(Q));
  Rational c = to_dyadic_floor(std::sqrt(std::max(0.0, (1 + cos_delta) / 2)));
  const Rational step(1, 1048576);
  while (c > 0) {
    const Rational k = 2 * c * c - 1;
    const bool ok = k <= 0 ? (P >= 0 || P * P <= k * k * Q) : (P > 0 && P * P >= k * k * Q);
    if (ok) return c;
    c = c > step ? c - step - c / 1024 : Rational(0);
  }
  return Rational(0);
}

namespace {
// floor(√(x · 4^20)) for x = p/q >= 0, as isqrt(p · q · 4^20) / q: exact.
Integer scaled_isqrt(const Rational& x, bool& exact) {
  const Integer p = boost::multiprecision::numerator(x), q = boost::multiprecision::denominator(x);
  const Integer n = p * q * (Integer(1) << 40);
  const Integer r = boost::multiprecision::sqrt(n);
  exact = r * r == n;
  return r;
}
}  // namespace

// √x = √(p q 4^20) / (q 2^20): integer square roots, no doubles, relative
// precision about 2^-20 / q.
Rational sqrt_upper(const Rational& x) {
  if (x <= 0) return Rational(0);
  bool exact = false;
  const Integer r = scaled_isqrt(x, exact);
  return Rational(exact ? r : Integer(r + 1), boost::multiprecision::denominator(x) * (Integer(1) << 20));
}

Rational sqrt_lower(const Rational& x) {
  if (x <= 0) return Rational(0);
  bool exact = false;
  return Rational(scaled_isqrt(x, exact), boost::multiprecision::denominator(x) * (Integer(1) << 20));
}

}  // namespace internal

std::string to_string(EdgeFamily family) {
  switch (family) {
    case EdgeFamily::kNormal:
      return "normal";
    case EdgeFamily::kMinus:
      return "n-mu*t";
    case EdgeFamily::kPlus:
      return "n+mu*t";
    case EdgeFamily::kWholeCone:
      return "friction cone";
  }
  return "?";
}

Vec2 push_direction(const Vec2& tangent, EdgeFamily family, const Rational& mu) {
  if (mu < 0) throw InputError("mu", to_string(mu), "must be >= 0 (a friction coefficient)");
  const Vec2 n = rot90(tangent);
  return internal::push_direction_from(n, rot90(n), family, mu);
}

bool WrenchCone::contains(const VectorQ& w) const {
  if (w.size() != 3) throw InputError("w", std::to_string(w.size()) + " components", "where 3 are needed (fx, fy, m)");
  for (const auto& a : facets)
    if (a.dot(w) < 0) return false;
  return true;
}

SegmentBounds segment_bounds(const BezierPiece& segment, bool with_hull) {
  SegmentBounds b;
  for (const auto& leg : segment.legs())
    if (!is_zero(leg)) b.legs.push_back(leg);
  if (b.legs.empty())
    throw SceneError("boundary[" + std::to_string(segment.curve) + "]",
                     "u in [" + to_string(segment.u0) + ", " + to_string(segment.u1) + "]",
                     "is a degenerate segment: all its control points coincide");
  if (with_hull) {
    std::vector<Kernel::Point_2> pts, hull;
    for (const auto& p : segment.control) pts.emplace_back(p.x, p.y);
    CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
    for (const auto& p : hull) b.hull.push_back({p.x(), p.y()});
  } else {
    b.hull = segment.control;
  }
  b.pointed = direction_extremes(b.legs, b.t_start, b.t_end);
  return b;
}

std::optional<WrenchCone> segment_wrench_cone(const SegmentBounds& b, const Vec2& p_AoCm_A, EdgeFamily family,
                                              const Rational& mu, ConeMethod method, bool with_facets) {
  // A negative μ would swap the friction edges: every sub-segment's cone
  // would look unpointed, and a caller splitting on nullopt would never stop.
  if (mu < 0) throw InputError("mu", to_string(mu), "must be >= 0 (a friction coefficient)");
  if (!b.pointed) return std::nullopt;
  // Push directions are a fixed orientation-preserving linear image of the
  // tangent, so the extreme legs map to the extreme directions.
  Vec2 ds = push_direction(b.t_start, family, mu), de = push_direction(b.t_end, family, mu);
  if (family == EdgeFamily::kWholeCone) de = push_direction(b.t_end, EdgeFamily::kPlus, mu);
  const Rational span = cross(ds, de);
  if (span < 0 || (span == 0 && dot(ds, de) < 0)) return std::nullopt;  // friction widened it to π
  if (method == ConeMethod::kTight) return tight(b, p_AoCm_A, ds, de, with_facets);
  return paper(b, p_AoCm_A, ds, de, with_facets);
}

std::optional<WrenchCone> segment_wrench_cone(const BezierPiece& segment, const Vec2& p_AoCm_A, EdgeFamily family,
                                              const Rational& mu, ConeMethod method) {
  return segment_wrench_cone(segment_bounds(segment), p_AoCm_A, family, mu, method);
}

const char* to_string(ConeMethod method) { return method == ConeMethod::kPaper ? "paper" : "tight"; }

WrenchCone internal::corner_cone(const Vec2& r, const Vec2& d_in, const Vec2& d_out) {
  return finish({wrench(d_in, cross(r, d_in)), wrench(d_out, cross(r, d_out))}, true);
}

}  // namespace fixel
