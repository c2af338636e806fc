// The one-step target G of the pushing region: the guaranteed set
// (docs/theory.md §9), a disjoint union of convex pieces, behind
// RegionTarget.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/filtered.h"
#include "fixel/internal/region_filter.h"
#include "fixel/internal/region_targets.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region_target.h"

namespace fixel {

namespace {

using internal::common_magnitudes;

// No ray of the cone (τ > 0) meets the convex piece Q: no μ ≥ 0 with
// Σ μ_j > 0 puts b0 + Σ μ_j g_j in Q (exact LP with strict rows). The strict
// row Σ μ_j > 0 matters only when b0 itself lies in Q: the push's magnitude
// is positive, so μ = 0 is no push (as for S, docs/theory.md §8).
bool cone_misses_piece(const VectorQ& b0, RegionStats* stats, const std::vector<VectorQ>& gens, const Polyhedron& Q) {
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
  lifted.strict.push_back({VectorQ::Ones(n), Rational(0)});
  return is_empty(lifted);
}

using internal::certain_sign;
using internal::FI;
using internal::kUndecided;

// One piece's rows a_h·x ≥ c_h (closed and strict alike: the closure) as
// seen from b0: enclosures of a_h and of β_h = c_h − a_h·b0.
struct PieceEnclosure {
  std::vector<std::array<FI, 3>> a;
  std::vector<FI> beta;

  PieceEnclosure(const Polyhedron& Q, const VectorQ& b0) {
    auto add = [&](const Halfspace& h) {
      if (h.a.size() != 3) return;
      a.push_back({internal::to_interval(h.a[0]), internal::to_interval(h.a[1]), internal::to_interval(h.a[2])});
      beta.push_back(internal::to_interval(h.c - h.a.dot(b0)));
    };
    for (const auto& h : Q.closed) add(h);
    for (const auto& h : Q.strict) add(h);
    complete = a.size() == Q.closed.size() + Q.strict.size();
  }

  bool complete = false;  // every row of the piece is here (none of another length)

  // Does the ray b0 + τ g (τ > 0) meet the piece: 1 certainly (every row
  // holds strictly on an open τ-interval, so closed and strict rows alike),
  // 0 certainly not (its closure misses, with τ > 0), kUndecided. Exact
  // zeros (α_h = β_h = 0, or two ends that meet) are left to the exact test,
  // where strict and closed rows differ.
  int ray_hits(const std::array<FI, 3>& g) const {
    const std::size_t m = beta.size();
    if (m > 64) return kUndecided;
    internal::Protect guard;
    std::array<FI, 64> al;
    bool hit = complete;
    for (std::size_t h = 0; h < m; ++h) {
      al[h] = a[h][0] * g[0] + a[h][1] * g[1] + a[h][2] * g[2];
      const int sa = certain_sign(al[h]), sb = certain_sign(beta[h]);
      if (sa == kUndecided) {
        hit = false;
        continue;
      }
      if (sa == 0) {  // τ·0 ≥ β (or >) for all τ, or for none
        if (sb == 1) return 0;
        hit = hit && sb == -1;
      } else if (sa < 0) {  // τ ≤ v = β/α, and τ > 0: needs β < 0
        if (sb == 0 || sb == 1) return 0;
        hit = hit && sb == -1;
      }
    }
    for (std::size_t i = 0; i < m; ++i) {
      if (!(al[i].inf() > 0)) continue;
      for (std::size_t j = 0; j < m; ++j) {
        if (!(al[j].sup() < 0)) continue;
        // v_i < v_j  ⇔  β_i α_j − β_j α_i > 0 (α_i > 0 > α_j).
        const FI d = beta[i] * al[j] - beta[j] * al[i];
        if (d.sup() < 0) return 0;
        hit = hit && d.inf() > 0;
      }
    }
    return hit ? 1 : kUndecided;
  }

