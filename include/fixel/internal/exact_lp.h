#pragma once
// Exact linear programming (CGAL's QP solver on Rational), kept behind a
// small interface so that CGAL stays in one source file.

#include <vector>

#include "fixel/rational.h"

namespace fixel::internal {

enum class Relation { kLessEqual, kEqual, kGreaterEqual };

struct LinearConstraint {
  VectorQ a;
  Relation rel;
  Rational b;  // a·x rel b
};

enum class LpStatus { kOptimal, kInfeasible, kUnbounded };

struct LpResult {
  LpStatus status = LpStatus::kInfeasible;
  VectorQ x;       // an optimal (or, for a feasibility problem, feasible) point
  Rational value;  // objective value at x
};

// Minimises c·x over x ∈ R^n subject to the constraints. Variables are
// free, except that with unit_box_from >= 0 each x_j with j >=
// unit_box_from lies in [0, 1] (bounds the solver handles without rows).
// An empty c (size 0) asks only for feasibility.
LpResult solve_lp(int n, const std::vector<LinearConstraint>& constraints, const VectorQ& c = VectorQ(),
                  int unit_box_from = -1);

}  // namespace fixel::internal
