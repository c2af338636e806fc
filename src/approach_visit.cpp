// The exact visit of a pair's family between t = 0 and t* (docs/theory.md
// §10.7): the roots of the polynomials, by FLINT and Arb root isolation,
// and the exact signs at the roots, at t* (in Q(√d)) and in the cells.
#include "fixel/internal/approach_visit.h"

#include <cmath>
#include <cstdio>

#include "fixel/error.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/internal/root_isolation.h"
#include "fixel/progress.h"

namespace fixel::internal {

namespace {

Q2 eval_q2(const Polynomial& p, const Q2& x) {
  Q2 v(0);
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + Q2(p[i]);
  return v;
}

// Sign of p at x. At an irrational root x of the polynomials' product, p
// either vanishes or has no root in x's isolating interval (the intervals of
// the product's roots are disjoint), so its sign there is its sign at the
// interval's midpoint.
int sign_at(const Polynomial& p, const Point& x, const Q2& t_star) {
  switch (x.kind) {
    case Point::kRational:
      return fixel::sign(peval(p, x.q));
    case Point::kRoot:
      return is_root(x.root, p) ? 0 : fixel::sign(peval(p, x.root.midpoint()));
    case Point::kStar:
      return sign(eval_q2(p, t_star));
  }
  return 0;
}

Rational upper(const Point& x) { return x.kind == Point::kRational ? x.q : x.root.hi; }
Rational lower(const Point& x) { return x.kind == Point::kRational ? x.q : x.root.lo; }

// Sign of a + √d·b at x. At a root of the visit, a, b and a² − d·b² each
// vanish there or have no root in its isolating interval (all three are
// among the visited polynomials), so their signs are sign_at's; where a
// and b have opposite signs, a + √d·b has a's sign iff a² > d·b².
int sign_at(const FieldPolynomial& p, const Polynomial& norm, const Point& x, const Q2& t_star, const Q2& root_d) {
  if (p.b.empty()) return sign_at(p.a, x, t_star);
  switch (x.kind) {
    case Point::kRational:
      return sign(Q2(peval(p.a, x.q)) + root_d * Q2(peval(p.b, x.q)));
    case Point::kStar:
      return sign(eval_q2(p.a, t_star) + root_d * eval_q2(p.b, t_star));
    case Point::kRoot: {
      const int sa = sign_at(p.a, x, t_star), sb = sign_at(p.b, x, t_star);
      if (sa == 0 || sb == 0 || sa == sb) return sa != 0 ? sa : sb;
      return sa * sign_at(norm, x, t_star);
    }
  }
  return 0;
}

}  // namespace

// Visits the closed interval between 0 and t*, from 0 towards t*: every
// point where a sign of `polys` may change, and one rational point inside
// each open cell between two such points (where every sign is constant).
// Returns the first point where `pred` is true.
std::optional<Point> first_point(const std::vector<FieldPolynomial>& polys, const ApproachData& d,
                                 const std::function<bool(const Signs&)>& pred) {
  const QuadraticIrrational& ts = d.t_star;
  const Q2 t_star = from_public(ts);
  // √d, and each field polynomial's norm a² − d·b² (its roots and its
  // conjugate's), whose roots join the visit with a's and b's.
  Q2 root_d(0);
  std::vector<Polynomial> norms(polys.size()), all;
  for (std::size_t k = 0; k < polys.size(); ++k) {
    all.push_back(polys[k].a);
    if (polys[k].b.empty()) continue;
    if (ts.b == 0) throw InternalError("approach: a wrench in Q(sqrt d) at a seat with a rational rotation");
    root_d = Q2(Rational(0), Rational(1), ts.d);
    norms[k] = psub(pmul(polys[k].a, polys[k].a), pscale(pmul(polys[k].b, polys[k].b), ts.d));
    all.push_back(polys[k].b);
    all.push_back(norms[k]);
  }
  auto visit = [&](const Point& x) {
    poll_exact_step();
    std::vector<int> cache(polys.size(), 2);
    const Signs s = [&](std::size_t k) {
      if (cache[k] == 2) cache[k] = sign_at(polys[k], norms[k], x, t_star, root_d);
      return cache[k];
    };
    return pred(s);
  };
  Point zero;
  zero.q = 0;
  if (sign(t_star) == 0) {
    if (visit(zero)) return zero;
    return std::nullopt;
  }
  // t*'s own polynomial joins the list, so t* is one of the roots found.
  if (ts.b == 0)
    all.push_back({-ts.a, Rational(1)});
  else
    all.push_back({ts.a * ts.a - ts.b * ts.b * ts.d, -2 * ts.a, Rational(1)});
  const bool positive = sign(t_star) > 0;
  const std::vector<AlgebraicReal> roots =
      positive ? real_roots(all, Rational(0), d.t_hi) : real_roots(all, d.t_lo, Rational(0));
  std::size_t star = roots.size();
  for (std::size_t k = 0; k < roots.size() && star == roots.size(); ++k)
    if (sign(Q2(roots[k].lo) - t_star) <= 0 && sign(Q2(roots[k].hi) - t_star) >= 0) star = k;
  if (star == roots.size()) throw InternalError("approach: t* is not among the roots of its own polynomial");
  // The events in increasing order, then visited from 0 towards t*.
  std::vector<Point> events;
  auto as_point = [](const AlgebraicReal& r) {
    Point p;
    if (r.is_rational()) {
      p.q = r.lo;
    } else {
      p.kind = Point::kRoot;
      p.root = r;
    }
    return p;
  };
  Point star_point;
  star_point.kind = Point::kStar;
  star_point.root = roots[star];
  if (positive) {
    events.push_back(zero);
    for (std::size_t k = 0; k < star; ++k) events.push_back(as_point(roots[k]));
    events.push_back(star_point);
  } else {
    events.push_back(star_point);
    for (std::size_t k = star + 1; k < roots.size(); ++k) events.push_back(as_point(roots[k]));
    events.push_back(zero);
  }
  // Each root's interval lies in the open search interval, so it clears 0;
  // the check guards the cell samples against an interval touching it.
  for (std::size_t k = 0; k + 1 < events.size(); ++k)
    if (!(upper(events[k]) < lower(events[k + 1])))
      throw InternalError("approach: isolating intervals overlap at a cell of the family");
  const std::size_t n = events.size();
  for (std::size_t m = 0; m < n; ++m) {
    const std::size_t k = positive ? m : n - 1 - m;
    if (visit(events[k])) return events[k];
    if (m + 1 == n) break;
    const std::size_t next = positive ? k + 1 : k - 1;
    const std::size_t left = std::min(k, next);
    Point cell;
    cell.q = (upper(events[left]) + lower(events[left + 1])) / 2;
    if (visit(cell)) return cell;
  }
  return std::nullopt;
}

std::optional<Point> first_point(const std::vector<Polynomial>& polys, const ApproachData& d,
                                 const std::function<bool(const Signs&)>& pred) {
  std::vector<FieldPolynomial> field;
  field.reserve(polys.size());
  for (const auto& p : polys) field.push_back({p, {}});
  return first_point(field, d, pred);
}

std::string theta_text(double theta) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.4f", theta);
  return buf;
}

double theta_of(const Point& x, double theta_star) {
  if (x.kind == Point::kStar) return theta_star;
  const double t = x.kind == Point::kRational ? to_double(x.q) : x.root.approx();
  return 2 * std::atan(t);
}

}  // namespace fixel::internal
