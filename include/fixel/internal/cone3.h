#pragma once
// Exact 3-D cone algebra over a number type NT (CGAL's Sqrt_extension for
// Q(√d), or Boost.Interval for certified enclosures): facets and extreme
// rays of cones, and Fourier–Motzkin feasibility with strict rows
// (docs/theory.md §10.2). `sign(NT)` must be exact, or throw Undecided.
// (Over CGAL's Interval_nt, src/sustained_filter.cpp: the certified sign,
// Undecided when the interval straddles 0.)

#include <array>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/interval_arith.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/progress.h"

namespace fixel::internal {

inline Q2 lift_number(const Rational& x, const Q2*) { return Q2(x); }
inline IV lift_number(const Rational& x, const IV*) { return enclose(x); }
inline Rational lift_number(const Rational& x, const Rational*) { return x; }

template <class NT>
using A3 = std::array<NT, 3>;

// The certified sign of a CGAL interval; throws Undecided when it straddles 0.
inline int sign(const FI& x) {
  const int s = certain_sign(x);
  if (s == kUndecided) throw Undecided();
  return s;
}

template <class NT>
NT dot3(const A3<NT>& a, const A3<NT>& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
// Sign of a·x. Over Q(√d) the interval filter decides first (each entry
// a0 + a1√d enclosed with CGAL's correctly rounded interval sqrt) and the
// exact Sqrt_extension sign runs only when it cannot; over intervals it is
// the interval's own sign (which throws Undecided when it straddles 0).
inline int sign_dot3(const A3<IV>& a, const A3<IV>& x) { return sign(dot3(a, x)); }

// An enclosure of x in any rounding mode: a rational's from fixel's
// conversion (CGAL's for a rational is slower and not cached), else CGAL's
// a0 + a1·√root, which x caches.
inline FI to_interval_q2(const Q2& x) {
  if (!x.is_extended() || x.a1() == 0) return to_interval(x.a0());
  const std::pair<double, double> i = x.to_interval();
  return FI(i.first, i.second);
}

// Sign of a·x over Q(√d), or over Q (J's rows at a rational seat, before
// they are lifted to Q(√d)): on the entries' enclosures first, the exact
// sign only when they cannot tell.
inline int sign(const Rational& x) { return fixel::sign(x); }
inline FI enclosure_of(const Q2& x) { return to_interval_q2(x); }
inline FI enclosure_of(const Rational& x) { return to_interval(x); }
template <class NT>
int sign_dot3_filtered(const A3<NT>& a, const A3<NT>& x) {
  if (!force_exact()) {
    int s = kUndecided;
    {
      Protect guard;
      FI sum = enclosure_of(a[0]) * enclosure_of(x[0]);
      for (int k = 1; k < 3; ++k) sum += enclosure_of(a[k]) * enclosure_of(x[k]);
      s = certain_sign(sum);
    }
    record_filter(FilterSite::kJam, s != kUndecided);
    if (s != kUndecided) return s;
  }
  return sign(dot3(a, x));
}
inline int sign_dot3(const A3<Q2>& a, const A3<Q2>& x) { return sign_dot3_filtered(a, x); }
inline int sign_dot3(const A3<Rational>& a, const A3<Rational>& x) { return sign_dot3_filtered(a, x); }

template <class NT>
A3<NT> cross3(const A3<NT>& a, const A3<NT>& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
template <class NT>
A3<NT> neg3(const A3<NT>& a) {
  return {-a[0], -a[1], -a[2]};
}

// Computes and keeps each irrational entry's interval enclosure
// (Sqrt_extension caches it, and copies carry it): rows enclosed once, not
// per system. A rational's is not cached (to_interval_q2 makes it).
inline void cache_enclosures(const A3<Q2>& v) {
  for (const Q2& x : v)
    if (x.is_extended() && x.a1() != 0) (void)x.to_interval();
}
inline void cache_enclosures(const A3<IV>&) {}

template <class NT>
A3<NT> lift3(const VectorQ& v) {
  const NT* tag = nullptr;
  return {lift_number(v[0], tag), lift_number(v[1], tag), lift_number(v[2], tag)};
}

// a·x ≥ b (or > b when strict).
template <class NT>
struct Row {
  A3<NT> a;
  NT b;
  bool strict = false;
};

inline constexpr std::size_t kMaxRows = 200000;  // bounds Fourier–Motzkin on any input

// Feasibility of a system in three unknowns by Fourier–Motzkin with
// strictness tracking (docs/theory.md §10.2). Exact over Q(√d); over
// intervals it throws Undecided when a sign is not certain.
template <class NT>
bool feasible(std::vector<Row<NT>> rows) {
  bool homogeneous = true;  // every b exactly 0 (J's systems)
  for (const auto& r : rows) try {
      homogeneous = homogeneous && sign(r.b) == 0;
    } catch (const Undecided&) {
      homogeneous = false;
    }
  for (int j = 2; j >= -1; --j) {
    std::vector<Row<NT>> pos, neg, next;
    for (auto& r : rows) {
      bool zero = true;
      for (int k = 0; k <= std::max(j, 0) && zero; ++k) zero = sign(r.a[k]) == 0;
      if (j < 0 || zero) {  // no unknown left in this row: 0 ≥ b or 0 > b decides itself
        bool all_zero = true;
        for (int k = 0; k < 3; ++k) all_zero = all_zero && sign(r.a[k]) == 0;
        if (all_zero) {
          const int sb = sign(r.b);
          if (r.strict ? sb >= 0 : sb > 0) return false;
          continue;
        }
      }
      if (j < 0) continue;
      const int s = sign(r.a[j]);
      (s > 0 ? pos : (s < 0 ? neg : next)).push_back(r);
    }
    if (j < 0) return true;
    if (j == 0 && homogeneous) {
      // Eliminating the last unknown of a homogeneous system makes rows
      // 0 ≥ 0, or 0 > 0 when a parent is strict (docs/theory.md §10.2).
      bool strict = false;
      if (!pos.empty() && !neg.empty()) {
        for (const auto& r : pos) strict = strict || r.strict;
        for (const auto& r : neg) strict = strict || r.strict;
      }
      if (strict) return false;
      rows = std::move(next);
      continue;
    }
    if (pos.size() * neg.size() + next.size() > kMaxRows)
      throw InternalError("sustained set: Fourier-Motzkin exceeded " + std::to_string(kMaxRows) + " rows");
    for (const auto& P : pos)
      for (const auto& N : neg) {
        const NT wp = -N.a[j], wn = P.a[j];  // both > 0
        Row<NT> r;
        // Unknowns above j are zero in every row left (eliminated), and j is by construction.
        for (int k = 0; k < j; ++k) r.a[k] = wp * P.a[k] + wn * N.a[k];
        for (int k = j; k < 3; ++k) r.a[k] = NT(0);
        r.b = homogeneous ? NT(0) : wp * P.b + wn * N.b;
        r.strict = P.strict || N.strict;
        next.push_back(r);
      }
    rows = std::move(next);
  }
  return true;
}

// feasible() decided on enclosures first (src/cone3.cpp, docs/theory.md
// §10.2): the same elimination on enclosures of the rows, each sign
// certified by its enclosure or, where that cannot tell (an exact zero
// the elimination makes), by the exact row, computed then from the exact
// rows it combines. Every choice is the exact run's, so the answer is the
// exact one. Over intervals it is feasible().
inline bool feasible_filtered(std::vector<Row<IV>> rows) { return feasible(std::move(rows)); }
bool feasible_filtered(const std::vector<Row<Q2>>& rows);

// A homogeneous row a·x ≥ 0 (> 0 when strict) by reference: J's systems
// are made of rows J keeps (its K rows and jam facets), so they need not
// be copied (a copy of a Q(√d) row is nine rationals). The rows must
// outlive the call.
template <class NT>
struct RowRef {
  const A3<NT>* a;
  bool strict;
};
template <class NT>
void append_refs(const std::vector<A3<NT>>& rows, bool strict, std::vector<RowRef<NT>>& out) {
  for (const auto& a : rows) out.push_back({&a, strict});
}
// feasible_filtered of the rows referred to: over Q(√d) an exact input row
// is copied only when a sign needs it.
bool feasible_filtered(const std::vector<RowRef<Q2>>& rows);
inline bool feasible_filtered(const std::vector<RowRef<IV>>& rows) {
  std::vector<Row<IV>> copies;
  for (const auto& r : rows) copies.push_back({*r.a, IV(0), r.strict});
  return feasible(std::move(copies));
}

// A row on enclosures, with its exact form when it has one (J's rows do;
// a region segment's cone facets on enclosures do not). Both must outlive
// the call.
struct MixedRow {
  A3<FI> a;
  FI b;
  bool strict = false;
  const A3<Q2>* exact_a = nullptr;  // null: an enclosure only
  const Q2* exact_b = nullptr;
};
// feasible() on the enclosures, each open sign taken exactly as in
// feasible_filtered when every row it derives from has its exact form;
// throws Undecided when one does not.
bool feasible_mixed(const std::vector<MixedRow>& rows);

template <class NT>
bool is_zero3(const A3<NT>& a) {
  return sign(a[0]) == 0 && sign(a[1]) == 0 && sign(a[2]) == 0;
}

// Duplicate rows only cost time: an undecidable comparison keeps both.
template <class NT>
void add_unique(std::vector<A3<NT>>& out, const A3<NT>& a) {
  for (const auto& q : out) try {
      if (is_zero3(cross3(q, a)) && sign_dot3(q, a) > 0) return;
    } catch (const Undecided&) {
    }
  out.push_back(a);
}

// +1 if a·g >= 0 for all g, −1 if <= 0 for all, 0 otherwise; the generators
// `skip_i`, `skip_j` (those a was built from) are on the plane by construction.
template <class NT>
int supporting_side(const A3<NT>& a, const std::vector<A3<NT>>& gens, std::size_t skip_i, std::size_t skip_j) {
  bool nonneg = true, nonpos = true;
  for (std::size_t k = 0; k < gens.size(); ++k) {
    if (k == skip_i || k == skip_j) continue;
    const int s = sign_dot3(a, gens[k]);
    nonneg = nonneg && s >= 0;
    nonpos = nonpos && s <= 0;
  }
  return nonneg ? 1 : (nonpos ? -1 : 0);
}

// Closed rows of cone(gens) ⊂ R³. `planar` (known exactly: both fixels
// frictionless) gives the plane as two opposite rows plus its edge rows.
template <class NT>
std::vector<A3<NT>> facets_of(const std::vector<A3<NT>>& gens, bool planar) {
  std::vector<A3<NT>> out;
  if (planar) {
    const A3<NT> n = cross3(gens[0], gens[1]);
    out.push_back(n);
    out.push_back(neg3(n));
    for (std::size_t k = 0; k < gens.size(); ++k) {
      const A3<NT> e = cross3(n, gens[k]);  // in the plane, normal to gens[k]
      const int side = supporting_side(e, gens, k, k);
      if (side != 0) add_unique(out, side > 0 ? e : neg3(e));
    }
    return out;
  }
  for (std::size_t i = 0; i < gens.size(); ++i)
    for (std::size_t j = i + 1; j < gens.size(); ++j) {
      poll_exact_step();
      const A3<NT> c = cross3(gens[i], gens[j]);
      const int side = supporting_side(c, gens, i, j);
      if (side != 0) add_unique(out, side > 0 ? c : neg3(c));
    }
  return out;
}

template <class NT>
bool satisfies(const A3<NT>& x, const std::vector<A3<NT>>& closed, const std::vector<A3<NT>>& strict) {
  for (const auto& a : closed)
    if (sign_dot3(a, x) < 0) return false;
  for (const auto& a : strict)
    if (sign_dot3(a, x) <= 0) return false;
  return true;
}

// Extreme rays of the pointed cone {a·x ≥ 0 for every row}.
template <class NT>
std::vector<A3<NT>> rays_of(const std::vector<A3<NT>>& rows) {
  std::vector<A3<NT>> out;
  for (std::size_t i = 0; i < rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.size(); ++j) {
      poll_exact_step();
      const A3<NT> c = cross3(rows[i], rows[j]);
      if (is_zero3(c)) continue;
      for (const A3<NT>& r : {c, neg3(c)}) {
        bool ok = true;
        for (std::size_t k = 0; k < rows.size() && ok; ++k)
          if (k != i && k != j) ok = sign_dot3(rows[k], r) >= 0;
        if (ok) add_unique(out, r);
      }
    }
  return out;
}

// The same over Q(√d) (src/cone3.cpp): the pairs' cross products and the
// side tests on enclosures first, exact products only for the rays kept and
// for signs the enclosures leave open. The same rays in the same order.
std::vector<A3<Q2>> rays_of(const std::vector<A3<Q2>>& rows);

// facets_of over Q(√d) (src/cone3.cpp), filtered the same way: each pair's
// cross product and side tests, and the duplicate test of add_unique, on
// enclosures first. The same facets in the same order.
std::vector<A3<Q2>> facets_of(const std::vector<A3<Q2>>& gens, bool planar);
// The same over Q (J's rows at a rational seat).
std::vector<A3<Rational>> facets_of(const std::vector<A3<Rational>>& gens, bool planar);

template <class NT>
std::vector<Row<NT>> homogeneous(const std::vector<A3<NT>>& rows, bool strict) {
  std::vector<Row<NT>> out;
  for (const auto& a : rows) out.push_back({a, NT(0), strict});
  return out;
}

}  // namespace fixel::internal
