// The one-step target S of the pushing region: the seating set
// (docs/theory.md §8), convex, behind RegionTarget; its ray test runs an
// interval filter first and the exact test when the filter cannot decide.
#include <algorithm>
#include <array>
#include <boost/container/small_vector.hpp>
#include <boost/range/iterator_range.hpp>
#include <cmath>
#include <memory>
#include <string>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/region_targets.h"
#include "fixel/region_target.h"
#include "fixel/seating.h"

namespace fixel {

namespace {

using internal::common_magnitudes;

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

using internal::certain_sign;
using internal::FI;
using internal::kUndecided;

// A generator (f_x, f_y, moment) as intervals.
std::array<FI, 3> to_interval3(const VectorQ& g) {
  return {internal::to_interval(g[0]), internal::to_interval(g[1]), internal::to_interval(g[2])};
}

// The halfspaces a_k·p ≥ c_k of a convex set as intervals, with
// β_k = c_k − a_k·b0 (the ray b0 + τ g needs τ α_k ≥ β_k, α_k = a_k·g).
struct FilteredHalfspaces {
  std::vector<std::array<FI, 3>> a;
  std::vector<FI> beta;

  FilteredHalfspaces(const std::vector<Halfspace>& hs, const VectorQ& b0) {
    for (const auto& h : hs) {
      a.push_back(to_interval3(h.a));
      beta.push_back(internal::to_interval(h.c - h.a.dot(b0)));
    }
  }

  // Needs a Protect scope.
  FI alpha(std::size_t k, const std::array<FI, 3>& g) const { return a[k][0] * g[0] + a[k][1] * g[1] + a[k][2] * g[2]; }

  // Whether {τ > 0 : τ α_k ≥ β_k ∀k} is non-empty (exactly the emptiness
  // rule of ray_magnitudes: every upper end v_j = β_j/α_j (α_j < 0) is
  // positive, every lower end v_i (α_i > 0) is at most every v_j, and no
  // α_k = 0 has β_k > 0): 1 hit, 0 miss, kUndecided.
  int ray_hits(const std::array<FI, 3>& g) const {
    internal::Protect guard;
    const std::size_t m = a.size();
    FI al[16];
    if (m > 16) return kUndecided;
    bool undecided = false;
    for (std::size_t k = 0; k < m; ++k) {
      al[k] = alpha(k, g);
      const int sa = certain_sign(al[k]);
      if (sa == kUndecided) return kUndecided;
      if (sa == 0) {
        const int sb = certain_sign(beta[k]);
        if (sb == 1) return 0;
        if (sb == kUndecided) undecided = true;
      } else if (sa < 0) {
        const int sb = certain_sign(beta[k]);  // v_k > 0 iff β_k < 0
        if (sb >= 0 && sb != kUndecided) return 0;
        if (sb == kUndecided) undecided = true;
      }
    }
    for (std::size_t i = 0; i < m; ++i) {
      if (!(al[i].inf() > 0)) continue;
      for (std::size_t j = 0; j < m; ++j) {
        if (!(al[j].sup() < 0)) continue;
        // v_i <= v_j  ⇔  β_i α_j − β_j α_i >= 0 (α_i > 0 > α_j).
        const FI d = beta[i] * al[j] - beta[j] * al[i];
        if (d.sup() < 0) return 0;
        if (!(d.inf() >= 0)) undecided = true;
      }
    }
    return undecided ? kUndecided : 1;
  }

