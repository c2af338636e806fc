// The one-step target G of the pushing region: the guaranteed set
// (docs/theory.md §9), a disjoint union of convex pieces, behind
// RegionTarget.
#include <memory>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/region_targets.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region_target.h"

namespace fixel {

namespace {

using internal::common_magnitudes;

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

std::unique_ptr<RegionTarget> guaranteed_target(const GuaranteedSet& G, const SeatingSet& S, const VectorQ& b0) {
  return std::make_unique<GuaranteedTarget>(G, S, b0);
}

}  // namespace fixel
