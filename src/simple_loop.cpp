// Is the boundary loop simple? Segments exactly (CGAL's O(n log n) sweep, and
// an exact pairwise classification to name a witness); curved pieces by
// exact de Casteljau refinement of their control-polygon hulls.
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/boost_mp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "fixel/curve.h"
#include "fixel/error.h"

namespace fixel {

namespace {

// is_simple_2 uses predicates only, so both kernels decide exactly: Epick
// (statically filtered, fastest) when the coordinates scaled by a common
// denominator are exactly doubles, otherwise Epeck (interval-filtered GMP
// rationals).
using DoubleKernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using RationalKernel = CGAL::Exact_predicates_exact_constructions_kernel;

constexpr int kMaxDepth = 24;          // refinements of one pair before "undecided"
constexpr int kMaxMonotoneDepth = 16;  // splits of one piece into monotone sub-pieces
constexpr long kBudget = 400000;       // pair evaluations for the whole loop

int orient(const Vec2& a, const Vec2& b, const Vec2& c) { return sign(cross(sub(b, a), sub(c, a))); }
Vec2 along(const Vec2& p, const Vec2& d, const Rational& t) { return {p.x + t * d.x, p.y + t * d.y}; }
Rational at(const BezierPiece& piece, const Rational& s) { return piece.u0 + s * (piece.u1 - piece.u0); }

enum class Kind { kNone, kCross, kTouch, kUndecided };

// What was found about a pair of pieces; parameters and point are exact
// unless `approximate`.
struct Finding {
  Kind kind = Kind::kNone;
  int curve_a = 0, curve_b = 0;
  Rational u_a, u_b;
  Vec2 point;
  bool approximate = false;
};

Finding exact(Kind kind, const BezierPiece& a, const Rational& sa, const BezierPiece& b, const Rational& sb,
              const Vec2& point) {
  return {kind, a.curve, b.curve, at(a, sa), at(b, sb), point, false};
}

// The pair could only be located to the pieces a and b (small after refinement).
Finding near(Kind kind, const BezierPiece& a, const BezierPiece& b) {
  const Vec2 ta = sub(a.control.back(), a.control.front()), tb = sub(b.control.back(), b.control.front());
  const Rational c = cross(ta, tb);
  Vec2 point = along(b.control.front(), sub(b.control.back(), b.control.front()), Rational(1, 2));
  if (c != 0) point = along(a.control.front(), ta, cross(sub(b.control.front(), a.control.front()), tb) / c);
  const Rational half(1, 2);
  return {kind, a.curve, b.curve, at(a, half), at(b, half), point, true};
}

bool disjoint_along(const Vec2& axis, const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  auto range = [&](const std::vector<Vec2>& S) {
    Rational lo = dot(axis, S[0]), hi = lo;
    for (std::size_t i = 1; i < S.size(); ++i) {
      const Rational d = dot(axis, S[i]);
      if (d < lo) lo = d;
      if (hi < d) hi = d;
    }
    return std::make_pair(lo, hi);
  };
  const auto p = range(P), q = range(Q);
  return p.second < q.first || q.second < p.first;
}

// Separating-axis test on the control polygons' convex hulls: the axes are
// the directions and normals of every pair of control points (a superset of
// the hull edges). True only for a strict separation.
bool separated(const std::vector<Vec2>& P, const std::vector<Vec2>& Q) {
  for (const auto* S : {&P, &Q})
    for (std::size_t i = 0; i < S->size(); ++i)
      for (std::size_t j = i + 1; j < S->size(); ++j) {
        const Vec2 e = sub((*S)[j], (*S)[i]);
        if (is_zero(e)) continue;
        if (disjoint_along(e, P, Q) || disjoint_along({-e.y, e.x}, P, Q)) return true;
      }
  return false;
}

// Proves that b meets a: a is monotone along its chord, b's hull lies in the
// open strip over that chord, and b starts strictly on one side of a's fat
// line (the band holding a's hull) and ends strictly on the other.
bool proves_crossing(const BezierPiece& a, const BezierPiece& b) {
  const Vec2 A0 = a.control.front(), t = sub(a.control.back(), A0);
  if (is_zero(t)) return false;
  for (const auto& leg : a.legs())
    if (dot(leg, t) < 0) return false;
  const Rational len2 = dot(t, t);
  for (const auto& q : b.control) {
    const Rational d = dot(sub(q, A0), t);
    if (!(0 < d && d < len2)) return false;
  }
  const Vec2 n{-t.y, t.x};
  Rational lo = 0, hi = 0;
  for (const auto& q : a.control) {
    const Rational d = dot(sub(q, A0), n);
    if (d < lo) lo = d;
    if (hi < d) hi = d;
  }
  const Rational h0 = dot(sub(b.control.front(), A0), n), h1 = dot(sub(b.control.back(), A0), n);
  return (h0 < lo && hi < h1) || (hi < h0 && h1 < lo);
}

// Two segments that are not consecutive along the loop, exactly.
Finding segments(const BezierPiece& a, const BezierPiece& b) {
  const Vec2 &p0 = a.control[0], &p1 = a.control[1], &q0 = b.control[0], &q1 = b.control[1];
  const Vec2 r = sub(p1, p0), w = sub(q1, q0);
  const int o1 = orient(p0, p1, q0), o2 = orient(p0, p1, q1), o3 = orient(q0, q1, p0), o4 = orient(q0, q1, p1);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    const Rational c = cross(r, w), t = cross(sub(q0, p0), w) / c, s = cross(sub(q0, p0), r) / c;
    return exact(Kind::kCross, a, t, b, s, along(p0, r, t));
  }
  // Touching: an endpoint of one lies on the other (closed) segment.
  auto on = [](const Vec2& x, const Vec2& y0, const Vec2& d, int o, Rational* t) {
    if (o != 0) return false;
    *t = dot(sub(x, y0), d) / dot(d, d);
    return 0 <= *t && *t <= 1;
  };
  Rational t;
  if (on(q0, p0, r, o1, &t)) return exact(Kind::kTouch, a, t, b, 0, q0);
  if (on(q1, p0, r, o2, &t)) return exact(Kind::kTouch, a, t, b, 1, q1);
  if (on(p0, q0, w, o3, &t)) return exact(Kind::kTouch, a, 0, b, t, p0);
  if (on(p1, q0, w, o4, &t)) return exact(Kind::kTouch, a, 1, b, t, p1);
  return {};
}

class Checker {
 public:
  // Two pieces that are not consecutive along the loop.
  Finding general(const BezierPiece& a, const BezierPiece& b, int depth) {
    if (--budget_ < 0) return near(Kind::kUndecided, a, b);
    if (a.degree() == 1 && b.degree() == 1) return segments(a, b);
    if (separated(a.control, b.control)) return {};
    if (proves_crossing(a, b) || proves_crossing(b, a)) return near(Kind::kCross, a, b);
    if (depth >= kMaxDepth) return near(Kind::kUndecided, a, b);
    // Off-centre, so that a crossing at a symmetric parameter (often s = 1/2)
    // does not stay on the children's ends, where no strip test can prove it.
    const Rational kSplit(15, 32);
    const auto [a1, a2] = a.split(kSplit);
    const auto [b1, b2] = b.split(kSplit);
    for (const auto* x : {&a1, &a2})
      for (const auto* y : {&b1, &b2}) {
        Finding f = general(*x, *y, depth + 1);
        if (f.kind != Kind::kNone) return f;
      }
    return {};
  }