  // T(g) of ray_magnitudes enclosed (see SeatingTarget::magnitudes): lo the
  // largest β_k/α_k over α_k > 0 (closed iff one has β_k > 0), hi the
  // smallest over α_k < 0. False when a sign is undecided or T may be empty.
  bool magnitudes(const std::array<FI, 3>& g, internal::FMagnitudes& T) const {
    internal::Protect guard;
    T = internal::FMagnitudes{};
    T.lo = FI(0);
    for (std::size_t k = 0; k < a.size(); ++k) {
      const FI al = alpha(k, g);
      const int sa = certain_sign(al), sb = certain_sign(beta[k]);
      if (sa == kUndecided || sb == kUndecided || (sa == 0 && sb > 0)) return false;
      if (sa > 0) {
        const FI v = beta[k] / al;
        T.lo = FI(std::max(T.lo.inf(), v.inf()), std::max(T.lo.sup(), v.sup()));
        T.lo_closed = T.lo_closed || sb > 0;
      } else if (sa < 0) {
        const FI v = beta[k] / al;
        T.hi = T.has_hi ? FI(std::min(T.hi.inf(), v.inf()), std::min(T.hi.sup(), v.sup())) : v;
        T.has_hi = true;
      }
    }
    return !T.has_hi || T.hi.inf() > T.lo.sup();
  }

  // A Farkas certificate that no μ >= 0 with Σ μ_j > 0 has
  // a_k·(b0 + Σ μ_j g_j) ≥ c_k for every k: y >= 0 with Σ_k y_k a_k·g_j <= 0
  // for every j and y·β > 0; or, for b0 on the facets with y_k > 0 (β_k = 0,
  // as at the apex of a cone S), Σ_k y_k a_k·g_j < 0 for every j and
  // y·β >= 0 (docs/theory.md §8). y is supported on three facets: all of
  // them for a set of three, else each triple in turn (a certificate for
  // the set those three bound is one for S, which lies inside it). A
  // candidate is found in doubles (the vertices of the feasible polygon on
  // the simplex Σ y = 1, then its centre at half the best y·β, or the
  // centre of its vertices) and checked in intervals. True only when
  // certified.
  bool certify_infeasible(const std::array<FI, 3>* gens, std::size_t n) const {
    const std::size_t m = a.size();
    if (m < 3 || m > kMaxFarkasFacets) return false;
    for (std::size_t i = 0; i < m; ++i)
      for (std::size_t j = i + 1; j < m; ++j)
        for (std::size_t k = j + 1; k < m; ++k)
          if (certify_on({i, j, k}, gens, n)) return true;
    return false;
  }

  static constexpr std::size_t kMaxFarkasFacets = 12;  // 220 triples at most

