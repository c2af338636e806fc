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

// feasible_mixed: rows on enclosures, some with their exact forms. Random
// homogeneous systems over Q(√2) whose K-like rows come in mirrored pairs
// ((a, b, c) and (−a, d, −c): eliminating the third unknown cancels the
// first exactly, which no enclosure shows). With every row exact the
// answer is always decided and is the exact elimination's; with the
// mirrored rows' exact forms withheld the same systems stay open at least
// once, and never give another answer.
GTEST_TEST(FourierMotzkin, MixedRowsSettleZerosAmongExactRowsOnly) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<int> small(1, 9);
  auto q = [&](int lo_sign) { return Q2(Rational(lo_sign * small(rng), small(rng))); };
  auto irrational = [&] { return Q2(Rational(small(rng), 7), Rational(small(rng), 11), Rational(2)); };
  int decided_only_with_exact = 0, feasible = 0;
  const int systems = 300;
  for (int k = 0; k < systems; ++k) {
    std::vector<internal::A3<Q2>> exact_rows;
    const Q2 a = irrational(), c = q(1);
    exact_rows.push_back({a, q(1), c});
    exact_rows.push_back({-a, q(-1), -c});
    for (int extra = 0; extra < 1 + k % 3; ++extra) exact_rows.push_back({q(rng() % 2 ? 1 : -1), irrational(), q(1)});
    std::vector<Row<Q2>> rows;
    for (std::size_t r = 0; r < exact_rows.size(); ++r) rows.push_back({exact_rows[r], Q2(0), r < 2 || rng() % 2 == 0});
    const bool expected = internal::feasible(rows);
    feasible += expected;
    static const Q2 zero(0);
    auto mixed = [&](bool withhold_mirrored) {
      std::vector<internal::MixedRow> out;
      for (std::size_t r = 0; r < rows.size(); ++r) {
        const auto& x = exact_rows[r];
        internal::MixedRow m{
            {internal::to_interval_q2(x[0]), internal::to_interval_q2(x[1]), internal::to_interval_q2(x[2])},
            internal::FI(0),
            rows[r].strict};
        if (!(withhold_mirrored && r < 2)) {
          m.exact_a = &exact_rows[r];
          m.exact_b = &zero;
        }
        out.push_back(m);
      }
      return out;
    };
    ASSERT_EQ(internal::feasible_mixed(mixed(false)), expected) << "system " << k;
    try {
      ASSERT_EQ(internal::feasible_mixed(mixed(true)), expected) << "system " << k << ", mirrored rows withheld";
    } catch (const internal::Undecided&) {
      ++decided_only_with_exact;
    }
  }
  EXPECT_GT(decided_only_with_exact, 0);
  EXPECT_GT(feasible, 0);
  EXPECT_LT(feasible, systems);
}

}  // namespace
}  // namespace fixel