  // A witness that the cone meets the piece: a direction d = Σ w_j g_j
  // (w ≥ 0 exact doubles) and a double τ > 0 with every row strictly
  // satisfied at b0 + τd, checked in intervals (so closed and strict rows
  // alike hold, and μ = τw is a point of the exact LP); d from
  // some_combination, τ the middle of the doubles' window.
  bool certify_met(const std::vector<std::array<FI, 3>>& gens) const {
    const std::size_t m = beta.size(), n = gens.size();
    if (!complete || m == 0 || m > 64 || n == 0) return false;
    auto strictly_inside = [&](const std::array<FI, 3>& d) {
      internal::Protect guard;
      std::array<FI, 64> alpha;
      double lo = 0, hi = std::numeric_limits<double>::infinity();
      for (std::size_t h = 0; h < m; ++h) {
        alpha[h] = a[h][0] * d[0] + a[h][1] * d[1] + a[h][2] * d[2];
        const double al = CGAL::to_double(alpha[h]), be = CGAL::to_double(beta[h]);
        if (al > 0)
          lo = std::max(lo, be / al);
        else if (al < 0)
          hi = std::min(hi, be / al);
        else if (!(be < 0))
          return false;
      }
      if (!(lo < hi)) return false;
      const double tau = std::isfinite(hi) ? (lo + hi) / 2 : 2 * lo + 1;
      if (!(tau > 0) || !std::isfinite(tau)) return false;
      for (std::size_t h = 0; h < m; ++h)
        if (!((alpha[h] * FI(tau) - beta[h]).inf() > 0)) return false;
      return true;
    };
    return internal::some_combination(gens.data(), n, strictly_inside);
  }

  // A Farkas certificate that no μ ≥ 0 with Σ μ_j > 0 puts b0 + Σ μ_j g_j
  // in the piece's closure, so none puts it in the piece: y ≥ 0 with
  // Σ_h y_h a_h·g_j ≤ 0 for every j and y·β > 0; or, for b0 on the rows y
  // uses (β_h = 0, as when b0 is the apex of S and G = S), Σ_h y_h a_h·g_j
  // < 0 for every j and y·β ≥ 0 (docs/theory.md §8). Candidates are one row
  // (y = e_h), then two (y = (1 − t)e_h + t e_k, t mid-way in the interval
  // where the doubles satisfy every condition); each is checked in
  // intervals with y taken as exact. True only when certified.
  bool certify_missed(const std::vector<std::array<FI, 3>>& gens) const {
    const std::size_t m = beta.size(), n = gens.size();
    if (m == 0 || m > 64 || n == 0) return false;
    internal::Protect guard;
    std::vector<FI> alpha(m * n);  // alpha[h·n + j] = a_h·g_j
    for (std::size_t h = 0; h < m; ++h)
      for (std::size_t j = 0; j < n; ++j)
        alpha[h * n + j] = a[h][0] * gens[j][0] + a[h][1] * gens[j][1] + a[h][2] * gens[j][2];
    for (std::size_t h = 0; h < m; ++h) {
      bool weak = beta[h].inf() > 0, strict = beta[h].inf() >= 0;
      for (std::size_t j = 0; (weak || strict) && j < n; ++j) {
        weak = weak && alpha[h * n + j].sup() <= 0;
        strict = strict && alpha[h * n + j].sup() < 0;
      }
      if (weak || strict) return true;
    }
    auto mid = [](const FI& x) { return (x.inf() + x.sup()) / 2; };
    for (std::size_t h = 0; h < m; ++h)
      for (std::size_t k = h + 1; k < m; ++k) {
        // f(t) = u + t·(v − u) ≤ 0 for each generator, > 0 for β.
        double lo = 0, hi = 1;
        auto restrict = [&](double u, double v, bool positive) {
          if (positive) u = -u, v = -v;  // f > 0  ⇔  −f < 0
          const double slope = v - u;
          if (slope > 0)
            hi = std::min(hi, -u / slope);
          else if (slope < 0)
            lo = std::max(lo, -u / slope);
          else if (u > 0)
            lo = 2;  // infeasible
        };
        for (std::size_t j = 0; j < n; ++j) restrict(mid(alpha[h * n + j]), mid(alpha[k * n + j]), false);
        restrict(mid(beta[h]), mid(beta[k]), true);
        if (!(lo < hi)) continue;
        const double t = (lo + hi) / 2, s = 1 - t;
        if (!(t >= 0) || !(s >= 0)) continue;
        const FI yb = FI(s) * beta[h] + FI(t) * beta[k];
        bool weak = yb.inf() > 0, strict = yb.inf() >= 0;
        for (std::size_t j = 0; (weak || strict) && j < n; ++j) {
          const FI ya = FI(s) * alpha[h * n + j] + FI(t) * alpha[k * n + j];
          weak = weak && ya.sup() <= 0;
          strict = strict && ya.sup() < 0;
        }
        if (weak || strict) return true;
      }
    return false;
  }
};

// The guaranteed set G: a disjoint union of convex pieces.
class GuaranteedTarget final : public RegionTarget, public internal::IntervalTarget {
 public:
  GuaranteedTarget(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0) : G_(G), S_(S), b0_(b0) {
    for (const auto& piece : G_.pieces) enclosures_.emplace_back(piece, b0_);
  }
  const char* push_model() const override { return "step"; }
  const char* name() const override { return "G"; }

