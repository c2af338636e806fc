#include "fixel/internal/cone3.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/filter.h"
#include "fixel/internal/exact_lp.h"

namespace fixel {
namespace {

using internal::Q2;
using internal::Row;

// Second method for a homogeneous system {a·x ≥ 0 (closed), a·x > 0
// (strict)}: an exact LP. Maximise t subject to a·x ≥ t on the strict
// rows, a·x ≥ 0 on the closed ones, −1 ≤ x_k ≤ 1 and t ≤ 1 (x = 0, t = 0
// is always feasible). The system is feasible iff it has no strict row, or
// the optimum t is positive (a solution scaled into the box keeps its signs).
bool feasible_by_lp(const std::vector<std::array<int, 3>>& a, const std::vector<bool>& strict) {
  using internal::LinearConstraint;
  using internal::Relation;
  std::vector<LinearConstraint> constraints;
  bool any_strict = false;
  for (std::size_t r = 0; r < a.size(); ++r) {
    VectorQ row(4);
    row << a[r][0], a[r][1], a[r][2], strict[r] ? -1 : 0;
    constraints.push_back({row, Relation::kGreaterEqual, Rational(0)});
    any_strict = any_strict || strict[r];
  }
  for (int k = 0; k < 4; ++k) {
    VectorQ e = VectorQ::Zero(4);
    e[k] = 1;
    constraints.push_back({e, Relation::kLessEqual, Rational(1)});
    if (k < 3) constraints.push_back({e, Relation::kGreaterEqual, Rational(-1)});
  }
  if (!any_strict) return true;
  VectorQ c = VectorQ::Zero(4);
  c[3] = -1;  // minimise −t
  const internal::LpResult lp = internal::solve_lp(4, constraints, c);
  EXPECT_EQ(lp.status, internal::LpStatus::kOptimal);
  return lp.value < 0;
}

// Small integer rows, with repeated, opposite and zero rows and zero
// entries, so that eliminations cancel exactly: Fourier–Motzkin exact, on
// enclosures (by value and by reference) and the LP agree on every system,
// and both answers occur often, with strict and closed rows.
GTEST_TEST(FourierMotzkin, HomogeneousSystemsAgreeWithAnExactLinearProgram) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> entry(-2, 2);
  ForceExactScope filtered(false);
  int feasible = 0, infeasible_with_strict_pairs = 0;
  const int systems = 600;
  for (int k = 0; k < systems; ++k) {
    const std::size_t n = 2 + static_cast<std::size_t>(k % 8);
    std::vector<std::array<int, 3>> a(n);
    std::vector<bool> strict(n);
    for (std::size_t r = 0; r < n; ++r) {
      const int kind = static_cast<int>(rng() % 6);
      if (r > 0 && kind == 0) {
        a[r] = a[rng() % r];  // a repeat
      } else if (r > 0 && kind == 1) {
        const auto& q = a[rng() % r];  // an opposite row
        a[r] = {-q[0], -q[1], -q[2]};
      } else {
        a[r] = {entry(rng), entry(rng), entry(rng)};
      }
      strict[r] = rng() % 3 == 0;
    }
    std::vector<Row<Q2>> rows(n);
    for (std::size_t r = 0; r < n; ++r) {
      rows[r].a = {Q2(Rational(a[r][0])), Q2(Rational(a[r][1])), Q2(Rational(a[r][2]))};
      rows[r].b = Q2(0);
      rows[r].strict = strict[r];
    }
    std::vector<internal::RowRef<Q2>> refs;
    for (const auto& r : rows) refs.push_back({&r.a, r.strict});
    const bool expected = feasible_by_lp(a, strict);
    ASSERT_EQ(internal::feasible(rows), expected) << "system " << k;
    ASSERT_EQ(internal::feasible_filtered(rows), expected) << "system " << k;
    ASSERT_EQ(internal::feasible_filtered(refs), expected) << "system " << k << " by reference";
    feasible += expected;
    // Infeasible although no strict row is zero on its own and no two rows
    // are opposite: the elimination's later steps decide it.
    bool trivial = false;
    for (std::size_t r = 0; r < n; ++r) {
      trivial = trivial || (strict[r] && a[r] == std::array<int, 3>{0, 0, 0});
      for (std::size_t q = 0; q < r; ++q)
        trivial = trivial || ((strict[r] || strict[q]) && a[q] == std::array<int, 3>{-a[r][0], -a[r][1], -a[r][2]});
    }
    infeasible_with_strict_pairs += !expected && !trivial;
  }
  EXPECT_GT(feasible, systems / 5);
  EXPECT_LT(feasible, systems * 4 / 5);
  EXPECT_GT(infeasible_with_strict_pairs, systems / 10);
}

}  // namespace
}  // namespace fixel
