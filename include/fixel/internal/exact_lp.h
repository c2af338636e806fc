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

// Minimises c·x over free variables x ∈ R^n subject to the constraints.
// An empty c (size 0) asks only for feasibility.
LpResult solve_lp(int n, const std::vector<LinearConstraint>& constraints, const VectorQ& c = VectorQ());

}  // namespace fixel::internal