  // The region's interval pre-test: OUT and partial segments from
  // enclosures; IN segments (their magnitudes come from the piece that
  // holds the cone) and points (which can be partial) take the exact path.
  internal::IntervalTarget* interval_target() override { return this; }
  bool answers_points() const override { return false; }
  bool interval_magnitudes(const internal::FGen&, internal::FMagnitudes&) const override { return false; }

  // Hits G: hits some piece (1), misses every piece (0).
  int interval_ray_hits(const internal::FGen& g) const override {
    bool undecided = false;
    for (const auto& e : enclosures_) {
      const int h = e.ray_hits(g);
      if (h == 1) return 1;
      undecided = undecided || h == kUndecided;
    }
    return undecided ? kUndecided : 0;
  }

  // contains_cone: one piece that every generator's ray hits.
  int interval_contains(const internal::FGen* gens, const int*, std::size_t n) const override {
    bool undecided = false;
    for (const auto& e : enclosures_) {
      bool all = true, some_miss = false;
      for (std::size_t k = 0; k < n && !some_miss; ++k) {
        const int h = e.ray_hits(gens[k]);
        all = all && h == 1;
        some_miss = h == 0;
      }
      if (all) return 1;
      undecided = undecided || !some_miss;
    }
    return undecided ? kUndecided : 0;
  }

  // misses() of any cone that is not IN, decision by decision in its order:
  // per piece, a generator's ray that hits it, then the
  // certificates that stand for its LP (counted as the LP would be). Nothing
  // is counted unless the whole answer is certified.
  bool out_test_sees_hits() const override { return true; }
  int certify_out_test(const internal::FGen* gens, std::size_t n) override {
    const std::vector<internal::FGen> fg(gens, gens + n);
    long tests = 0;
    int answer = 1;
    for (std::size_t p = 0; p < G_.pieces.size() && answer == 1; ++p) {
      bool hit = false;
      for (std::size_t k = 0; k < n && !hit; ++k) {
        const int h = enclosures_[p].ray_hits(gens[k]);
        if (h == kUndecided) return kUndecided;
        hit = h == 1;
      }
      if (hit) {
        answer = 0;
        break;
      }
      ++tests;
      if (enclosures_[p].certify_missed(fg)) continue;
      if (!enclosures_[p].certify_met(fg)) return kUndecided;
      answer = 0;
    }
    if (stats) stats->lp_tests += tests;
    return answer;
  }

  void check_scene(const Scene& scene) const override { check_guaranteed_set_of(scene, S_, G_); }

  void check_pusher(const Rational& mu) const override {
    if (mu != 0)
      throw UnsupportedError("RegionOptions.pusher_mu", to_string(mu),
                             "against G is not supported: G is not convex, so the two friction edges hitting G "
                             "do not make every push direction between them hit G (use a frictionless pusher)");
  }

  std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>&) const override {
    throw UnsupportedError("RegionOptions.exact", "",
                           "against G is not supported: G is a union of pieces minus non-seating "
                           "sets with strict rows, and its exact region is a separate project "
                           "(docs/theory.md §12); use subdivision");
  }

