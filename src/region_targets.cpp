// The one-step targets of the pushing region: the seating set S and the
// guaranteed set G (docs/theory.md §8, §9), behind RegionTarget.
#include <algorithm>
#include <memory>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region_target.h"
#include "fixel/wrench_cone.h"

namespace fixel {

std::vector<Polynomial> RegionTarget::sign_polynomials(const std::vector<std::array<Polynomial, 3>>&) const {
  throw UnsupportedError("RegionOptions.exact", "",
                         std::string("is not supported for the push model \"") + push_model() +
                             "\" of this target (it gives no sign polynomials)");
}

namespace {

// The ray-test conditions of S along a piece (docs/theory.md §12): for each
// generator g(s) and facet a·p >= c of S, α(s) = a·g(s) (β = c − a·b0 is
// constant), and for each pair of facets β_h α_k − β_k α_h. T(g) is an
// intersection of half-lines {τ α_h >= β_h} with τ > 0; whether it is empty
// depends only on the signs of the α_h, the β_h and those cross terms.
std::vector<Polynomial> ray_test_polynomials(const std::vector<Halfspace>& rows, const VectorQ& b0,
                                             const std::vector<std::array<Polynomial, 3>>& gens) {
  std::vector<Polynomial> out;
  std::vector<std::array<Polynomial, 3>> distinct;
  for (const auto& g : gens)
    if (std::find(distinct.begin(), distinct.end(), g) == distinct.end()) distinct.push_back(g);
  for (const auto& g : distinct) {
    std::vector<Polynomial> alpha;
    std::vector<Rational> beta;
    for (const auto& h : rows) {
      alpha.push_back(internal::row_dot({h.a[0], h.a[1], h.a[2]}, g));
      beta.push_back(h.c - h.a.dot(b0));
      out.push_back(alpha.back());
    }
    for (std::size_t i = 0; i < alpha.size(); ++i)
      for (std::size_t k = i + 1; k < alpha.size(); ++k)
        out.push_back(internal::psub(internal::pscale(alpha[k], beta[i]), internal::pscale(alpha[i], beta[k])));
  }
  return out;
}

// No ray of the cone (τ > 0) meets the convex piece Q: the set
// {μ >= 0 : b0 + Σ μ_j g_j ∈ Q} is empty (exact LP with strict rows). When
// b0 itself lies in Q (μ = 0) this cannot be certified this way.
bool cone_misses_piece(const VectorQ& b0, RegionStats* stats, const std::vector<VectorQ>& gens, const Polyhedron& Q) {
  if (Q.contains(b0)) return false;
  if (stats) ++stats->lp_tests;
  const int n = static_cast<int>(gens.size());
  Polyhedron lifted;
  lifted.dim = n;
  auto lift = [&](const Halfspace& h) {
    VectorQ a(n);
    for (int j = 0; j < n; ++j) a[j] = h.a.dot(gens[j]);
    return Halfspace{a, h.c - h.a.dot(b0)};
  };
  for (const auto& h : Q.closed) lifted.closed.push_back(lift(h));
  for (const auto& h : Q.strict) lifted.strict.push_back(lift(h));
  for (int j = 0; j < n; ++j) lifted.closed.push_back({VectorQ::Unit(n, j), Rational(0)});
  return is_empty(lifted);
}

// Certified inner bound of the common Euclidean magnitudes (docs/theory.md
// §8): generators g_j with force parts f_j in cone(d_first, d_last) and
// exact T(g_j). Any m in the result has b0 + m w ∈ S for every wrench w of
// the cone whose force part is a unit vector.
Magnitudes common_magnitudes(const std::vector<VectorQ>& gens, const std::vector<Magnitudes>& T, const Vec2& d_first,
                             const Vec2& d_last) {
  Magnitudes m;
  m.empty = false;
  m.lo = 0;
  m.lo_closed = true;
  m.hi_closed = true;
  const Rational c = internal::cos_half_angle_lower(d_first, d_last);
  if (c <= 0) return Magnitudes{};
  for (std::size_t j = 0; j < gens.size(); ++j) {
    if (T[j].empty) return Magnitudes{};
    const Rational f2 = gens[j][0] * gens[j][0] + gens[j][1] * gens[j][1];
    const Rational lo = T[j].lo * internal::sqrt_upper(f2);
    if (lo > m.lo) m.lo = lo;
    m.lo_closed = m.lo_closed && T[j].lo_closed;
    if (T[j].hi) {
      // m·K must stay below hi_j |f_j|, K = 1/cos(Δ/2) <= 1/c.
      const Rational hi = *T[j].hi * internal::sqrt_lower(f2) * c;
      if (!m.hi || hi < *m.hi) m.hi = hi;
      m.hi_closed = m.hi_closed && T[j].hi_closed;
    }
  }
  if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
  return m;
}

// The one-step seating set S (paper §4): convex, so a cone reaches it iff
// every generator does.
class SeatingTarget final : public RegionTarget {
 public:
  SeatingTarget(const SeatingSet& S, const VectorQ& b0) : S_(S), b0_(b0) {}
  const char* push_model() const override { return "step"; }
  const char* name() const override { return "S"; }

  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2* d_first, const Vec2* d_last,
                     RegionInterval* detail) override {
    std::vector<Magnitudes> T;
    bool all_half = true;
    hits_.clear();
    for (const auto& g : gens) {
      T.push_back(ray_magnitudes(S_, b0_, g));
      hits_.emplace_back(g, !T.back().empty);
      if (T.back().empty) return false;
      all_half = all_half && T.back().half_line();
    }
    if (detail) {
      detail->half_line = all_half;
      detail->magnitudes = d_first ? common_magnitudes(gens, T, *d_first, *d_last) : Magnitudes{};
    }
    return true;
  }

