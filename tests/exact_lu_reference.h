#pragma once
// The reference solution of a k×k integer system C·x = y for the lifting
// tests: Eigen's exact LU over the rationals, a second method.
#include <cstddef>

#include "fixel/internal/exact_lu.h"
#include "fixel/rational.h"

namespace fixel::test {

// x from C (row-major, k·k integers of any type Rational takes) and y;
// false when C is singular.
template <typename Entries, typename Rhs>
bool exact_lu_solution(int k, const Entries& c, const Rhs& y, VectorQ& x) {
  MatrixQ A(k, k);
  VectorQ b(k);
  for (int a = 0; a < k; ++a) {
    b[a] = Rational(y[a]);
    for (int j = 0; j < k; ++j) A(a, j) = Rational(c[static_cast<std::size_t>(a) * k + j]);
  }
  const auto lu = internal::exact_lu(A);
  if (!lu.isInvertible()) return false;
  x = lu.solve(b);
  return true;
}

}  // namespace fixel::test
