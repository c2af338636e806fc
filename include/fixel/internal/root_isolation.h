#pragma once
// Real root isolation for the exact pushing region, behind one interface so
// that the library doing it (FLINT's factorisation and Arb's certified
// complex root isolation, docs/theory.md §12) stays in src/root_isolation.cpp.

#include <vector>

#include "fixel/algebraic.h"

namespace fixel::internal {

// The distinct real roots in the open interval (a, b), a < b, of the product
// of `polys` (zero and constant polynomials contribute none), in increasing
// order. Each root has its irreducible polynomial (AlgebraicReal) and an
// isolating interval inside (a, b); the intervals are pairwise disjoint
// (hi of one < lo of the next).
std::vector<AlgebraicReal> real_roots(const std::vector<Polynomial>& polys, const Rational& a, const Rational& b);

// p(x) == 0, exactly.
bool is_root(const AlgebraicReal& x, const Polynomial& p);

// The monic greatest common divisor of p and q over Q (zero if both are).
Polynomial gcd(const Polynomial& p, const Polynomial& q);

}  // namespace fixel::internal
