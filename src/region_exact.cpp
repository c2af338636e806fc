// The exact pushing region (docs/theory.md §12): along a Bézier piece the
// push wrenches are polynomial in the local parameter s, the target names
// the polynomials whose signs decide its point test, their real roots in
// (0, 1) are isolated exactly (internal/root_isolation.h), and one exact
// point test between consecutive roots gives each stretch its status.
#include "fixel/internal/region_exact.h"

#include "fixel/error.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/root_isolation.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal {

namespace {

// Coefficient k of a polynomial, 0 past its end.
Rational coeff(const Polynomial& p, std::size_t k) { return k < p.size() ? p[k] : Rational(0); }

// The push direction of a family as a polynomial vector: push_direction is
// linear in the tangent, so it applies coefficient by coefficient.
Vec2P direction(const Vec2P& T, EdgeFamily f, const Rational& mu) {
  Vec2P d;
  const std::size_t n = std::max(T.x.size(), T.y.size());
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 v = push_direction({coeff(T.x, k), coeff(T.y, k)}, f, mu);
    d.x.push_back(v.x);
    d.y.push_back(v.y);
  }
  trim(d.x);
  trim(d.y);
  return d;
}

// The end of a stretch in the curve parameter u = u0 + s (u1 − u0).
void set_end(const AlgebraicReal& s, const BezierPiece& piece, Rational& u, std::optional<AlgebraicReal>& exact) {
  const AlgebraicReal x = affine_image(s, piece.u0, piece.u1 - piece.u0);
  u = x.midpoint();
  if (x.is_rational())
    exact.reset();
  else
    exact = x;
}

// The rational with the smallest denominator in the open interval (a, b),
// 0 <= a < b (continued fractions): test points with small numbers keep the
// exact point tests cheap.
Rational simplest_between(const Rational& a, const Rational& b) {
  const Integer n = numerator(a) / denominator(a);  // floor, a >= 0
  if (Rational(n + 1) < b) return Rational(n + 1);
  const Rational fa = a - Rational(n), fb = b - Rational(n);  // 0 <= fa < fb <= 1
  if (fa == 0) {
    const Rational inv = 1 / fb;
    return Rational(n) + Rational(1) / Rational(numerator(inv) / denominator(inv) + 1);
  }
  return Rational(n) + 1 / simplest_between(1 / fb, 1 / fa);
}

}  // namespace

std::vector<RegionInterval> exact_piece_intervals(const Scene& scene, RegionTarget& target, const BezierPiece& piece,
                                                  const Rational& mu, RegionStats& stats) {
  const Vec2P P = bezier_power_basis(piece.control);
  const Vec2P T{derivative(P.x), derivative(P.y)};
  const Vec2& c = scene.body.p_AoCm_A;
  const Polynomial rx = padd(P.x, Polynomial{-c.x}), ry = padd(P.y, Polynomial{-c.y});
  // The generators in test_point's order: d_first, d_last (n − μt, n + μt;
  // the normal twice for a frictionless pusher).
  std::vector<std::array<Polynomial, 3>> gens;
  const std::vector<EdgeFamily> fams = mu == 0 ? std::vector<EdgeFamily>{EdgeFamily::kNormal, EdgeFamily::kNormal}
                                               : std::vector<EdgeFamily>{EdgeFamily::kMinus, EdgeFamily::kPlus};
  for (auto f : fams) {
    const Vec2P d = direction(T, f, mu);
    gens.push_back({d.x, d.y, psub(pmul(rx, d.y), pmul(ry, d.x))});
  }
  std::vector<Polynomial> polys = target.sign_polynomials(gens);
  const Polynomial cusp = gcd(T.x, T.y);  // the tangent vanishes at its roots
  if (cusp.size() >= 2) polys.push_back(cusp);
  const std::vector<AlgebraicReal> roots = real_roots(polys, Rational(0), Rational(1));
  stats.roots += static_cast<long>(roots.size());

  // Ends s_0 = 0 < s_1 < … < s_k < s_{k+1} = 1; a rational test point
  // strictly inside each stretch (the isolating intervals are disjoint).
  std::vector<AlgebraicReal> ends{AlgebraicReal::rational(Rational(0))};
  for (const auto& r : roots) ends.push_back(r);
  ends.push_back(AlgebraicReal::rational(Rational(1)));
  std::vector<RegionInterval> out;
  const Rational L = piece.u1 - piece.u0;
  for (std::size_t i = 0; i + 1 < ends.size(); ++i) {
    const Rational t = simplest_between(ends[i].hi, ends[i + 1].lo);
    RegionInterval r{piece.curve, Rational(0), Rational(0), RegionStatus::kPartial, false, Magnitudes{}, {}, {}, {}};
    set_end(ends[i], piece, r.u0, r.exact_u0);
    set_end(ends[i + 1], piece, r.u1, r.exact_u1);
    ++stats.point_tests;
    Magnitudes m;
    r.status = point_status(scene, target, piece.curve, piece.u0 + t * L, mu, &m);
    if (r.status == RegionStatus::kPartial)
      throw InternalError("exact region: the point test is undecided between two roots");
    r.half_line = r.status == RegionStatus::kIn && (std::string(target.push_model()) == "sustained" || m.half_line());
    if (i > 0 && cusp.size() >= 2 && is_root(ends[i], cusp)) {
      RegionInterval point = r;
      point.u1 = point.u0;
      point.exact_u1 = point.exact_u0;
      point.status = RegionStatus::kPartial;
      point.half_line = false;
      out.push_back(point);
    }
    out.push_back(r);
  }
  return out;
}

}  // namespace fixel::internal
