#pragma once
// Small exact arithmetic on Polynomial (rational coefficients, power basis)
// for the sign polynomials of the exact region (docs/theory.md §12).

#include <array>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/error.h"
#include "fixel/geometry.h"

namespace fixel::internal {

inline void trim(Polynomial& p) {
  while (!p.empty() && p.back() == 0) p.pop_back();
}

inline Polynomial padd(const Polynomial& a, const Polynomial& b) {
  Polynomial r(std::max(a.size(), b.size()));
  for (std::size_t i = 0; i < a.size(); ++i) r[i] += a[i];
  for (std::size_t i = 0; i < b.size(); ++i) r[i] += b[i];
  trim(r);
  return r;
}

inline Polynomial pscale(const Polynomial& a, const Rational& s) {
  if (s == 0) return {};
  Polynomial r(a);
  for (auto& c : r) c *= s;
  return r;
}

inline Polynomial psub(const Polynomial& a, const Polynomial& b) { return padd(a, pscale(b, Rational(-1))); }

inline Polynomial pmul(const Polynomial& a, const Polynomial& b) {
  if (a.empty() || b.empty()) return {};
  Polynomial r(a.size() + b.size() - 1);
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i] != 0)
      for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  trim(r);
  return r;
}

inline Rational peval(const Polynomial& p, const Rational& x) {
  Rational v = 0;
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + p[i];
  return v;
}

// A planar vector of polynomials.
struct Vec2P {
  Polynomial x, y;
};

// Σ_k a_k w_k for a row a (length 3) and a wrench of polynomials.
inline Polynomial row_dot(const std::array<Rational, 3>& a, const std::array<Polynomial, 3>& w) {
  Polynomial r;
  for (int k = 0; k < 3; ++k) r = padd(r, pscale(w[k], a[k]));
  return r;
}

// The power-basis coordinates of a Bézier curve with control points P
// (local parameter s ∈ [0, 1]).
inline Vec2P bezier_power_basis(const std::vector<Vec2>& P) {
  const int n = static_cast<int>(P.size()) - 1;
  Vec2P out;
  out.x.assign(n + 1, Rational(0));
  out.y.assign(n + 1, Rational(0));
  // B_i^n(s) = C(n,i) s^i (1−s)^{n−i} = Σ_j C(n,j) C(j,i) (−1)^{j−i} s^j.
  std::vector<std::vector<Rational>> C(n + 1, std::vector<Rational>(n + 1, Rational(0)));
  for (int i = 0; i <= n; ++i) {
    C[i][0] = 1;
    for (int j = 1; j <= i; ++j) C[i][j] = C[i - 1][j - 1] + (j <= i - 1 ? C[i - 1][j] : Rational(0));
  }
  for (int i = 0; i <= n; ++i)
    for (int j = i; j <= n; ++j) {
      const Rational c = C[n][j] * C[j][i] * ((j - i) % 2 ? -1 : 1);
      out.x[j] += c * P[i].x;
      out.y[j] += c * P[i].y;
    }
  trim(out.x);
  trim(out.y);
  return out;
}

inline Polynomial derivative(const Polynomial& p) {
  Polynomial r;
  for (std::size_t i = 1; i < p.size(); ++i) r.push_back(p[i] * static_cast<long>(i));
  trim(r);
  return r;
}

// Sign of p(q) for integer coefficients: the homogenised value
// Σ c_i n^i d^(deg−i) (d > 0) has the sign of p(n/d).
inline int sign_at(const std::vector<Integer>& p, const Rational& q) {
  const Integer n = numerator(q), d = denominator(q);
  Integer v = 0, dpow = 1;
  // Horner in n with the powers of d accumulated from the top.
  for (std::size_t i = p.size(); i-- > 0;) {
    v = v * n + p[i] * dpow;
    dpow *= d;
  }
  return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

// One bisection step of an irrational x's isolating interval at
// m ∈ (lo, hi). m is never a root (x.poly is irreducible of degree >= 2).
inline void split_at(AlgebraicReal& x, const Rational& m) {
  const int s_lo = sign_at(x.poly, x.lo), s_m = sign_at(x.poly, m);
  if (s_lo == 0 || s_m == 0)
    throw InternalError("algebraic number: a rational root of an irreducible polynomial of degree >= 2");
  (s_m == s_lo ? x.lo : x.hi) = m;
}

}  // namespace fixel::internal