  // a ends where b starts, at P: they must meet only there. Proven by a line
  // through P with a strictly on one side (but at P) and b on the other.
  Finding adjacent(const BezierPiece& a, const BezierPiece& b, int depth) {
    const Vec2 P = a.control.back();
    if (--budget_ < 0) return exact(Kind::kUndecided, a, 1, b, 0, P);
    Vec2 d1, d2;
    for (auto it = a.control.rbegin(); it != a.control.rend() && is_zero(d1); ++it) d1 = sub(P, *it);
    for (auto it = b.control.begin(); it != b.control.end() && is_zero(d2); ++it) d2 = sub(*it, P);
    const Rational c = cross(d1, d2);
    if (a.degree() == 1 && b.degree() == 1)  // a segment doubling back over the previous one
      return c == 0 && dot(d1, d2) < 0 ? exact(Kind::kTouch, a, 1, b, 0, P) : Finding{};
    if (c != 0 || dot(d1, d2) > 0) {
      const Vec2 n = c > 0 ? Vec2{d2.y - d1.y, d1.x - d2.x} : c < 0 ? Vec2{d1.y - d2.y, d2.x - d1.x} : d1;
      bool ok = dot(sub(a.control.front(), P), n) < 0 && dot(sub(b.control.back(), P), n) > 0;
      for (const auto& q : a.control) ok = ok && dot(sub(q, P), n) <= 0;
      for (const auto& q : b.control) ok = ok && dot(sub(q, P), n) >= 0;
      if (ok) return {};
    }
    if (depth >= kMaxDepth) return exact(Kind::kUndecided, a, 1, b, 0, P);
    const Rational half(1, 2);
    const auto [a_far, a_near] = a.split(half);
    const auto [b_near, b_far] = b.split(half);
    for (const auto& [x, y] :
         {std::make_pair(&a_far, &b_near), std::make_pair(&a_far, &b_far), std::make_pair(&a_near, &b_far)}) {
      Finding f = general(*x, *y, depth + 1);
      if (f.kind != Kind::kNone) return f;
    }
    return adjacent(a_near, b_near, depth + 1);
  }