  // The cone misses S − b0 except at 0: the LP max Σμ_j s.t. b0 + Σ μ_j g_j
  // ∈ S, μ >= 0 is infeasible or has optimum 0. (No cap on Σμ: S is not a
  // cone from b0, so a cap would also cap the push magnitude.)
  bool misses(const std::vector<VectorQ>& gens) override {
    bool some_miss = false;
    for (const auto& g : gens) {
      // The region asks misses() right after contains_cone() on the same
      // generators: reuse those ray tests.
      const auto cached = std::find_if(hits_.begin(), hits_.end(), [&](const auto& h) { return h.first == g; });
      some_miss = some_miss || (cached != hits_.end() ? !cached->second : ray_magnitudes(S_, b0_, g).empty);
    }
    if (!some_miss) return false;
    if (stats) ++stats->lp_tests;
    const int n = static_cast<int>(gens.size());
    std::vector<internal::LinearConstraint> rows;
    for (const auto& h : S_.halfspaces) {
      VectorQ a(n);
      for (int j = 0; j < n; ++j) a[j] = h.a.dot(gens[j]);
      rows.push_back({a, internal::Relation::kGreaterEqual, h.c - h.a.dot(b0_)});
    }
    for (int j = 0; j < n; ++j) rows.push_back({VectorQ::Unit(n, j), internal::Relation::kGreaterEqual, Rational(0)});
    const internal::LpResult lp = internal::solve_lp(n, rows, VectorQ(-VectorQ::Ones(n)));
    if (lp.status == internal::LpStatus::kInfeasible) return true;
    if (lp.status == internal::LpStatus::kUnbounded) return false;
    return lp.value == 0;
  }

  std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>& gens) const override {
    if (S_.dof != 3) throw UnsupportedError("body.dof", std::to_string(S_.dof), "the exact region needs dof 3");
    return ray_test_polynomials(S_.halfspaces, b0_, gens);
  }

 private:
  const SeatingSet& S_;
  VectorQ b0_;
  std::vector<std::pair<VectorQ, bool>> hits_;  // generators of the last contains_cone call
};

