#include "fixel/internal/exact_lp.h"

#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>
#include <CGAL/boost_mp.h>

namespace fixel::internal {

LpResult solve_lp(int n, const std::vector<LinearConstraint>& constraints, const VectorQ& c) {
  // All variables free: no lower or upper bounds.
  CGAL::Quadratic_program<Rational> lp(CGAL::SMALLER, false, 0, false, 0);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    const auto& row = constraints[i];
    const int r = static_cast<int>(i);
    for (int j = 0; j < n; ++j)
      if (row.a[j] != 0) lp.set_a(j, r, row.a[j]);
    lp.set_b(r, row.b);
    lp.set_r(r, row.rel == Relation::kLessEqual ? CGAL::SMALLER
                                                : (row.rel == Relation::kEqual ? CGAL::EQUAL : CGAL::LARGER));
  }
  for (int j = 0; j < c.size(); ++j)
    if (c[j] != 0) lp.set_c(j, c[j]);

  const auto solution = CGAL::solve_linear_program(lp, Rational());
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
    result.x[j] = it->numerator() / it->denominator();
  result.value = c.size() ? c.dot(result.x) : Rational(0);
  return result;
}

}  // namespace fixel::internal
