#include "fixel/polyhedron.h"

#include <algorithm>

#include "fixel/error.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/filtered.h"

namespace fixel {

namespace {

Halfspace normalised(const VectorQ& a, const Rational& c) {
  // Scale so that a is a primitive integer vector (positive factor).
  if (a.isZero()) return {a, c};
  const VectorQ p = primitive_direction(a);
  Rational factor = 0;
  for (int k = 0; k < a.size(); ++k)
    if (a[k] != 0) {
      factor = p[k] / a[k];
      break;
    }
  return {p, c * factor};
}

bool same_row(const Halfspace& x, const Halfspace& y) { return x.a == y.a && x.c == y.c; }

void add_unique(std::vector<Halfspace>& rows, const Halfspace& h) {
  for (const auto& r : rows)
    if (same_row(r, h)) return;
  rows.push_back(h);
}

// Rows with the same (primitive) normal: only the tightest matters; at equal
// offsets a strict row implies the closed one.
void drop_parallel_redundancy(Polyhedron& P) {
  auto tighter = [](const Halfspace& x, bool xs, const Halfspace& y, bool ys) {
    return x.c > y.c || (x.c == y.c && xs && !ys);
  };
  struct Row {
    Halfspace h;
    bool strict;
  };
  std::vector<Row> rows, kept;
  for (const auto& h : P.closed) rows.push_back({h, false});
  for (const auto& h : P.strict) rows.push_back({h, true});
  for (const auto& r : rows) {
    bool replaced = false, dominated = false;
    for (auto& k : kept) {
      if (k.h.a != r.h.a || r.h.a.isZero()) continue;
      if (tighter(r.h, r.strict, k.h, k.strict))
        k = r;
      else
        dominated = true;
      replaced = true;
      break;
    }
    if (!replaced && !dominated) kept.push_back(r);
  }
  P.closed.clear();
  P.strict.clear();
  for (const auto& k : kept) (k.strict ? P.strict : P.closed).push_back(k.h);
}

}  // namespace

void drop_constant_rows(Polyhedron& P) {
  bool infeasible = false;
  auto keep = [&](std::vector<Halfspace>& rows, bool strict) {
    std::vector<Halfspace> kept;
    for (const auto& h : rows) {
      if (!h.a.isZero()) {
        kept.push_back(h);
        continue;
      }
      // 0 >= c (or 0 > c): true for every p, or for none.
      if (strict ? !(h.c < 0) : h.c > 0) infeasible = true;
    }
    rows = std::move(kept);
  };
  keep(P.closed, false);
  keep(P.strict, true);
  if (!infeasible) return;
  P.closed = {Halfspace{VectorQ::Zero(P.dim), Rational(1)}};  // the canonical empty set, 0 >= 1
  P.strict.clear();
}

namespace {

// Every row's length is P.dim (≥ 0): a polyhedron built in code with dim
// left at its default, or rows of mixed lengths, is an InputError here,
// not a read past the end of a vector (field names the argument).
void check_rows(const Polyhedron& P, const char* field) {
  if (P.dim < 0) throw InputError(std::string(field) + ".dim", std::to_string(P.dim), "must be >= 0");
  const auto check = [&](const std::vector<Halfspace>& rows, const char* kind) {
    for (std::size_t k = 0; k < rows.size(); ++k)
      if (rows[k].a.size() != P.dim)
        throw InputError(std::string(field) + "." + kind + "[" + std::to_string(k) + "]",
                         std::to_string(rows[k].a.size()) + " components",
                         "but dim is " + std::to_string(P.dim) + " (set Polyhedron::dim to the rows' length)");
  };
  check(P.closed, "closed");
  check(P.strict, "strict");
}

void check_same_dim(const Polyhedron& Q, const Polyhedron& P) {
  check_rows(Q, "Q");
  check_rows(P, "P");
  if (Q.dim != P.dim)
    throw InputError("P.dim", std::to_string(P.dim), "but Q.dim is " + std::to_string(Q.dim) + ": one space is needed");
}

}  // namespace

bool Polyhedron::is_trivially_empty() const {
  return closed.size() == 1 && strict.empty() && closed[0].a.isZero() && closed[0].c > 0;
}

bool Polyhedron::contains(const VectorQ& p) const {
  if (p.size() != dim)
    throw InputError("p", std::to_string(p.size()) + " components", "where " + std::to_string(dim) + " are needed");
  for (const auto& h : closed)
    if (internal::affine_sign_filtered(h.a, h.c, p) < 0) return false;
  for (const auto& h : strict)
    if (internal::affine_sign_filtered(h.a, h.c, p) <= 0) return false;
  return true;
}

Polyhedron Polyhedron::intersect(const Polyhedron& other) const {
  check_same_dim(*this, other);
  Polyhedron out = *this;
  for (const auto& h : other.closed) add_unique(out.closed, h);
  for (const auto& h : other.strict) add_unique(out.strict, h);
  return out;
}

bool is_empty(const Polyhedron& P) {
  check_rows(P, "P");
  // Trivial rows (a = 0) decide themselves.
  for (const auto& h : P.closed)
    if (h.a.isZero() && h.c > 0) return true;
  for (const auto& h : P.strict)
    if (h.a.isZero() && h.c >= 0) return true;
  // Variables (p, t): closed rows a·p >= c; strict rows a·p − t >= c;
  // t <= 1; maximise t. Non-empty iff feasible and (no strict rows or t* > 0).
  const int n = P.dim + 1;
  std::vector<internal::LinearConstraint> rows;
  for (const auto& h : P.closed) {
    VectorQ a = VectorQ::Zero(n);
    a.head(P.dim) = h.a;
    rows.push_back({a, internal::Relation::kGreaterEqual, h.c});
  }
  for (const auto& h : P.strict) {
    VectorQ a = VectorQ::Zero(n);
    a.head(P.dim) = h.a;
    a[P.dim] = -1;
    rows.push_back({a, internal::Relation::kGreaterEqual, h.c});
  }
  VectorQ t = VectorQ::Unit(n, P.dim);
  rows.push_back({t, internal::Relation::kLessEqual, Rational(1)});
  const internal::LpResult lp = internal::solve_lp(n, rows, VectorQ(-t));
  if (lp.status == internal::LpStatus::kInfeasible) return true;
  if (P.strict.empty()) return false;
  return lp.status == internal::LpStatus::kOptimal && lp.x[P.dim] <= 0;
}

int affine_dimension(const Polyhedron& P) {
  if (is_empty(P)) return -1;
  // P is non-empty, so no strict row is tight everywhere, and a closed row
  // is an implicit equality iff it is tight on all of P's closure. One LP
  // over the closure maximises Σ s_k with a_k·p − s_k ≥ c_k, 0 ≤ s_k ≤ 1,
  // over the closed rows k still open to doubt: every row with s_k > 0 at
  // the optimum is not an equality, and an optimum of 0 makes all of them
  // equalities (docs/theory.md §9). Each LP that does not end the loop
  // settles at least one row, so there are at most as many LPs as rows.
  std::vector<std::size_t> doubtful;
  for (std::size_t k = 0; k < P.closed.size(); ++k)
    if (!P.closed[k].a.isZero()) doubtful.push_back(k);
  while (!doubtful.empty()) {
    const int m = static_cast<int>(doubtful.size()), n = P.dim + m;
    std::vector<internal::LinearConstraint> rows;
    auto add_row = [&](const Halfspace& h, int slack) {
      VectorQ a = VectorQ::Zero(n);
      a.head(P.dim) = h.a;
      if (slack >= 0) a[P.dim + slack] = -1;
      rows.push_back({a, internal::Relation::kGreaterEqual, h.c});
    };
    std::vector<int> slack_of(P.closed.size(), -1);
    for (int j = 0; j < m; ++j) slack_of[doubtful[j]] = j;
    for (std::size_t k = 0; k < P.closed.size(); ++k) add_row(P.closed[k], slack_of[k]);
    for (const auto& h : P.strict) add_row(h, -1);  // the closure's rows
    VectorQ objective = VectorQ::Zero(n);
    for (int j = 0; j < m; ++j) objective[P.dim + j] = -1;                        // minimise −Σ s
    const internal::LpResult lp = internal::solve_lp(n, rows, objective, P.dim);  // 0 <= s <= 1
    if (lp.status != internal::LpStatus::kOptimal)  // the closure of a non-empty P is feasible and s is bounded
      throw InternalError("affine_dimension: the slack LP of a non-empty polyhedron is not optimal");
    if (lp.value == 0) break;
    std::vector<std::size_t> left;
    for (int j = 0; j < m; ++j)
      if (lp.x[P.dim + j] == 0) left.push_back(doubtful[j]);
    doubtful = std::move(left);
  }
  std::vector<VectorQ> equalities;
  for (const std::size_t k : doubtful) equalities.push_back(P.closed[k].a);
  return P.dim - internal::exact_rank(equalities, P.dim);
}

std::vector<Polyhedron> subtract(const Polyhedron& Q, const Polyhedron& P) {
  check_same_dim(Q, P);
  // Rows of P in a fixed order: closed then strict.
  struct Row {
    Halfspace h;
    bool strict;
  };
  std::vector<Row> rows;
  for (const auto& h : P.closed) rows.push_back({h, false});
  for (const auto& h : P.strict) rows.push_back({h, true});
  std::vector<Polyhedron> out;
  Polyhedron prefix = Q;  // Q with rows 0..k−1 of P holding
  for (const auto& row : rows) {
    Polyhedron piece = prefix;
    // Violating a·p >= c is a·p < c, i.e. (−a)·p > −c; violating a·p > c is (−a)·p >= −c.
    const Halfspace flipped{VectorQ(-row.h.a), Rational(-row.h.c)};
    if (row.strict)
      add_unique(piece.closed, flipped);
    else
      add_unique(piece.strict, flipped);
    if (!is_empty(piece)) out.push_back(piece);
    if (row.strict)
      add_unique(prefix.strict, row.h);
    else
      add_unique(prefix.closed, row.h);
    if (is_empty(prefix)) break;  // nothing of Q is left inside P's remaining rows
  }
  return out;
}

Polyhedron project_out_x(const LiftedSystem& s) {
  const int nx = s.nx, np = s.np, n = nx + np;
  if (nx < 0 || np < 0) throw InputError(nx < 0 ? "nx" : "np", std::to_string(nx < 0 ? nx : np), "must be >= 0");
  const auto sized = [&](const char* field, long got, long want) {
    if (got != want) throw InputError(field, std::to_string(got), "but " + std::to_string(want) + " are needed");
  };
  if (s.A_eq.rows() > 0) sized("A_eq columns", s.A_eq.cols(), n);
  if (s.A_in.rows() > 0) sized("A_in columns", s.A_in.cols(), n);
  sized("b_eq entries", s.b_eq.size(), s.A_eq.rows());
  sized("b_in entries", s.b_in.size(), s.A_in.rows());
  sized("strict_in entries", static_cast<long>(s.strict_in.size()), s.A_in.rows());
  struct Row {
    VectorQ a;
    Rational b;
    bool strict;
  };
  std::vector<VectorQ> eq_a;
  std::vector<Rational> eq_b;
  for (int r = 0; r < s.A_eq.rows(); ++r) {
    eq_a.push_back(s.A_eq.row(r).transpose());
    eq_b.push_back(s.b_eq[r]);
  }
  std::vector<Row> in;
  for (int r = 0; r < s.A_in.rows(); ++r) in.push_back({s.A_in.row(r).transpose(), s.b_in[r], s.strict_in[r]});

  // Gaussian elimination of x through the equalities.
  std::vector<bool> used(eq_a.size(), false);
  std::vector<int> free_x;
  for (int j = 0; j < nx; ++j) {
    int pivot = -1;
    for (std::size_t r = 0; r < eq_a.size() && pivot < 0; ++r)
      if (!used[r] && eq_a[r][j] != 0) pivot = static_cast<int>(r);
    if (pivot < 0) {
      free_x.push_back(j);
      continue;
    }
    used[pivot] = true;
    const VectorQ pa = eq_a[pivot];
    const Rational pb = eq_b[pivot], pj = pa[j];
    for (std::size_t r = 0; r < eq_a.size(); ++r) {
      if (static_cast<int>(r) == pivot || eq_a[r][j] == 0) continue;
      const Rational f = eq_a[r][j] / pj;
      eq_a[r] -= f * pa;
      eq_b[r] -= f * pb;
    }
    for (auto& row : in) {
      if (row.a[j] == 0) continue;
      const Rational f = row.a[j] / pj;
      row.a -= f * pa;
      row.b -= f * pb;
    }
  }
  // Fourier–Motzkin on the x without a pivot (they appear only in inequalities).
  for (int j : free_x) {
    std::vector<Row> pos, neg, next;
    for (auto& row : in) {
      if (row.a[j] > 0)
        pos.push_back(row);
      else if (row.a[j] < 0)
        neg.push_back(row);
      else
        next.push_back(row);
    }
    for (const auto& P : pos)
      for (const auto& N : neg) {
        // P.a·v >= P.b with P.a_j > 0 and N.a·v >= N.b with N.a_j < 0:
        // (−N.a_j) P + P.a_j N eliminates v_j.
        const Rational wp = -N.a[j], wn = P.a[j];
        next.push_back({VectorQ(wp * P.a + wn * N.a), Rational(wp * P.b + wn * N.b), P.strict || N.strict});
      }
    in = std::move(next);
  }
  Polyhedron out;
  out.dim = np;
  auto p_part = [&](const VectorQ& a) { return VectorQ(a.tail(np)); };
  for (std::size_t r = 0; r < eq_a.size(); ++r) {
    if (used[r]) continue;  // defines an eliminated x
    const VectorQ a = p_part(eq_a[r]);
    add_unique(out.closed, normalised(a, eq_b[r]));
    add_unique(out.closed, normalised(VectorQ(-a), Rational(-eq_b[r])));
  }
  for (const auto& row : in) {
    const Halfspace h = normalised(p_part(row.a), row.b);
    add_unique(row.strict ? out.strict : out.closed, h);
  }
  (void)n;
  drop_parallel_redundancy(out);
  drop_constant_rows(out);
  return out;
}

Magnitudes ray_magnitudes(const Polyhedron& P, const VectorQ& b0, const VectorQ& g) {
  check_rows(P, "P");
  for (const auto& [v, name] : {std::pair<const VectorQ&, const char*>{b0, "b0"}, {g, "g"}})
    if (v.size() != P.dim)
      throw InputError(name, std::to_string(v.size()) + " components",
                       "where the polyhedron is in " + std::to_string(P.dim) + " dimensions");
  Magnitudes m;
  m.empty = false;
  m.lo = 0;
  m.lo_closed = false;
  auto apply = [&](const Halfspace& h, bool strict) {
    const Rational alpha = h.a.dot(g), beta = h.c - h.a.dot(b0);  // τα >= β (or >)
    if (alpha > 0) {
      const Rational v = beta / alpha;
      if (v > m.lo) {
        m.lo = v;
        m.lo_closed = !strict;
      } else if (v == m.lo && strict) {
        m.lo_closed = false;
      }
    } else if (alpha < 0) {
      const Rational v = beta / alpha;
      if (!m.hi || v < *m.hi) {
        m.hi = v;
        m.hi_closed = !strict;
      } else if (v == *m.hi && strict) {
        m.hi_closed = false;
      }
    } else if (strict ? beta >= 0 : beta > 0) {
      m.empty = true;
    }
  };
  for (const auto& h : P.closed) apply(h, false);
  for (const auto& h : P.strict) apply(h, true);
  if (m.empty) return Magnitudes{};
  if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
  return m;
}

}  // namespace fixel