// The guaranteed set G: a disjoint union of convex pieces.
class GuaranteedTarget final : public RegionTarget {
 public:
  GuaranteedTarget(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0) : G_(G), S_(S), b0_(b0) {}
  const char* push_model() const override { return "step"; }
  const char* name() const override { return "G"; }

  void check_pusher(const Rational& mu) const override {
    if (mu != 0)
      throw UnsupportedError("RegionOptions.pusher_mu", to_string(mu),
                             "with --guaranteed is not supported: G is not convex, so the two friction edges hitting G "
                             "does not make every push direction between them hit G (use a frictionless pusher)");
  }

  std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>&) const override {
    throw UnsupportedError("RegionOptions.exact", "",
                           "with --guaranteed is not supported: G is a union of pieces minus non-seating "
                           "sets with strict rows, and its exact region is a separate project "
                           "(docs/theory.md §12); use subdivision");
  }

  // The hit set of one convex piece is convex: IN when one piece holds
  // every generator's ray.
  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2* d_first, const Vec2* d_last,
                     RegionInterval* detail) override {
    if (!d_first) return false;
    for (const auto& piece : G_.pieces) {
      std::vector<Magnitudes> T;
      bool all = true;
      for (const auto& g : gens) {
        T.push_back(ray_magnitudes(piece, b0_, g));
        all = all && !T.back().empty;
      }
      if (!all) continue;
      if (detail) {
        detail->magnitudes = common_magnitudes(gens, T, *d_first, *d_last);
        detail->magnitude_set = {detail->magnitudes};
        bool half = true;
        for (const auto& t : T) half = half && t.half_line();
        detail->half_line = half;
      }
      return true;
    }
    return false;
  }

  // G is the disjoint union of its pieces: the cone misses G iff it misses
  // every piece.
  bool misses(const std::vector<VectorQ>& gens) override {
    for (const auto& piece : G_.pieces)
      if (!cone_misses_piece(b0_, stats, gens, piece)) return false;
    return true;
  }

  RegionStatus test_point(const std::vector<VectorQ>& gens, const Vec2& d_first, const Vec2& d_last, Magnitudes* out,
                          std::vector<Magnitudes>* set) override {
    if (cross(d_first, d_last) == 0) {  // one ray: exact union of intervals
      const std::vector<Magnitudes> parts = ray_magnitudes(G_, S_, b0_, gens[0]);
      if (set) {
        // Report Euclidean |p| like every other magnitude: τ|d| with |d|
        // irrational, so each end is rounded inward (a certified subset).
        set->clear();
        const Rational d2 = d_first.x * d_first.x + d_first.y * d_first.y;
        for (const auto& t : parts) {
          Magnitudes m = t;
          m.lo = t.lo * internal::sqrt_upper(d2);
          if (t.hi) m.hi = *t.hi * internal::sqrt_lower(d2);
          if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) continue;
          set->push_back(m);
        }
      }
      if (out) *out = set && !set->empty() ? set->front() : Magnitudes{};
      return parts.empty() ? RegionStatus::kOut : RegionStatus::kIn;
    }
    RegionInterval tmp;
    RegionStatus st = RegionStatus::kIn;
    if (!contains_cone(gens, &d_first, &d_last, &tmp)) st = misses(gens) ? RegionStatus::kOut : RegionStatus::kPartial;
    if (out) *out = tmp.magnitudes;
    if (set) *set = tmp.magnitude_set;
    return st;
  }

 private:
  const GuaranteedSet& G_;
  const SeatingSet& S_;
  VectorQ b0_;
};

}  // namespace

std::unique_ptr<RegionTarget> seating_target(const SeatingSet& S, const VectorQ& b0) {
  return std::make_unique<SeatingTarget>(S, b0);
}

std::unique_ptr<RegionTarget> guaranteed_target(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0) {
  return std::make_unique<GuaranteedTarget>(G, S, b0);
}

}  // namespace fixel
