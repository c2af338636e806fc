#include "fixel/internal/exact_lp.h"

#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/boost_mp.h>

namespace fixel::internal {

namespace {

// The least common multiple of the denominators of a row's entries and
// its right side, so that the row times it is integral.
Integer row_scale(const VectorQ& a, const Rational* b) {
  Integer l = 1;
  auto take = [&](const Rational& q) {
    const Integer d = boost::multiprecision::denominator(q);
    if (d != 1) l = boost::multiprecision::lcm(l, d);
  };
  for (int j = 0; j < a.size(); ++j) take(a[j]);
  if (b) take(*b);
  return l;
}

Integer scaled(const Rational& q, const Integer& l) {
  return boost::multiprecision::numerator(q) * (l / boost::multiprecision::denominator(q));
}

}  // namespace

LpResult solve_lp(int n, const std::vector<LinearConstraint>& constraints, const VectorQ& c, int unit_box_from) {
  // Variables free unless boxed (below). Each row is multiplied by
  // the positive lcm of its denominators (the same feasible set, the same
  // simplex path), so the solver runs on integers: CGAL's fraction-free
  // updates in Gmpz-like integers instead of a gcd per rational operation.
  CGAL::Quadratic_program<Integer> lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const auto& row = constraints[i];
    const int r = static_cast<int>(i);
    const Integer l = row_scale(row.a, &row.b);
    for (int j = 0; j < n; ++j)
      if (row.a[j] != 0) lp.set_a(j, r, scaled(row.a[j], l));
    lp.set_b(r, scaled(row.b, l));
    lp.set_r(r, row.rel == Relation::kLessEqual ? CGAL::SMALLER
                                                : (row.rel == Relation::kEqual ? CGAL::EQUAL : CGAL::LARGER));
  }
  if (unit_box_from >= 0)
    for (int j = unit_box_from; j < n; ++j) {
      lp.set_l(j, true, 0);
      lp.set_u(j, true, 1);
    }
  if (c.size()) {
    const Integer l = row_scale(c, nullptr);
    for (int j = 0; j < c.size(); ++j)
      if (c[j] != 0) lp.set_c(j, scaled(c[j], l));
  }

  const auto solution = CGAL::solve_linear_program(lp, Integer());
  LpResult result;
  if (solution.is_infeasible()) return result;
  if (solution.is_unbounded()) {
    result.status = LpStatus::kUnbounded;
    return result;
  }
  result.status = LpStatus::kOptimal;
  result.x = VectorQ::Zero(n);
  // Variables that appear nowhere are absent from CGAL's program; they stay 0.
  int j = 0;
  for (auto it = solution.variable_values_begin(); it != solution.variable_values_end() && j < n; ++it, ++j)
    result.x[j] = Rational(it->numerator(), it->denominator());
  result.value = c.size() ? c.dot(result.x) : Rational(0);
  return result;
}

}  // namespace fixel::internal