  bool certify_on(const std::array<std::size_t, 3>& f, const std::array<FI, 3>* gens, std::size_t n) const {
    using V3 = std::array<double, 3>;
    using V3s = boost::container::small_vector<V3, 24>;  // no allocation for small cones
    V3s u;                                               // constraints u·y <= 0
    {
      internal::Protect guard;
      for (const auto& g : boost::make_iterator_range(gens, gens + n)) {
        V3 c;
        for (int k = 0; k < 3; ++k) c[k] = CGAL::to_double(alpha(f[k], g));
        u.push_back(c);
      }
    }
    for (int k = 0; k < 3; ++k) u.push_back({k == 0 ? -1.0 : 0.0, k == 1 ? -1.0 : 0.0, k == 2 ? -1.0 : 0.0});
    const V3 b{CGAL::to_double(beta[f[0]]), CGAL::to_double(beta[f[1]]), CGAL::to_double(beta[f[2]])};
    auto dot3 = [](const V3& x, const V3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
    // Vertices: u_p·y = u_q·y = 0, Σ y = 1.
    auto vertices = [&](const V3s& cons) {
      V3s out;
      for (std::size_t p = 0; p < cons.size(); ++p)
        for (std::size_t q = p + 1; q < cons.size(); ++q) {
          const V3 &r0 = cons[p], &r1 = cons[q];
          // y ∝ r0 × r1, scaled to Σ y = 1.
          V3 y{r0[1] * r1[2] - r0[2] * r1[1], r0[2] * r1[0] - r0[0] * r1[2], r0[0] * r1[1] - r0[1] * r1[0]};
          const double s = y[0] + y[1] + y[2];
          if (!(std::abs(s) > 1e-300)) continue;
          for (auto& x : y) x /= s;
          bool ok = true;
          for (const auto& c : cons) ok = ok && dot3(c, y) <= 1e-12;
          if (ok) out.push_back(y);
        }
      return out;
    };
    auto centre = [](const V3s& vs) {
      V3 y{0, 0, 0};
      for (const auto& v : vs)
        for (int k = 0; k < 3; ++k) y[k] += v[k] / static_cast<double>(vs.size());
      for (auto& x : y) x = std::max(x, 0.0);
      return y;
    };
    const V3s corners = vertices(u);
    if (corners.empty()) return false;
    double best = 0;
    for (const auto& y : corners) best = std::max(best, dot3(b, y));
    const bool strict = !(best > 0);  // no y·β > 0: try the other alternative
    V3 y;
    if (strict) {
      y = centre(corners);
    } else {
      V3s cons = u;
      cons.push_back({best / 2 - b[0], best / 2 - b[1], best / 2 - b[2]});  // y·β >= best/2
      const auto vs = vertices(cons);
      if (vs.empty()) return false;
      y = centre(vs);
    }
    // Certify with the data's enclosures; y is taken as exact.
    internal::Protect guard;
    for (const auto& g : boost::make_iterator_range(gens, gens + n)) {
      const FI t = FI(y[0]) * alpha(f[0], g) + FI(y[1]) * alpha(f[1], g) + FI(y[2]) * alpha(f[2], g);
      if (!(strict ? t.sup() < 0 : t.sup() <= 0)) return false;
    }
    const FI t = FI(y[0]) * beta[f[0]] + FI(y[1]) * beta[f[1]] + FI(y[2]) * beta[f[2]];
    return strict ? t.inf() >= 0 : t.inf() > 0;
  }

  // A witness that some μ >= 0 with Σμ > 0 puts b0 + Σ μ_j g_j in the set: a
  // combination d = Σ w_j g_j whose ray is certified to hit it (then
  // μ = τw for a τ > 0 of that ray).
  bool certify_meets(const std::array<FI, 3>* gens, std::size_t n) const {
    return internal::some_combination(gens, n, [this](const std::array<FI, 3>& d) { return ray_hits(d) == 1; });
  }

  // misses() of a cone none of whose generators' rays hits: 1 missed
  // (Farkas certificate), 0 met (a combination's ray hits), kUndecided.
  int out_test(const std::array<FI, 3>* gens, std::size_t n) const {
    if (certify_infeasible(gens, n)) return 1;
    if (certify_meets(gens, n)) return 0;
    return kUndecided;
  }
};

// The one-step seating set S (paper §4): convex, so a cone reaches it iff
// every generator does.
class SeatingTarget final : public RegionTarget, public internal::IntervalTarget {
 public:
  SeatingTarget(const SeatingSet& S, const VectorQ& b0) : S_(S), b0_(b0), filtered_(S.halfspaces, b0) {
    for (const auto& h : S.halfspaces) beta_.push_back(h.c - h.a.dot(b0));
  }

  void check_scene(const Scene& scene) const override { check_seating_set_of(scene, S_); }

  // ray_magnitudes(S, b0, g) with β_k = c_k − a_k·b0 computed once.
  Magnitudes magnitudes(const VectorQ& g) const {
    Magnitudes m;
    m.empty = false;
    m.lo = 0;
    m.lo_closed = false;  // τ > 0
    for (std::size_t k = 0; k < beta_.size(); ++k) {
      const Rational alpha = S_.halfspaces[k].a.dot(g);  // need τ α >= β
      if (alpha > 0) {
        const Rational v = beta_[k] / alpha;
        if (v > m.lo) {
          m.lo = v;
          m.lo_closed = true;
        }
      } else if (alpha < 0) {
        const Rational v = beta_[k] / alpha;
        if (!m.hi || v < *m.hi) {
          m.hi = v;
          m.hi_closed = true;
        }
      } else if (beta_[k] > 0) {
        return Magnitudes{};
      }
    }
    if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
    return m;
  }
  const char* push_model() const override { return "step"; }
  internal::IntervalTarget* interval_target() override { return this; }
  int interval_ray_hits(const internal::FGen& g) const override { return filtered_.ray_hits(g); }
  bool interval_magnitudes(const internal::FGen& g, internal::FMagnitudes& T) const override {
    return filtered_.magnitudes(g, T);
  }
  int certify_out_test(const internal::FGen* gens, std::size_t n) override {
    const int missed = filtered_.out_test(gens, n);
    if (missed != kUndecided && stats) ++stats->lp_tests;
    return missed;
  }
  const char* name() const override { return "S"; }

