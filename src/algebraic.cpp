// Real algebraic numbers: exact comparison, refinement by bisection of an
// isolating interval, affine maps and certified decimals (docs/theory.md §12).
#include "fixel/algebraic.h"

#include "fixel/error.h"
#include "fixel/internal/polynomial.h"

namespace fixel {

using internal::sign_at;

namespace {

// A caller's x is checked where it enters (an irrational: degree >= 2,
// lo < hi, a sign change between them), and every bisection point first:
// a rational root there means x.poly is reducible, the caller's error (x
// made by real_roots never has one), so an InputError, not InternalError.
void check_isolating(const AlgebraicReal& x) {
  if (x.is_rational()) {
    // No polynomial: a rational, lo == hi (an interval would say nothing of which number).
    if (x.lo != x.hi)
      throw InputError("x", "[" + to_string(x.lo) + ", " + to_string(x.hi) + "]",
                       "has no polynomial, so it must be a rational with lo == hi (AlgebraicReal::rational)");
    return;
  }
  if (x.poly.size() < 3 || !(x.lo < x.hi) || sign_at(x.poly, x.lo) * sign_at(x.poly, x.hi) >= 0)
    throw InputError("x", "[" + to_string(x.lo) + ", " + to_string(x.hi) + "]",
                     "is not an isolating interval of an irrational root of x.poly (degree >= 2, a sign change "
                     "between lo and hi, and no other root there)");
}

void split_at(AlgebraicReal& x, const Rational& m) {
  const int s_m = sign_at(x.poly, m);
  if (s_m == 0)
    throw InputError("x.poly", "root " + to_string(m),
                     "has a rational root: it must be irreducible (as the exact region's ends are)");
  (s_m == sign_at(x.poly, x.lo) ? x.lo : x.hi) = m;
}

}  // namespace

AlgebraicReal AlgebraicReal::rational(const Rational& q) {
  AlgebraicReal x;
  x.lo = x.hi = q;
  return x;
}

double AlgebraicReal::approx() const { return to_double(midpoint()); }

int compare(const AlgebraicReal& x, const Rational& q) {
  check_isolating(x);
  if (x.is_rational()) return x.lo < q ? -1 : (x.lo > q ? 1 : 0);
  if (q <= x.lo) return 1;
  if (q >= x.hi) return -1;
  AlgebraicReal y = x;
  split_at(y, q);
  return y.lo == q ? 1 : -1;
}

AlgebraicReal refined(const AlgebraicReal& x, const Rational& width) {
  if (width <= 0) throw InputError("width", to_string(width), "must be > 0");
  check_isolating(x);
  AlgebraicReal y = x;
  if (y.is_rational()) return y;
  while (y.hi - y.lo > width) split_at(y, (y.lo + y.hi) / 2);
  return y;
}

std::vector<Integer> primitive_integer(const Polynomial& p) {
  Integer l = 1;
  for (const auto& c : p)
    if (c != 0) l = lcm(l, denominator(c));
  std::vector<Integer> out;
  Integer g = 0;
  for (const auto& c : p) {
    out.push_back(numerator(c) * (l / denominator(c)));
    g = gcd(g, out.back());
  }
  while (!out.empty() && out.back() == 0) out.pop_back();
  if (g != 0 && g != 1)
    for (auto& c : out) c /= g;
  return out;
}

AlgebraicReal affine_image(const AlgebraicReal& x, const Rational& a, const Rational& b) {
  if (b <= 0) throw InputError("b", to_string(b), "must be > 0");
  check_isolating(x);
  if (x.is_rational()) return AlgebraicReal::rational(a + b * x.lo);
  // y = a + b x ⇔ x = (y − a)/b: p(x) = Σ c_i ((y − a)/b)^i.
  Polynomial result, power{Rational(1)};
  const Polynomial lin{-a / b, Rational(1) / b};
  for (std::size_t i = 0; i < x.poly.size(); ++i) {
    if (i > 0) {
      Polynomial next(power.size() + 1, Rational(0));
      for (std::size_t k = 0; k < power.size(); ++k) {
        next[k] += power[k] * lin[0];
        next[k + 1] += power[k] * lin[1];
      }
      power = next;
    }
    if (result.size() < power.size()) result.resize(power.size(), Rational(0));
    for (std::size_t k = 0; k < power.size(); ++k) result[k] += power[k] * Rational(x.poly[i]);
  }
  AlgebraicReal y;
  y.poly = primitive_integer(result);
  if (!y.poly.empty() && y.poly.back() < 0)
    for (auto& c : y.poly) c = -c;
  y.lo = a + b * x.lo;
  y.hi = a + b * x.hi;
  return y;
}

std::string certified_decimal(const AlgebraicReal& x_in, int max_digits) {
  // Bounded: the digits cost quadratic time (100,000 take seconds).
  if (max_digits < 0 || max_digits > 100000)
    throw InputError("digits", std::to_string(max_digits), "must be in [0, 100000]");
  check_isolating(x_in);
  AlgebraicReal x = x_in;
  // An irrational x is not 0: shrink its interval to one side of 0.
  while (!x.is_rational() && x.lo < 0 && x.hi > 0) split_at(x, Rational(0));
  const bool negative = x.hi <= 0 && !(x.is_rational() && x.lo == 0);
  const Rational lo = negative ? -x.hi : x.lo, hi = negative ? -x.lo : x.hi;
  auto floor_scaled = [](const Rational& v, const Integer& scale) {
    const Rational s = v * scale;
    Integer q = numerator(s) / denominator(s);  // truncation = floor for v >= 0
    return q;
  };
  Integer scale = 1;
  int k = 0;
  Integer digits = floor_scaled(lo, scale);
  if (digits != floor_scaled(hi, scale)) return std::string(negative ? "-" : "") + "...";
  bool exact = x.is_rational() && Rational(digits) == lo * scale;
  while (!exact && k < max_digits) {
    const Integer next_scale = scale * 10;
    const Integer a = floor_scaled(lo, next_scale), b = floor_scaled(hi, next_scale);
    if (a != b) break;
    scale = next_scale;
    ++k;
    digits = a;
    exact = x.is_rational() && Rational(digits) == lo * scale;
  }
  std::string s = digits.str();
  if (k > 0) {
    if (static_cast<int>(s.size()) <= k) s = std::string(k + 1 - s.size(), '0') + s;
    s.insert(s.size() - k, ".");
  }
  return std::string(negative ? "-" : "") + s + (exact ? "" : "...");
}

}  // namespace fixel