 private:
  long budget_ = kBudget;
};

// True if the piece's derivative stays in an open half-plane, so that the
// piece cannot meet itself.
bool monotone(const BezierPiece& piece) {
  const auto legs = piece.legs();
  std::vector<Vec2> candidates = legs;
  candidates.push_back(sub(piece.control.back(), piece.control.front()));
  for (const auto& n : candidates) {
    if (is_zero(n)) continue;
    bool ok = true, positive = false;
    for (const auto& leg : legs) {
      const Rational d = dot(leg, n);
      ok = ok && d >= 0;
      positive = positive || d > 0;
    }
    if (ok && positive) return true;
  }
  return false;
}

std::string curve_name(const std::string& path, int k) { return path + "[" + std::to_string(k) + "]"; }

std::string number(const Rational& v, bool approximate) {
  if (!approximate) return to_string(v);
  std::ostringstream out;
  out.precision(6);
  out << to_double(v);
  return out.str();
}

void split_monotone(const BezierPiece& piece, int depth, const std::string& path, std::vector<BezierPiece>* out) {
  if (monotone(piece)) {
    out->push_back(piece);
    return;
  }
  if (depth >= kMaxMonotoneDepth)
    throw SceneError(curve_name(path, piece.curve),
                     "u ≈ " + number((piece.u0 + piece.u1) / 2, true) + " near (" + number(piece.control[0].x, true) +
                         ", " + number(piece.control[0].y, true) + ")",
                     "turns back on itself (a cusp?): the check that the boundary is a simple loop cannot decide "
                     "there; smooth the curve");
  const auto [left, right] = piece.split(Rational(1, 2));
  split_monotone(left, depth + 1, path, out);
  split_monotone(right, depth + 1, path, out);
}

[[noreturn]] void report(const Finding& f, const std::string& path) {
  const std::string eq = f.approximate ? " ≈ " : " = ";
  const std::string where = curve_name(path, f.curve_a) + " at u" + eq + number(f.u_a, f.approximate) + " and " +
                            curve_name(path, f.curve_b) + " at u" + eq + number(f.u_b, f.approximate);
  const std::string point = "(" + number(f.point.x, f.approximate) + ", " + number(f.point.y, f.approximate) + ")";
  const std::string rule = "; a part's boundary must be a simple loop";
  switch (f.kind) {
    case Kind::kCross:
      throw SceneError(path, where,
                       (f.approximate ? "cross near " : "cross at ") + point + ": the boundary crosses itself" + rule);
    case Kind::kTouch:
      throw SceneError(path, where, "meet at " + point + ": the boundary touches itself" + rule);
    default:
      throw SceneError(path, where,
                       "come too close near " + point + " to be told apart after " + std::to_string(kMaxDepth) +
                           " exact refinements: the boundary touches or crosses itself there, or nearly so" + rule);
  }
}

// Conservative double bounds of a piece (for candidate pairs only; every
// decision is exact).
struct Box {
  double x0, x1, y0, y1;
};
Box box_of(const BezierPiece& piece) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Box b{inf, -inf, inf, -inf};
  for (const auto& p : piece.control) {
    const double x = to_double(p.x), y = to_double(p.y);
    b.x0 = std::min(b.x0, std::nextafter(x, -inf));
    b.x1 = std::max(b.x1, std::nextafter(x, inf));
    b.y0 = std::min(b.y0, std::nextafter(y, -inf));
    b.y1 = std::max(b.y1, std::nextafter(y, inf));
  }
  return b;
}