  // Does the ray of g meet S: the interval filter, then the exact ray test.
  bool ray_hits(const VectorQ& g) {
    if (!force_exact()) {
      const int h = filtered_.ray_hits(to_interval3(g));
      internal::record_filter(FilterSite::kRayTest, h != kUndecided);
      if (h != kUndecided) return h == 1;
    }
    return !magnitudes(g).empty;
  }

  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2* d_first, const Vec2* d_last,
                     RegionInterval* detail) override {
    hits_.clear();
    for (const auto& g : gens) {
      hits_.emplace_back(g, ray_hits(g));
      if (!hits_.back().second) return false;
    }
    // Every ray hits: the exact magnitudes (they are part of the answer).
    std::vector<Magnitudes> T;
    bool all_half = true;
    for (std::size_t j = 0; j < gens.size(); ++j) {
      // Equal generators (a straight piece's tight cone repeats its pair)
      // share their magnitudes.
      std::size_t i = 0;
      while (i < j && gens[i] != gens[j]) ++i;
      T.push_back(i < j ? T[i] : magnitudes(gens[j]));
      if (T.back().empty) throw InternalError("region: a certified ray hit has no exact magnitudes");
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
    // A generator whose ray hits S is a feasible μ with Σμ > 0: the cone
    // does not miss. (The region asks misses() right after contains_cone()
    // on the same generators: reuse those ray tests.)
    for (const auto& g : gens) {
      const auto cached = std::find_if(hits_.begin(), hits_.end(), [&](const auto& h) { return h.first == g; });
      if (cached != hits_.end() ? cached->second : ray_hits(g)) return false;
    }
    if (stats) ++stats->lp_tests;
    if (!force_exact()) {
      std::vector<std::array<FI, 3>> fg;
      for (const auto& g : gens) fg.push_back(to_interval3(g));
      const int missed = filtered_.out_test(fg.data(), fg.size());
      internal::record_filter(FilterSite::kOutTest, missed != kUndecided);
      if (missed != kUndecided) return missed == 1;
    }
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
  const SeatingSet S_;  // a copy: the caller's S may be a temporary
  VectorQ b0_;
  FilteredHalfspaces filtered_;
  std::vector<Rational> beta_;                  // c_k − a_k·b0
  std::vector<std::pair<VectorQ, bool>> hits_;  // generators of the last contains_cone call
};

}  // namespace

void internal::check_rigid_seating_set(const SeatingSet& S, const VectorQ& b0) {
  // Rows of another length would be read past their end by the region.
  bool rigid = S.dof == 3 && b0.size() == 3;
  for (const Halfspace& h : S.halfspaces) rigid = rigid && h.a.size() == 3;
  if (!rigid)
    throw InputError("S", "dof " + std::to_string(S.dof) + ", b0 of " + std::to_string(b0.size()) + " components",
                     "a region target needs a rigid body's seating set (dof 3) and a three-component b0");
  // A set seating_set never makes (no apex, as a default-constructed one)
  // would read as all of R³: every push IN. (S itself can be all of R³,
  // with no facets, when every gap is 0.)
  if (S.apex.size() != 3)
    throw InputError("S", "an apex of " + std::to_string(S.apex.size()) + " components",
                     "is not a seating set: build it with seating_set(scene)");
}

std::unique_ptr<RegionTarget> seating_target(const SeatingSet& S, const VectorQ& b0) {
  internal::check_rigid_seating_set(S, b0);
  return std::make_unique<SeatingTarget>(S, b0);
}

}  // namespace fixel
