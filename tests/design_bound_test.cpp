// Fixture design's pair bound (include/fixel/internal/design_bound.h): it
// is at least every triple's score, it counts every cell where K's rows
// hold, and the bounded search reports the exhaustive search's layouts.
#include "fixel/internal/design_bound.h"

#include <gtest/gtest.h>

#include <map>
#include <tuple>

#include "fixel/design.h"
#include "fixel/filter.h"
#include "fixel/internal/design_detail.h"
#include "fixel/internal/region_runs.h"
#include "test_util.h"

namespace fixel {
namespace {

using internal::PairBound;
using test::scene_file;

// Every other of the part's 24 default candidates: 12, 220 triples.
std::vector<DesignCandidate> every_other(const Scene& part) {
  std::vector<DesignCandidate> all = boundary_candidates(part, std::nullopt), out;
  for (std::size_t k = 0; k < all.size(); k += 2) out.push_back(all[k]);
  return out;
}

PairBound bound_of(const Scene& part, const std::vector<DesignCandidate>& c, const DesignOptions& o) {
  PairBound b(part, c, o);
  for (long p = 0; p < b.pair_count(); ++p) b.compute_pair(p);
  return b;
}

// K's rows a_k (docs/theory.md §10.2) of three normal wrenches, from the
// definition: −sign(det W_n) times the rows of adj(W_n).
std::array<VectorQ, 3> k_rows(const std::array<VectorQ, 3>& W) {
  auto cross = [](const VectorQ& a, const VectorQ& b) {
    VectorQ c(3);
    c << a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0];
    return c;
  };
  const Rational det = W[0].dot(cross(W[1], W[2]));
  std::array<VectorQ, 3> rows;
  for (int i = 0; i < 3; ++i) rows[i] = (det > 0 ? -1 : 1) * cross(W[(i + 1) % 3], W[(i + 2) % 3]);
  return rows;
}

GTEST_TEST(PairBound, IsAtLeastEveryTriplesSustainedScoreAndItsUpperEndAtLeastTheBound) {
  for (const char* name : {"polygon", "blob", "fig6"}) {
    const Scene part = scene_file(name);
    const auto c = every_other(part);
    const long n = static_cast<long>(c.size());
    const auto joins = internal::joins(*part.body.boundary);
    const Rational total = internal::total_length(*part.body.boundary);
    // Pusher μ 0 and 1/5 with the fixels' μ 1/10; and fixel μ in [0, 1/5]
    // (J judged at 1/5, so are the jam cones).
    for (int variant = 0; variant < 3; ++variant) {
      DesignOptions o;
      o.pusher_mu = variant == 1 ? Rational(1, 5) : Rational(0);
      if (variant == 2) o.mu = 0, o.mu_hi = Rational(1, 5);
      const Rational& pusher_mu = o.pusher_mu;
      const PairBound b = bound_of(part, c, o);
      int scored = 0, informative = 0;
      for (long index = 0; index < triple_count(n); ++index) {
        const auto f = triple_at(n, index);
        DesignLayout layout;
        const internal::Verdict v = internal::evaluate(part, c, o, total, f, layout, &joins);
        ASSERT_EQ(b.singular(f), v == internal::Verdict::kSingular) << name << " triple " << index;
        if (v == internal::Verdict::kSingular) continue;
        const Rational exact = b.exact(f);
        EXPECT_LE(exact, Rational(1));
        EXPECT_GE(Rational(b.upper(f)), exact) << name << " triple " << index;
        if (v == internal::Verdict::kNoFormClosure) continue;
        ++scored;
        EXPECT_GE(exact, layout.score) << name << " triple " << index << " mu_p " << pusher_mu;
        informative += exact < 1;
      }
      EXPECT_GE(scored, 50) << name;
      EXPECT_GE(informative, scored / 2) << name;  // the bound says something about most
    }
  }
}

// Whether w lies in the closed cone of `gens` (three dimensions), by
// Carathéodory: in the cone of some three independent generators, with
// coefficients from Cramer's rule (no facets, unlike the code under test).
bool in_closed_cone(const std::vector<VectorQ>& gens, const VectorQ& w) {
  auto det = [](const VectorQ& a, const VectorQ& b, const VectorQ& c) {
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  };
  const std::size_t m = gens.size();
  for (std::size_t i = 0; i < m; ++i)
    for (std::size_t j = i + 1; j < m; ++j)
      for (std::size_t k = j + 1; k < m; ++k) {
        const Rational d = det(gens[i], gens[j], gens[k]);
        if (d == 0) continue;
        const Rational li = det(w, gens[j], gens[k]) / d, lj = det(gens[i], w, gens[k]) / d,
                       lk = det(gens[i], gens[j], w) / d;
        if (li >= 0 && lj >= 0 && lk >= 0) return true;
      }
  return false;
}

// The jam cone −(FC_a + FC_b) of two candidates (docs/theory.md §10.2):
// its four generators −(W_n ± μ W_t).
std::vector<VectorQ> jam_generators(const Scene& part, const DesignCandidate& a, const DesignCandidate& b,
                                    const Rational& mu) {
  std::vector<VectorQ> g;
  for (const DesignCandidate* c : {&a, &b}) {
    const Vec2 r = sub(c->point, part.body.p_AoCm_A);
    const VectorQ n = contact_wrench(r, c->normal, 3), t = contact_wrench(r, Vec2{-c->normal.y, c->normal.x}, 3);
    g.push_back(-(n + mu * t));
    g.push_back(-(n - mu * t));
  }
  return g;
}

// Stretches of the outline as (curve, u0, u1), in loop order.
using Stretches = std::vector<std::tuple<int, Rational, Rational>>;

// The stretches of a frictionless finger's region against `target`, at the
// pair bound's resolution, whose status `keep` accepts (corners dropped).
template <class Keep>
Stretches region_stretches(const Scene& part, RegionTarget& target, const Rational& resolution, Keep&& keep) {
  RegionOptions o;
  o.resolution = resolution;
  o.pusher_mu = Rational(0);
  o.merge = false;
  Stretches out;
  for (const auto& iv : compute_region(part, target, o).intervals)
    if (iv.u0 != iv.u1 && keep(iv.status)) out.emplace_back(iv.curve, iv.u0, iv.u1);
  return out;
}

// What both lists hold (sorted, disjoint stretches).
Stretches intersect(const Stretches& a, const Stretches& b) {
  Stretches out;
  for (const auto& [ca, a0, a1] : a)
    for (const auto& [cb, b0, b1] : b)
      if (ca == cb && std::max(a0, b0) < std::min(a1, b1)) out.emplace_back(ca, std::max(a0, b0), std::min(a1, b1));
  return out;
}

// What `a` holds outside `cut`.
Stretches minus(const Stretches& a, const Stretches& cut) {
  Stretches out;
  for (auto [ca, lo, hi] : a) {
    for (const auto& [cc, c0, c1] : cut) {
      if (cc != ca || c1 <= lo || c0 >= hi) continue;
      if (c0 > lo) out.emplace_back(ca, lo, c0);
      lo = std::max(lo, c1);
      if (lo >= hi) break;
    }
    if (lo < hi) out.emplace_back(ca, lo, hi);
  }
  return out;
}

// A second method for the whole bound: the pair regions made by the region
// code itself (compute_region against the pair's open half-space and its
// jam cone, at the same resolution), K's rows from their definition, and
// the intersection's length in rationals. PairBound makes the same tests on
// cones it builds once per node of the grid and shares between pairs, so
// the two must agree exactly, triple by triple.
GTEST_TEST(PairBound, IsTheBoundOfTheRegionsAgainstEachPairsHalfSpaceAndJamCone) {
  for (const char* name : {"polygon", "blob"}) {
    const Scene part = scene_file(name);
    const auto all = boundary_candidates(part, std::nullopt);
    std::vector<DesignCandidate> c;
    for (std::size_t k = 0; k < all.size(); k += 3) c.push_back(all[k]);  // 8 candidates, 56 triples
    const int n = static_cast<int>(c.size());
    const Rational total = internal::total_length(*part.body.boundary);
    DesignOptions o;
    o.mu = Rational(1, 5);
    const Rational resolution = std::max(o.resolution, total / PairBound::kCells);
    std::vector<VectorQ> W;
    for (const auto& x : c) W.push_back(contact_wrench(sub(x.point, part.body.p_AoCm_A), x.normal, 3));
    // Per pair a < b: [0] c · w > 0 may hold, [1] c · w < 0 may, less the jam cone's IN stretches.
    std::map<std::pair<int, int>, std::array<Stretches, 2>> sides;
    for (int a = 0; a < n; ++a)
      for (int b = a + 1; b < n; ++b) {
        const VectorQ cab = internal::cross3(W[a], W[b]);
        if (cab.isZero()) continue;
        auto half = internal::open_half_space_target(cab);
        const Stretches may_pos =
            region_stretches(part, *half, resolution, [](RegionStatus s) { return s != RegionStatus::kOut; });
        const Stretches may_neg =
            region_stretches(part, *half, resolution, [](RegionStatus s) { return s != RegionStatus::kIn; });
        std::vector<VectorQ> jam = jam_generators(part, c[a], c[b], o.mu);
        auto cone = internal::closed_cone_target(cone_facet_normals(jam, 3));
        const Stretches held =
            region_stretches(part, *cone, resolution, [](RegionStatus s) { return s == RegionStatus::kIn; });
        sides[{a, b}] = {minus(may_pos, held), minus(may_neg, held)};
      }
    const PairBound bound = bound_of(part, c, o);
    int below_one = 0;
    for (long index = 0; index < triple_count(n); ++index) {
      const auto f = triple_at(n, index);
      if (bound.singular(f)) continue;
      const auto rows = k_rows({W[f[0]], W[f[1]], W[f[2]]});
      Stretches shared{{-1, Rational(0), Rational(0)}};
      for (int i = 0; i < 3; ++i) {
        const int a = f[(i + 1) % 3], b = f[(i + 2) % 3];
        const VectorQ cab = internal::cross3(W[std::min(a, b)], W[std::max(a, b)]);
        // Row i is a positive multiple of c_ab or of −c_ab.
        const bool along = rows[i].dot(cab) > 0;
        const Stretches& side = sides.at({std::min(a, b), std::max(a, b)})[along ? 0 : 1];
        shared = i == 0 ? side : intersect(shared, side);
      }
      Rational length(0);
      for (const auto& [curve, u0, u1] : shared) length += u1 - u0;
      EXPECT_EQ(bound.exact(f), length / total) << name << " triple " << index;
      below_one += length < total;
    }
    EXPECT_GE(below_one, 20) << name;
  }
}

// A second method: at the midpoint of every cell of the pairs' grid, the
// exact push wrench, K's rows from their definition and the jam cones from
// their generators. Where all three rows are positive there and no pair's
// jam cone holds the push, no row's region can have found that cell OUT
// and no jam cone can hold the whole cell, so the bound counts it.
GTEST_TEST(PairBound, CountsEveryCellWhoseMidpointPushIsStrictlyInsideKAndOutsideTheJamCones) {
  for (const char* name : {"polygon", "example2_rounded", "blob"})
    for (const Rational& pusher_mu : {Rational(0), Rational(1, 5)}) {
      const Scene part = scene_file(name);
      const auto c = every_other(part);
      const long n = static_cast<long>(c.size());
      DesignOptions o;
      o.pusher_mu = pusher_mu;
      const PairBound b = bound_of(part, c, o);
      const Boundary& outline = *part.body.boundary;
      const Rational total = internal::total_length(outline);
      const Rational resolution = std::max(o.resolution, total / PairBound::kCells);
      int checked = 0;
      for (long index = 0; index<triple_count(n); index += pusher_mu> 0 ? 3 : 7) {
        const auto f = triple_at(n, index);
        if (b.singular(f)) continue;
        std::array<VectorQ, 3> W;
        for (int i = 0; i < 3; ++i) W[i] = contact_wrench(sub(c[f[i]].point, part.body.p_AoCm_A), c[f[i]].normal, 3);
        const auto rows = k_rows(W);
        const std::array<std::vector<VectorQ>, 3> jams = {jam_generators(part, c[f[0]], c[f[1]], o.mu),
                                                          jam_generators(part, c[f[0]], c[f[2]], o.mu),
                                                          jam_generators(part, c[f[1]], c[f[2]], o.mu)};
        Rational inside = 0;
        for (const auto& piece : outline.pieces) {
          Rational cell = piece.u1 - piece.u0;
          int cells = 1;
          while (cell > resolution) cell /= 2, cells *= 2;
          for (int k = 0; k < cells; ++k) {
            const Rational s = (Rational(k) + Rational(1, 2)) / cells;  // the cell's midpoint, piece-local
            const Vec2 t = piece.derivative(s);
            if (t.x == 0 && t.y == 0) continue;
            // The push's fan edges n ± μ_p t (n the tangent turned +90°, as
            // long as t): the normal alone without friction.
            const Vec2 normal{-t.y, t.x};
            std::vector<Vec2> edges{normal};
            if (pusher_mu > 0)
              edges = {Vec2{normal.x + pusher_mu * t.x, normal.y + pusher_mu * t.y},
                       Vec2{normal.x - pusher_mu * t.x, normal.y - pusher_mu * t.y}};
            bool counts = true;
            for (const Vec2& d : edges) {
              const VectorQ w = contact_wrench(sub(piece.point(s), part.body.p_AoCm_A), d, 3);
              counts = counts && rows[0].dot(w) > 0 && rows[1].dot(w) > 0 && rows[2].dot(w) > 0 &&
                       !in_closed_cone(jams[0], w) && !in_closed_cone(jams[1], w) && !in_closed_cone(jams[2], w);
            }
            if (counts) inside += cell / total;
          }
        }
        EXPECT_GE(b.exact(f), inside) << name << " triple " << index << " pusher mu " << pusher_mu;
        checked += inside > 0;
      }
      EXPECT_GE(checked, 5) << name << " pusher mu " << pusher_mu;
    }
}

void expect_same_layouts(const DesignResult& a, const DesignResult& b, const std::string& what) {
  ASSERT_EQ(a.layouts.size(), b.layouts.size()) << what;
  for (std::size_t k = 0; k < a.layouts.size(); ++k) {
    const DesignLayout &x = a.layouts[k], &y = b.layouts[k];
    EXPECT_EQ(x.fixels, y.fixels) << what << " #" << k;
    EXPECT_EQ(x.index, y.index) << what << " #" << k;
    EXPECT_EQ(x.score, y.score) << what << " #" << k;
    EXPECT_EQ(x.sustained_score, y.sustained_score) << what << " #" << k;
    EXPECT_EQ(x.sustained_empty, y.sustained_empty) << what << " #" << k;
    EXPECT_EQ(x.step_score, y.step_score) << what << " #" << k;
    EXPECT_EQ(x.note, y.note) << what << " #" << k;
  }
  EXPECT_EQ(a.no_layout, b.no_layout) << what;
}

GTEST_TEST(Design, TheBoundedSearchReportsTheLayoutsOfScoringEveryTriple) {
  int skipped_somewhere = 0;
  for (const char* name : {"polygon", "example2_rounded", "blob"}) {
    const Scene part = scene_file(name);
    const std::vector<DesignCandidate> c = every_other(part);
    struct Case {
      int top;
      Rational pusher_mu, mu;
      std::optional<Rational> mu_hi;
    };
    for (const Case& kase : {Case{5, 0, Rational(1, 10), {}}, Case{1, 0, Rational(1, 10), {}},
                             Case{2, Rational(1, 5), Rational(1, 10), {}}, Case{3, 0, 0, Rational(1, 5)}}) {
      DesignOptions o;
      o.resolution = Rational(1, 32);
      o.top = kase.top;
      o.pusher_mu = kase.pusher_mu;
      o.mu = kase.mu;
      o.mu_hi = kase.mu_hi;
      o.jobs = 1;
      const DesignResult bounded = design(part, c, o);
      o.jobs = 2;
      const DesignResult bounded2 = design(part, c, o);
      o.bound = false;
      const DesignResult every = design(part, c, o);
      const std::string what = std::string(name) + " top " + std::to_string(kase.top);
      expect_same_layouts(bounded, every, what);
      expect_same_layouts(bounded2, every, what + " (2 threads)");
      const DesignStats &s = bounded.stats, &s2 = bounded2.stats;
      EXPECT_EQ(s.singular + s.no_form_closure + s.j_empty + s.regions + s.bounded, s.triples) << what;
      EXPECT_EQ(s.singular, every.stats.singular) << what;
      EXPECT_EQ(every.stats.bounded, 0) << what;
      // The counts do not depend on the threads either.
      EXPECT_EQ(std::make_tuple(s.no_form_closure, s.j_empty, s.regions, s.bounded),
                std::make_tuple(s2.no_form_closure, s2.j_empty, s2.regions, s2.bounded))
          << what;
      skipped_somewhere += s.bounded > 0;
    }
  }
  EXPECT_GE(skipped_somewhere, 6);
}

// On nonunique_part every layout scores 0 (J is empty, or its region has no
// IN stretch): the pilot (32 triples spread over the indices) scores
// nothing above 0, and the search then scores every triple rather than pay
// for the pair regions.
GTEST_TEST(Design, APartWhosePilotScoresNothingAboveZeroIsSearchedWithoutTheBound) {
  const Scene part = scene_file("nonunique_part");
  std::vector<DesignCandidate> all = boundary_candidates(part, std::nullopt), c;
  for (std::size_t k = 0; k < all.size(); k += 3) c.push_back(all[k]);  // 8 candidates, 56 triples
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.jobs = 1;
  reset_filter_stats();
  const DesignResult bounded = design(part, c, o);
  const FilterCounts counted = filter_stats().at(FilterSite::kDesignBound);
  EXPECT_EQ(counted.certified + counted.fallbacks, 0);  // no triple was bounded
  o.bound = false;
  const DesignResult every = design(part, c, o);
  expect_same_layouts(bounded, every, "nonunique_part");
  EXPECT_EQ(bounded.stats.bounded, 0);
  EXPECT_EQ(bounded.stats.j_empty, every.stats.j_empty);
  ASSERT_FALSE(every.layouts.empty());
  EXPECT_EQ(every.layouts.front().score, 0);  // the best scores 0, so every layout does
}

// The rule at the K-th layout, directly: a triple whose exact bound equals
// the K-th score may still tie it, and then enters only with an earlier
// index; an upper end equal to the K-th score proves nothing about the
// triples after it.
GTEST_TEST(PairBound, ATripleWhoseBoundEqualsTheKthScoreEntersOnlyWithAnEarlierIndex) {
  const Scene part = scene_file("polygon");
  const auto c = every_other(part);
  const PairBound b = bound_of(part, c, DesignOptions{});
  const long n = static_cast<long>(c.size());
  int tested = 0;
  for (long index = 1; index + 1 < triple_count(n) && tested < 20; index += 5) {
    const auto f = triple_at(n, index);
    if (b.singular(f)) continue;
    const Rational exact = b.exact(f);
    if (exact == 0) continue;
    const double upper = b.upper(f);
    for (const bool forced : {false, true}) {
      const ForceExactScope scope(forced);
      EXPECT_TRUE(b.can_enter(f, index, upper, exact, index + 1));
      EXPECT_FALSE(b.can_enter(f, index, upper, exact, index - 1));
      EXPECT_TRUE(b.can_enter(f, index, upper, exact / 2, index - 1));
      EXPECT_FALSE(b.can_enter(f, index, upper, exact * 2, index + 1));
      EXPECT_FALSE(b.none_can_enter(upper, Rational(upper), 1));
      EXPECT_FALSE(b.none_can_enter(upper, exact, 1));
      // Below the upper end by a little: proved only on the filtered path.
      EXPECT_EQ(b.none_can_enter(upper, Rational(upper) + Rational(1, 1 << 30), 1), !forced);
    }
    ++tested;
  }
  EXPECT_EQ(tested, 20);
}

GTEST_TEST(Design, TheBoundedSearchSkipsTheSameTriplesWithTheExactPathForced) {
  const Scene part = scene_file("polygon");
  std::vector<DesignCandidate> all = boundary_candidates(part, std::nullopt), c;
  for (std::size_t k = 0; k < all.size(); k += 3) c.push_back(all[k]);
  DesignOptions o;
  o.resolution = Rational(1, 32);
  o.top = 2;
  o.jobs = 1;
  reset_filter_stats();
  const DesignResult filtered = design(part, c, o);
  const FilterCounts counted = filter_stats().at(FilterSite::kDesignBound);
  DesignResult exact;
  {
    const ForceExactScope forced;
    exact = design(part, c, o);
  }
  expect_same_layouts(filtered, exact, "forced exact");
  const DesignStats &s = filtered.stats, &t = exact.stats;
  EXPECT_EQ(std::make_tuple(s.singular, s.no_form_closure, s.j_empty, s.regions, s.bounded),
            std::make_tuple(t.singular, t.no_form_closure, t.j_empty, t.regions, t.bounded));
  EXPECT_GT(s.bounded, 0);
  // Every skip was certified by the upper ends; every determinant sign was
  // decided by its enclosure except at exact zeros (the singular triples).
  EXPECT_GT(counted.certified, s.bounded);
  EXPECT_LE(counted.fallbacks, s.singular + s.regions + s.j_empty + s.no_form_closure);
}

}  // namespace
}  // namespace fixel