// The loop's vertices as exact doubles after scaling by the common
// denominator (simplicity is invariant under scaling), or empty if that is
// not possible.
std::vector<DoubleKernel::Point_2> scaled_double_vertices(const std::vector<BezierPiece>& pieces) {
  Integer scale = 1;
  const Integer limit = Integer(1) << 53;
  for (const auto& p : pieces)
    for (const Rational* c : {&p.control[0].x, &p.control[0].y}) {
      scale = boost::multiprecision::lcm(scale, boost::multiprecision::denominator(*c));
      if (scale > limit) return {};
    }
  std::vector<DoubleKernel::Point_2> out;
  out.reserve(pieces.size());
  for (const auto& p : pieces) {
    const Rational x = p.control[0].x * scale, y = p.control[0].y * scale;
    const double dx = to_double(x), dy = to_double(y);
    if (!std::isfinite(dx) || !std::isfinite(dy) || Rational(dx) != x || Rational(dy) != y) return {};
    out.emplace_back(dx, dy);
  }
  return out;
}

bool cgal_says_simple(const std::vector<BezierPiece>& pieces) {
  if (pieces.size() < 3) return false;
  for (const auto& p : pieces)
    if (p.degree() != 1) return false;
  const auto fast = scaled_double_vertices(pieces);
  if (!fast.empty()) return CGAL::is_simple_2(fast.begin(), fast.end(), DoubleKernel());
  std::vector<RationalKernel::Point_2> pts;
  pts.reserve(pieces.size());
  auto lazy = [](const Rational& v) { return RationalKernel::FT(RationalKernel::FT::ET(v.backend().data())); };
  for (const auto& p : pieces) pts.emplace_back(lazy(p.control[0].x), lazy(p.control[0].y));
  return CGAL::is_simple_2(pts.begin(), pts.end(), RationalKernel());
}

}  // namespace

void check_simple_loop(const std::vector<BezierPiece>& pieces, const std::string& path, RunControl* control) {
  const long total = static_cast<long>(pieces.size());
  // No piece would leave the halving below nothing to halve, forever.
  if (pieces.empty()) throw SceneError(path, "0 pieces", "has no Bezier pieces: an outline is a closed loop of them");
  poll(control, "load", 0, total, "pieces checked for crossings");
  if (cgal_says_simple(pieces)) return;  // the common all-segment case, O(n log n)

  std::vector<BezierPiece> parts;
  for (const auto& piece : pieces) split_monotone(piece, 0, path, &parts);
  while (parts.size() < 3) {  // so that only consecutive parts share a point
    std::vector<BezierPiece> halves;
    for (const auto& p : parts) {
      const auto [l, r] = p.split(Rational(1, 2));
      halves.push_back(l);
      halves.push_back(r);
    }
    parts = std::move(halves);
  }

  // Sweep the boxes along x; exact tests on the overlapping pairs.
  const std::size_t n = parts.size();
  std::vector<Box> boxes(n);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) {
    boxes[i] = box_of(parts[i]);
    order[i] = i;
  }
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return boxes[i].x0 < boxes[j].x0; });
  Checker checker;
  std::vector<std::size_t> active;
  long swept = 0;
  for (const std::size_t i : order) {
    if (swept++ % 256 == 0) poll(control, "load", swept - 1, static_cast<long>(n), "pieces swept for crossings");
    const Box& bi = boxes[i];
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t j) { return boxes[j].x1 < bi.x0; }),
                 active.end());
    for (const std::size_t j : active) {
      const Box& bj = boxes[j];
      if (bj.y1 < bi.y0 || bi.y1 < bj.y0) continue;
      Finding f;
      if ((i + 1) % n == j)
        f = checker.adjacent(parts[i], parts[j], 0);
      else if ((j + 1) % n == i)
        f = checker.adjacent(parts[j], parts[i], 0);
      else
        f = checker.general(std::min(i, j) == i ? parts[i] : parts[j], std::min(i, j) == i ? parts[j] : parts[i], 0);
      if (f.kind != Kind::kNone) report(f, path);
    }
    active.push_back(i);
  }
  if (pieces.size() >= 3 &&
      std::all_of(pieces.begin(), pieces.end(), [](const BezierPiece& p) { return p.degree() == 1; }))
    throw InternalError("check_simple_loop: CGAL::is_simple_2 rejects the polygon but no pair of its " +
                        std::to_string(pieces.size()) + " edges meets");
}

}  // namespace fixel
