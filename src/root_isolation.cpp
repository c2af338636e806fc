// Real root isolation behind include/fixel/internal/root_isolation.h. The
// only file that uses FLINT and Arb (docs/theory.md §12): FLINT factors
// each polynomial into irreducible integer factors (so rational roots come
// from the linear factors, exactly, and every other root has its minimal
// polynomial), and Arb's arb_fmpz_poly_complex_roots isolates the roots of
// each irreducible factor with certified disjoint enclosures, real roots
// with an imaginary part of exactly zero.
#include "fixel/internal/root_isolation.h"

#include <arb_fmpz_poly.h>
#include <flint/fmpq.h>
#include <flint/fmpq_poly.h>
#include <flint/fmpz.h>
#include <flint/fmpz_poly.h>
#include <flint/fmpz_poly_factor.h>

#include <algorithm>

#include "fixel/error.h"
#include "fixel/internal/flint_thread.h"
#include "fixel/internal/polynomial.h"

namespace fixel::internal {

namespace {

// RAII wrappers for the FLINT types used here.
struct ZPoly {
  fmpz_poly_t p;
  ZPoly() { fmpz_poly_init(p); }
  ZPoly(const ZPoly&) = delete;
  ZPoly& operator=(const ZPoly&) = delete;
  ~ZPoly() { fmpz_poly_clear(p); }
};
struct QPoly {
  fmpq_poly_t p;
  QPoly() { fmpq_poly_init(p); }
  QPoly(const QPoly&) = delete;
  QPoly& operator=(const QPoly&) = delete;
  ~QPoly() { fmpq_poly_clear(p); }
};

void to_flint(const std::vector<Integer>& c, fmpz_poly_t out) {
  fmpz_poly_zero(out);
  fmpz_t t;
  fmpz_init(t);
  for (std::size_t i = 0; i < c.size(); ++i) {
    fmpz_set_mpz(t, c[i].backend().data());
    fmpz_poly_set_coeff_fmpz(out, static_cast<slong>(i), t);
  }
  fmpz_clear(t);
}

std::vector<Integer> from_flint(const fmpz_poly_t p) {
  std::vector<Integer> out(static_cast<std::size_t>(fmpz_poly_length(p)));
  for (slong i = 0; i < fmpz_poly_length(p); ++i) fmpz_get_mpz(out[i].backend().data(), fmpz_poly_get_coeff_ptr(p, i));
  return out;
}

void to_flint(const Polynomial& p, fmpq_poly_t out) {
  fmpq_poly_zero(out);
  for (std::size_t i = 0; i < p.size(); ++i) fmpq_poly_set_coeff_mpq(out, static_cast<slong>(i), p[i].backend().data());
}

Rational from_arf(const arf_t x) {
  fmpq_t q;
  fmpq_init(q);
  arf_get_fmpq(q, x);
  Rational r;
  fmpq_get_mpq(r.backend().data(), q);
  fmpq_clear(q);
  return r;
}

void bisect(AlgebraicReal& x) { split_at(x, (x.lo + x.hi) / 2); }

// Descartes' rule on (0, 1): the sign variations of the coefficients of
// (1 + t)^n f(1/(1 + t)) bound the number of roots of f in (0, 1) from
// above. Zero variations prove that f has no root there (an exclusion test
// only; isolation is Arb's).
bool may_have_root_in_unit_interval(const fmpz_poly_t f) {
  ZPoly q;
  fmpz_poly_reverse(q.p, f, fmpz_poly_length(f));  // x^n f(1/x)
  fmpz_t one;
  fmpz_init_set_ui(one, 1);
  fmpz_poly_taylor_shift(q.p, q.p, one);  // evaluated at x = 1 + t
  fmpz_clear(one);
  int variations = 0, last = 0;
  for (slong i = 0; i < fmpz_poly_length(q.p); ++i) {
    const int s = fmpz_sgn(fmpz_poly_get_coeff_ptr(q.p, i));
    if (s == 0) continue;
    if (last != 0 && s != last) ++variations;
    last = s;
  }
  return variations > 0;
}

constexpr int kMaxBisections = 100000;  // far above what distinct roots of these degrees need

// The real roots of one irreducible factor f (degree >= 2) inside (a, b).
void irrational_roots(const fmpz_poly_t f, const Rational& a, const Rational& b, std::vector<AlgebraicReal>& out) {
  const slong deg = fmpz_poly_degree(f);
  acb_ptr roots = _acb_vec_init(deg);
  arb_fmpz_poly_complex_roots(roots, f, 0, 64);
  const std::vector<Integer> coeffs = from_flint(f);
  arf_t bound;
  arf_init(bound);
  for (slong i = 0; i < deg; ++i) {
    if (!arb_is_zero(acb_imagref(roots + i))) continue;  // real roots come first, imaginary part exactly 0
    AlgebraicReal x;
    x.poly = coeffs;
    arb_get_lbound_arf(bound, acb_realref(roots + i), ARF_PREC_EXACT);
    x.lo = from_arf(bound);
    arb_get_ubound_arf(bound, acb_realref(roots + i), ARF_PREC_EXACT);
    x.hi = from_arf(bound);
    if (!(x.lo < x.hi) || sign_at(x.poly, x.lo) * sign_at(x.poly, x.hi) >= 0)
      throw InternalError("root isolation: Arb returned a real enclosure without a sign change");
    int steps = 0;
    while (!(x.hi <= a || x.lo >= b || (x.lo >= a && x.hi <= b))) {
      if (++steps > kMaxBisections) throw InternalError("root isolation: bisection limit against the range");
      bisect(x);
    }
    if (x.lo >= a && x.hi <= b) out.push_back(std::move(x));
  }
  arf_clear(bound);
  _acb_vec_clear(roots, deg);
}

}  // namespace

std::vector<AlgebraicReal> real_roots(const std::vector<Polynomial>& polys, const Rational& a, const Rational& b) {
  free_flint_caches_at_thread_exit();
  if (!(a < b)) throw InputError("interval", to_string(a) + ", " + to_string(b), "must have a < b");
  std::vector<std::vector<Integer>> factors;  // distinct irreducible factors, positive leading coefficient
  const bool unit = a == 0 && b == 1;         // Descartes' exclusion test applies
  ZPoly f;
  fmpz_poly_factor_t fac;
  fmpz_poly_factor_init(fac);
  for (const auto& p : polys) {
    const std::vector<Integer> c = primitive_integer(p);
    if (c.size() < 2) continue;  // zero or constant
    to_flint(c, f.p);
    if (unit && !may_have_root_in_unit_interval(f.p)) continue;
    fmpz_poly_factor(fac, f.p);
    for (slong i = 0; i < fac->num; ++i) {
      std::vector<Integer> g = from_flint(fac->p + i);
      if (g.back() < 0)
        for (auto& x : g) x = -x;
      if (std::find(factors.begin(), factors.end(), g) == factors.end()) factors.push_back(std::move(g));
    }
  }
  fmpz_poly_factor_clear(fac);
  std::vector<AlgebraicReal> roots;
  for (const auto& g : factors) {
    if (g.size() == 2) {
      const Rational r = Rational(-g[0]) / Rational(g[1]);
      if (r > a && r < b) roots.push_back(AlgebraicReal::rational(r));
      continue;
    }
    to_flint(g, f.p);
    if (unit && !may_have_root_in_unit_interval(f.p)) continue;
    irrational_roots(f.p, a, b, roots);
  }
  // Order the roots: all are distinct, so refining overlapping neighbours
  // until their intervals are disjoint terminates.
  for (int round = 0;; ++round) {
    if (round > kMaxBisections) throw InternalError("root isolation: could not separate the roots");
    std::sort(roots.begin(), roots.end(), [](const AlgebraicReal& x, const AlgebraicReal& y) {
      return x.lo < y.lo || (x.lo == y.lo && x.hi < y.hi);
    });
    bool separated = true;
    for (std::size_t i = 0; i + 1 < roots.size(); ++i) {
      if (roots[i].hi < roots[i + 1].lo) continue;
      separated = false;
      if (roots[i].is_rational() && roots[i + 1].is_rational())
        throw InternalError("root isolation: two distinct factors share a rational root");
      if (!roots[i].is_rational()) bisect(roots[i]);
      if (!roots[i + 1].is_rational()) bisect(roots[i + 1]);
    }
    if (separated) break;
  }
  return roots;
}

bool is_root(const AlgebraicReal& x, const Polynomial& p) {
  free_flint_caches_at_thread_exit();
  const std::vector<Integer> c = primitive_integer(p);
  if (c.empty()) return true;
  if (x.is_rational()) return sign_at(c, x.lo) == 0;
  ZPoly P, M, G;
  to_flint(c, P.p);
  to_flint(x.poly, M.p);
  fmpz_poly_gcd(G.p, P.p, M.p);  // M irreducible: p(x) = 0 iff M divides p
  return fmpz_poly_degree(G.p) == fmpz_poly_degree(M.p);
}

Polynomial gcd(const Polynomial& p, const Polynomial& q) {
  free_flint_caches_at_thread_exit();
  QPoly P, Q, G;
  to_flint(p, P.p);
  to_flint(q, Q.p);
  fmpq_poly_gcd(G.p, P.p, Q.p);
  Polynomial out(static_cast<std::size_t>(fmpq_poly_length(G.p)));
  for (slong i = 0; i < fmpq_poly_length(G.p); ++i) fmpq_poly_get_coeff_mpq(out[i].backend().data(), G.p, i);
  return out;
}

}  // namespace fixel::internal