  // The hit set of one convex piece is convex: IN when one piece holds
  // every generator's ray.
  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2* d_first, const Vec2* d_last,
                     RegionInterval* detail) override {
    if (!d_first) return false;
    hit_gens_ = gens;
    piece_hit_.assign(G_.pieces.size(), false);
    for (std::size_t p = 0; p < G_.pieces.size(); ++p) {
      const Polyhedron& piece = G_.pieces[p];
      std::vector<Magnitudes> T;
      bool all = true;
      for (const auto& g : gens) {
        T.push_back(ray_magnitudes(piece, b0_, g));
        all = all && !T.back().empty;
        if (!T.back().empty) piece_hit_[p] = true;
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
  // A piece some generator's ray hits (known from contains_cone on the same
  // generators) is not missed; otherwise an interval-certified Farkas
  // certificate, else the exact LP.
  bool misses(const std::vector<VectorQ>& gens) override {
    const bool hits_known = hit_gens_ == gens;
    std::vector<std::array<FI, 3>> fg;
    if (!force_exact())
      for (const auto& g : gens)
        fg.push_back({internal::to_interval(g[0]), internal::to_interval(g[1]), internal::to_interval(g[2])});
    for (std::size_t p = 0; p < G_.pieces.size(); ++p) {
      if (hits_known && piece_hit_[p]) return false;
      if (!force_exact()) {
        const bool missed = enclosures_[p].certify_missed(fg);
        const bool met = !missed && enclosures_[p].certify_met(fg);
        internal::record_filter(FilterSite::kOutTest, missed || met);
        if (missed || met) {
          if (stats) ++stats->lp_tests;  // as the LP it replaces would count
          if (met) return false;
          continue;
        }
      }
      if (!cone_misses_piece(b0_, stats, gens, G_.pieces[p])) return false;
    }
    return true;
  }

  RegionStatus test_point(const std::vector<VectorQ>& gens, const Vec2& d_first, const Vec2& d_last, Magnitudes* out,
                          std::vector<Magnitudes>* set) override {
    const bool one_ray = (d_first.x == d_last.x && d_first.y == d_last.y) ||  // the usual one: no product
                         internal::orientation_filtered(d_first, d_last) == 0;
    if (one_ray) {  // exact union of intervals
      if (!force_exact() && gens[0].size() == 3) {
        // A ray whose every piece certainly misses is OUT (G is the union
        // of its pieces) with no exact test; otherwise the exact union.
        const internal::FGen g{internal::to_interval(gens[0][0]), internal::to_interval(gens[0][1]),
                               internal::to_interval(gens[0][2])};
        const int hits = interval_ray_hits(g);
        internal::record_filter(FilterSite::kRegionTest, hits != kUndecided);
        if (hits == 0) {
          if (set) set->clear();
          if (out) *out = Magnitudes{};
          return RegionStatus::kOut;
        }
      }
      const std::vector<Magnitudes> parts = ray_magnitudes(G_, S_, b0_, gens[0]);
      // Report Euclidean |p| like every other magnitude: τ|d| with |d|
      // irrational, so each end is rounded inward (a certified subset).
      // Made also without `set`: a point test (push-plan) reads only `out`,
      // which used to stay empty then.
      std::vector<Magnitudes> windows;
      const Rational d2 = d_first.x * d_first.x + d_first.y * d_first.y;
      for (const auto& t : parts) {
        Magnitudes m = t;
        m.lo = t.lo * internal::sqrt_upper(d2);
        if (t.hi) m.hi = *t.hi * internal::sqrt_lower(d2);
        if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) continue;
        windows.push_back(m);
      }
      if (out) *out = windows.empty() ? Magnitudes{} : windows.front();
      if (set) *set = std::move(windows);
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
  const GuaranteedSet G_;  // copies: the caller's sets may be temporaries
  const SeatingSet S_;
  VectorQ b0_;
  std::vector<PieceEnclosure> enclosures_;
  std::vector<VectorQ> hit_gens_;  // the generators of the last contains_cone
  std::vector<bool> piece_hit_;    // per piece: some generator's ray hit it
};

}  // namespace

std::unique_ptr<RegionTarget> guaranteed_target(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0) {
  internal::check_rigid_seating_set(S, b0);
  for (const Polyhedron& piece : G.pieces)
    if (piece.dim != 3)
      throw InputError("G", "a piece of dimension " + std::to_string(piece.dim),
                       "a region target needs a rigid body's guaranteed set (dof 3)");
  return std::make_unique<GuaranteedTarget>(G, S, b0);
}

}  // namespace fixel
