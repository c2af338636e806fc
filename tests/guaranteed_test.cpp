#include "fixel/guaranteed.h"

#include <gtest/gtest.h>

#include <chrono>
#include <functional>
#include <iostream>
#include <random>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/lcp.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::scene_file;
using test::v3;

// Second method: every enumerated LCP outcome at p seats.
bool every_outcome_seats(const Scene& scene, const VectorQ& p) {
  for (const auto& o : enumerate_outcomes(scene, p))
    if (!o.seated) return false;
  return true;
}

GTEST_TEST(GuaranteedSet, DesignSceneImpulseIsInSButNotGuaranteed) {
  const Scene scene = scene_file("nonunique");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const VectorQ p = v3(Rational(29157, 10540), Rational(-71119, 105400), Rational(-1169839, 263500));
  EXPECT_TRUE(S.contains(p));
  EXPECT_FALSE(G.contains(p, S));
  EXPECT_FALSE(every_outcome_seats(scene, p));  // what `fixel solutions` reports
  EXPECT_FALSE(G.non_seating.empty());
}

GTEST_TEST(GuaranteedSet, DeepImpulsesOfTheDesignSceneAreGuaranteedAndEnumerationAgrees) {
  const Scene scene = scene_file("nonunique");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  int guaranteed = 0;
  for (const Rational& t : {Rational(1, 10), Rational(1), Rational(10), Rational(100)})
    for (int w0 = 0; w0 <= 3; ++w0)
      for (int w1 = 0; w1 + w0 <= 3; ++w1) {
        const int w2 = 3 - w0 - w1;
        VectorQ p = S.apex - t * (Rational(w0 + 1) * S.generators[0] + Rational(w1 + 1) * S.generators[1] +
                                  Rational(w2 + 1) * S.generators[2]);
        const bool in_g = G.contains(p, S);
        EXPECT_EQ(in_g, every_outcome_seats(scene, p)) << "t " << to_string(t);
        guaranteed += in_g;
      }
  EXPECT_GT(guaranteed, 0);
}

GTEST_TEST(GuaranteedSet, Example2GuaranteedSetEqualsS) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  EXPECT_TRUE(G.non_seating.empty());
  ASSERT_EQ(G.pieces.size(), 1u);
  EXPECT_EQ(G.pieces[0].closed.size(), S.halfspaces.size());
  EXPECT_EQ(lost_fraction(S, G), Rational(0));
  EXPECT_THROW(lost_fraction(S, G, 1000000), InputError);  // bounded: it would test ~10¹⁷ points
}

// On seeded random scenes (μ from 0.05 to 2): guaranteed == contains &&
// every enumerated outcome seats, exactly, for many random impulses; the
// pieces represent the same set, disjointly.
GTEST_TEST(GuaranteedSet, AgreesWithEnumerationOnRandomScenes) {
  std::mt19937_64 rng(83);
  const int wanted = test::sanitizer_scaled(24);
  int scenes = 0, nonunique = 0, points = 0, lost_points = 0;
  for (int attempt = 0; attempt < 200 && scenes < wanted; ++attempt) {
    Scene scene = test::random_scene(rng, 3, 20);
    for (auto& f : scene.fixels) f.mu = Rational(1, 20) + test::random_rational(rng, 0, 2, 20) * Rational(39, 40);
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const Error&) {
      continue;
    }
    ++scenes;
    const GuaranteedSet G = guaranteed_set(scene, S);
    nonunique += G.non_seating.empty() ? 0 : 1;
    for (int k = 0; k < 12; ++k) {
      VectorQ p = S.apex;
      for (const auto& g : S.generators) p -= test::random_rational(rng, -1, 4, 5) * g;
      const bool in_g = G.contains(p, S);
      EXPECT_EQ(in_g, S.contains(p) && every_outcome_seats(scene, p)) << "scene " << scenes << " point " << k;
      int pieces = 0;
      for (const auto& q : G.pieces) pieces += q.contains(p) ? 1 : 0;
      EXPECT_EQ(pieces, in_g ? 1 : 0);
      ++points;
      lost_points += S.contains(p) && !in_g;
    }
  }
  EXPECT_EQ(scenes, wanted);
  EXPECT_GT(nonunique, 0);
  EXPECT_GT(lost_points, 0);
  std::cout << "[ info     ] " << nonunique << " of " << scenes << " random scenes have non-seating outcomes inside S; "
            << lost_points << " of " << points << " sampled impulses are in S but not guaranteed\n";
}

GTEST_TEST(GuaranteedSet, StickingScenesAgreeWithEnumeration) {
  std::string text = internal::paper::kExample2Scene;
  text.replace(text.find(R"("gap": "1/20")"), 13, R"("gap": "0")");
  text.replace(text.find(R"("gap": "1/5")"), 12, R"("gap": "0")");
  const Scene scene = parse_scene(text);
  const SeatingSet S = seating_set(scene);
  ASSERT_EQ(S.sliding[0], 0);
  const GuaranteedSet G = guaranteed_set(scene, S);
  std::mt19937_64 rng(89);
  int in_s = 0;
  for (int k = 0; k < 40; ++k) {
    VectorQ p = S.apex;
    for (const auto& g : S.generators) p -= test::random_rational(rng, -1, 3, 5) * g;
    // S itself against enumeration: p ∈ S iff some outcome seats.
    bool any_seats = false;
    for (const auto& o : enumerate_outcomes(scene, p)) any_seats = any_seats || o.seated;
    EXPECT_EQ(S.contains(p), any_seats);
    EXPECT_EQ(G.contains(p, S), S.contains(p) && every_outcome_seats(scene, p));
    in_s += S.contains(p);
  }
  EXPECT_GT(in_s, 5);
}

GTEST_TEST(SeatAndStay, IsSIntersectedWithTheWeakStabilityCone) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const SeatingSet S = seating_set(scene);
  const auto cone = stability_cone(scene);
  const ContactMatrices W = contact_matrices(scene);
  // Every −(W_n,i ± μ W_t,i) is in the cone; W_n,0 (pushing away) is not.
  for (int i = 0; i < 3; ++i)
    for (int s : {1, -1}) {
      const VectorQ w = -(W.Wn.col(i) + Rational(s, 10) * W.Wt.col(i));
      for (const auto& h : cone) EXPECT_GE(h.a.dot(w), 0);
    }
  bool outside = false;
  for (const auto& h : cone) outside = outside || h.a.dot(W.Wn.col(0)) < 0;
  EXPECT_TRUE(outside);
  const Polyhedron stay = seat_and_stay(scene, S);
  std::mt19937_64 rng(97);
  int both = 0;
  for (int k = 0; k < 200; ++k) {
    const VectorQ p = S.apex + v3(test::random_rational(rng, -3, 1, 7), test::random_rational(rng, -3, 1, 7),
                                  test::random_rational(rng, -3, 1, 7));
    bool in_cone = true;
    for (const auto& h : cone) in_cone = in_cone && h.contains(p);
    EXPECT_EQ(stay.contains(p), S.contains(p) && in_cone);
    both += stay.contains(p);
  }
  EXPECT_GT(both, 0);
  EXPECT_TRUE(stay.contains(v3(-1, -1, -1)));  // the paper's impulse also keeps the part seated
}

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

GTEST_TEST(GuaranteedRegion, IsInsideTheOrdinaryRegionAndSoundBySampling) {
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  RegionOptions opt;
  opt.resolution = Rational(1, 256);
  opt.guaranteed = &G;
  const Region against_g = compute_region(scene, S, opt);
  int in = 0, out = 0, samples = 0;
  for (const auto& r : against_g.intervals) {
    if (r.status == RegionStatus::kPartial) continue;
    (r.status == RegionStatus::kIn ? in : out)++;
    for (int k = 0; k <= 40; ++k) {
      const Rational u = r.u0 + (r.u1 - r.u0) * Rational(k, 40);
      // Exact point test against G: one ray, T_G as a union of intervals.
      EXPECT_EQ(point_status(scene, S, r.curve, u, 0, nullptr, &G), r.status) << to_string(u);
      // G ⊆ S: a point whose ray meets G meets S.
      if (r.status == RegionStatus::kIn) {
        EXPECT_EQ(point_status(scene, S, r.curve, u, 0), RegionStatus::kIn);
      }
      ++samples;
    }
  }
  EXPECT_GT(in, 0);
  EXPECT_GT(out, 0);
  EXPECT_GT(samples, 100);
  // Against S the same pushes all start inside S (b0 is interior): IN everywhere.
  const Region against_s = compute_region(scene, S, RegionOptions{});
  for (const auto& r : against_s.intervals) EXPECT_EQ(r.status, RegionStatus::kIn);
}

GTEST_TEST(GuaranteedRegion, IsOutWhereverTheOrdinaryRegionIsOutWhenB0IsTheApexOfS) {
  // Every gap 0: b0 = 0 is S's apex and lies in G (= S here). A push has a
  // positive magnitude, so a cone that meets G only at b0 misses it; G's OUT
  // test once let b0 alone make every piece "met", and left PARTIAL the
  // 82% of the polygon's outline where S is OUT.
  Scene scene = scene_file("polygon");
  for (auto& f : scene.fixels) f.gap = 0;
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  ASSERT_EQ(S.apex, scene.background_impulse);
  ASSERT_TRUE(G.contains(scene.background_impulse, S));
  RegionOptions opt;
  opt.resolution = Rational(1, 256);
  const Region against_s = compute_region(scene, S, opt);
  opt.guaranteed = &G;
  reset_filter_stats();
  const Region against_g = compute_region(scene, S, opt);
  const FilterCounts out_tests = filter_stats().at(FilterSite::kOutTest);
  Region exact_g;
  {
    ForceExactScope scope(true);
    exact_g = compute_region(scene, S, opt);
  }
  // G ⊆ S: no stretch OUT for S is IN or PARTIAL for G (intervals overlapping
  // in more than an end). Corners are left out: S's corner is IN or OUT
  // (OUT when not all of its fan is in S), G's can be PARTIAL.
  int s_out = 0, g_out = 0;
  for (const auto& r : against_s.intervals) {
    if (r.status != RegionStatus::kOut) continue;
    ++s_out;
    for (const auto& q : against_g.intervals)
      if (q.curve == r.curve && q.u0 < q.u1 && q.u0 < r.u1 && r.u0 < q.u1) {
        EXPECT_EQ(q.status, RegionStatus::kOut)
            << "S is OUT on [" << to_string(r.u0) << ", " << to_string(r.u1) << "], G is not on [" << to_string(q.u0)
            << ", " << to_string(q.u1) << "]";
      }
  }
  for (const auto& q : against_g.intervals) g_out += q.status == RegionStatus::kOut;
  EXPECT_GT(s_out, 0);
  EXPECT_GT(g_out, 0);
  // Second method: the forced exact path (the LP with Σμ > 0) agrees, and
  // the filter certified misses with b0 on the piece's rows (the strict
  // Farkas form) instead of sending every one to the LP.
  ASSERT_EQ(exact_g.intervals.size(), against_g.intervals.size());
  for (std::size_t i = 0; i < exact_g.intervals.size(); ++i) {
    EXPECT_EQ(exact_g.intervals[i].u0, against_g.intervals[i].u0);
    EXPECT_EQ(exact_g.intervals[i].status, against_g.intervals[i].status);
  }
  EXPECT_GT(out_tests.certified, out_tests.fallbacks);
}

// G records its scene. With every gap 0 and the part at rest, S's apex is
// 0 whatever the mass, so a heavier part has the same S and its check
// passes; G's non-seating sets come from the step LCP, which the mass
// enters, so G of the lighter part is refused beside the heavier one,
// naming G and what differs.
GTEST_TEST(GuaranteedRegion, AGOfAnotherSceneIsRefusedNamingGWhereItsSPasses) {
  Scene scene = scene_file("polygon");
  for (auto& f : scene.fixels) f.gap = 0;
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  Scene heavier = scene;
  heavier.body.mass *= 2;
  heavier.body.mass_from_area = false;
  EXPECT_NO_THROW(check_seating_set_of(heavier, S));
  RegionOptions opt;
  opt.resolution = Rational(1, 16);
  opt.guaranteed = &G;
  auto refused = [](const std::function<void()>& f) {
    try {
      f();
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "G");
      EXPECT_NE(
          std::string(e.what()).find(
              "belongs to another scene than \"polygon\": body.mass is 10 here, 5 in the scene it was built from"),
          std::string::npos)
          << e.what();
      return true;
    }
    return false;
  };
  EXPECT_TRUE(refused([&] { compute_region(heavier, S, opt); }));
  EXPECT_TRUE(refused([&] { point_status(heavier, S, 0, Rational(5, 2), 0, nullptr, &G); }));
  EXPECT_TRUE(refused([&] { guaranteed_target(G, S, heavier.background_impulse)->check_scene(heavier); }));
  EXPECT_NO_THROW(compute_region(scene, S, opt));
  // A G built by hand records no scene and is not checked.
  GuaranteedSet by_hand = G;
  by_hand.built_from = nullptr;
  opt.guaranteed = &by_hand;
  EXPECT_NO_THROW(compute_region(heavier, S, opt));
}

GTEST_TEST(GuaranteedRegion, RayMagnitudesAgainstGAreTheExactUnionOfIntervals) {
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  int checked = 0, split = 0;
  for (const auto& piece : scene.body.boundary->pieces)
    for (int k = 0; k < 4; ++k) {
      const Rational s(2 * k + 1, 8);
      const Vec2 T = piece.derivative(s), x = piece.point(s);
      const VectorQ g = contact_wrench({x.x - scene.body.p_AoCm_A.x, x.y - scene.body.p_AoCm_A.y}, {-T.y, T.x}, 3);
      const std::vector<Magnitudes> parts = ray_magnitudes(G, S, scene.background_impulse, g);
      split += parts.size() > 1;
      // Second method: exact membership of b0 + τ g in G at many τ.
      for (int j = 1; j <= 80; ++j) {
        const Rational tau(j, 16);
        bool in_union = false;
        for (const auto& m : parts) in_union = in_union || m.contains(tau);
        EXPECT_EQ(in_union, G.contains(VectorQ(scene.background_impulse + tau * g), S));
        ++checked;
      }
      for (const auto& m : parts) {  // the ends are exact too
        if (m.lo > 0) {
          EXPECT_EQ(G.contains(VectorQ(scene.background_impulse + m.lo * g), S), m.lo_closed);
        }
        if (m.hi) {
          EXPECT_EQ(G.contains(VectorQ(scene.background_impulse + *m.hi * g), S), m.hi_closed);
        }
      }
    }
  EXPECT_GT(checked, 3000);
  std::cout << "[ info     ] " << split << " sampled rays meet G in more than one interval\n";
}

GTEST_TEST(GuaranteedRegion, ConeMissTestsAgreeWithTheExactLpAndMostAreCertifiedEitherWay) {
  // Second method: the same target with the filters off (the exact LP per piece).
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const auto target = guaranteed_target(G, S, scene.background_impulse);
  std::vector<VectorQ> wrenches;
  for (const auto& piece : scene.body.boundary->pieces)
    for (int k = 0; k < 6; ++k) {
      const Rational s(2 * k + 1, 12);
      const Vec2 T = piece.derivative(s), x = piece.point(s);
      const Vec2 r{x.x - scene.body.p_AoCm_A.x, x.y - scene.body.p_AoCm_A.y};
      wrenches.push_back(contact_wrench(r, {-T.y, T.x}, 3));
      wrenches.push_back(contact_wrench(r, {-T.y + T.x / 3, T.x + T.y / 3}, 3));
    }
  reset_filter_stats();
  int missed = 0, met = 0;
  for (std::size_t i = 0; i < wrenches.size(); ++i)
    for (std::size_t j = i + 1; j < wrenches.size(); j += 9) {
      const std::vector<VectorQ> gens{wrenches[i], wrenches[j]};
      const bool filtered = target->misses(gens);
      bool exact;
      {
        ForceExactScope scope(true);
        exact = target->misses(gens);
      }
      ASSERT_EQ(filtered, exact) << "generators " << i << ", " << j;
      (filtered ? missed : met) += 1;
    }
  const FilterCounts out = filter_stats().at(FilterSite::kOutTest);
  std::cout << "[ info     ] " << missed << " cones miss G, " << met << " meet it; out test certified " << out.certified
            << ", exact LP " << out.fallbacks << "\n";
  EXPECT_GT(missed, 0);
  EXPECT_GT(met, 0);
  EXPECT_GT(out.certified, 0);
  // A cone that meets G has no Farkas certificate; it is certified by a
  // point strictly inside the piece it meets (without that witness every
  // one of them went to the LP: fallbacks >= met).
  EXPECT_LT(out.fallbacks, met / 4);
}

GTEST_TEST(GuaranteedRegion, OneRayPointTestsAgreeWithTheExactUnionAndMissesAreCertified) {
  // Second method: the same point test with the filters off (the exact
  // union of S's interval minus the non-seating sets). Points along the
  // boundary, pushed along the inward normal and along directions turned
  // from it; the pre-test answers OUT only when every piece certainly
  // misses, so the status, the reported magnitudes and their set agree.
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const auto target = guaranteed_target(G, S, scene.background_impulse);
  reset_filter_stats();
  int out = 0, in = 0;
  for (const auto& piece : scene.body.boundary->pieces)
    for (int k = 0; k < 24; ++k) {
      const Rational s(2 * k + 1, 48);
      const Vec2 T = piece.derivative(s), x = piece.point(s);
      const Vec2 r{x.x - scene.body.p_AoCm_A.x, x.y - scene.body.p_AoCm_A.y};
      for (const Vec2& d :
           {Vec2{-T.y, T.x}, Vec2{-T.y + T.x / 2, T.x + T.y / 2}, Vec2{-T.y - T.x / 2, T.x - T.y / 2}}) {
        const std::vector<VectorQ> gens{contact_wrench(r, d, 3)};
        Magnitudes filtered_out, exact_out;
        std::vector<Magnitudes> filtered_set, exact_set;
        const RegionStatus filtered = target->test_point(gens, d, d, &filtered_out, &filtered_set);
        RegionStatus exact;
        {
          ForceExactScope scope(true);
          exact = target->test_point(gens, d, d, &exact_out, &exact_set);
        }
        ASSERT_EQ(filtered, exact) << "piece at u0 = " << piece.u0 << ", s = " << s;
        auto same = [](const Magnitudes& a, const Magnitudes& b) {
          return a.empty == b.empty && a.lo == b.lo && a.lo_closed == b.lo_closed && a.hi == b.hi &&
                 a.hi_closed == b.hi_closed;
        };
        EXPECT_TRUE(same(filtered_out, exact_out));
        ASSERT_EQ(filtered_set.size(), exact_set.size());
        for (std::size_t m = 0; m < exact_set.size(); ++m) EXPECT_TRUE(same(filtered_set[m], exact_set[m]));
        (filtered == RegionStatus::kOut ? out : in) += 1;
      }
    }
  const FilterCounts region = filter_stats().at(FilterSite::kRegionTest);
  std::cout << "[ info     ] " << out << " rays miss G, " << in << " meet it; region test certified "
            << region.certified << ", exact " << region.fallbacks << "\n";
  EXPECT_GT(out, 0);
  EXPECT_GT(in, 0);
  EXPECT_GT(region.certified, out / 2);
}

GTEST_TEST(GuaranteedRegion, SampleMagnitudesAreCertifiedEuclideanSubsets) {
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const Region samples = sample_region(scene, S, 24, std::nullopt, &G);
  int checked = 0;
  for (const auto& r : samples.intervals) {
    EXPECT_EQ(r.status == RegionStatus::kIn, !r.magnitude_set.empty());
    const Rational u = r.u0;
    const BezierPiece* piece = nullptr;
    for (const auto& p : scene.body.boundary->pieces)
      if (u >= p.u0 && u < p.u1) piece = &p;
    ASSERT_NE(piece, nullptr);
    const Vec2 T = piece->derivative(piece->local(u)), x = piece->point(piece->local(u));
    const Vec2 n{-T.y, T.x};
    const VectorQ g = contact_wrench({x.x - scene.body.p_AoCm_A.x, x.y - scene.body.p_AoCm_A.y}, n, 3);
    const Rational n2 = n.x * n.x + n.y * n.y;
    for (const auto& m : r.magnitude_set) {
      const Rational mid = m.hi ? Rational((m.lo + *m.hi) / 2) : Rational(m.lo + 1);
      // |p| = mid along n̂ is τ = mid / |n| ∈ [mid / L, mid / L']; both ends
      // must lie in G along the ray (and in one of its intervals).
      const Rational t0 = mid / internal::sqrt_upper(n2), t1 = mid / internal::sqrt_lower(n2);
      bool same_interval = false;
      for (const auto& t : ray_magnitudes(G, S, scene.background_impulse, g))
        same_interval = same_interval || (t.contains(t0) && t.contains(t1));
      EXPECT_TRUE(same_interval) << to_string(u);
      ++checked;
    }
  }
  EXPECT_GT(checked, 5);
}

GTEST_TEST(GuaranteedRegion, FrictionalPusherIsAClearNotSupportedError) {
  const Scene scene = scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  RegionOptions opt;
  opt.guaranteed = &G;
  opt.pusher_mu = Rational(1, 5);
  try {
    compute_region(scene, S, opt);
    ADD_FAILURE() << "a frictional pusher was taken with G";
  } catch (const UnsupportedError& e) {
    EXPECT_EQ(e.field(), "RegionOptions.pusher_mu");
  }
  // The same μ from the scene (none given) names the scene's field, so the
  // CLI does not name an option the user never gave.
  Scene frictional = scene;
  frictional.pusher_mu = Rational(1, 5);
  const SeatingSet S2 = seating_set(frictional);
  const GuaranteedSet G2 = guaranteed_set(frictional, S2);
  opt.guaranteed = &G2;
  opt.pusher_mu.reset();
  for (int sample = 0; sample < 2; ++sample) {
    try {
      if (sample)
        sample_region(frictional, *guaranteed_target(G2, S2, frictional.background_impulse), 4);
      else
        compute_region(frictional, S2, opt);
      ADD_FAILURE() << "a frictional pusher was taken with G";
    } catch (const UnsupportedError& e) {
      EXPECT_EQ(e.field(), "pusher.mu");
      EXPECT_EQ(std::string(e.what()),
                "pusher.mu: 1/5 against G is not supported: G is not convex, so the two friction edges "
                "hitting G do not make every push direction between them hit G (use a frictionless pusher); it is "
                "the scene's pusher friction, taken when no pusher mu is given");
    }
  }
}

// The CLI's --max-seconds and Ctrl-C reach the construction of G: a
// cancelled control stops it at its first contact mode, a deadline already
// past likewise, each with the task and the count in the message; an
// untouched control lets it finish with the same G as no control.
GTEST_TEST(GuaranteedSet, AStoppedControlStopsTheConstructionWithItsCount) {
  const Scene scene = scene_file("nonunique");
  const SeatingSet S = seating_set(scene);
  RunControl cancelled;
  cancelled.cancel = true;
  try {
    (void)guaranteed_set(scene, S, &cancelled);
    ADD_FAILURE() << "not stopped";
  } catch (const StoppedError& e) {
    EXPECT_NE(std::string(e.what()).find("guaranteed set: interrupted after 0 of 64 contact modes"), std::string::npos)
        << e.what();
  }
  RunControl late;
  late.deadline = RunControl::Clock::now() - std::chrono::seconds(1);
  EXPECT_THROW((void)guaranteed_set(scene, S, &late), StoppedError);
  RunControl open;
  const GuaranteedSet with = guaranteed_set(scene, S, &open), without = guaranteed_set(scene, S);
  ASSERT_EQ(with.pieces.size(), without.pieces.size());
  EXPECT_EQ(with.non_seating.size(), without.non_seating.size());
  EXPECT_EQ(with.dimensions, without.dimensions);
  // The same G, row for row: a control that never fires changes nothing.
  auto same_rows = [](const std::vector<Halfspace>& a, const std::vector<Halfspace>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
      if (a[i].a != b[i].a || a[i].c != b[i].c) return false;
    return true;
  };
  for (std::size_t k = 0; k < with.pieces.size(); ++k) {
    EXPECT_TRUE(same_rows(with.pieces[k].closed, without.pieces[k].closed)) << "piece " << k;
    EXPECT_TRUE(same_rows(with.pieces[k].strict, without.pieces[k].strict)) << "piece " << k;
  }
}

// The check every consumer of G runs: S first (named S), then the scene G
// was built from (named G, even where S passes); a G built by hand passes.
GTEST_TEST(GuaranteedSet, ItsSceneCheckNamesSThenGAndPassesAGBuiltByHand) {
  const test::SetCheckScenes s = test::set_check_scenes();
  const SeatingSet S = seating_set(s.scene);
  const GuaranteedSet G = guaranteed_set(s.scene, S);
  EXPECT_EQ(test::input_error_of([&] { check_guaranteed_set_of(s.scene, S, G); }), "(no InputError)");
  const std::string g = test::input_error_of([&] { check_guaranteed_set_of(s.heavier, S, G); });
  EXPECT_EQ(g.rfind("G: ", 0), 0u) << g;
  EXPECT_NE(g.find("body.mass is 10 here, 5 in the scene it was built from; build it from this scene"),
            std::string::npos)
      << g;
  const std::string s_named = test::input_error_of([&] { check_guaranteed_set_of(s.gapped, S, G); });
  EXPECT_EQ(s_named.rfind("S: ", 0), 0u) << s_named;
  GuaranteedSet by_hand = G;
  by_hand.built_from = nullptr;
  EXPECT_EQ(test::input_error_of([&] { check_guaranteed_set_of(s.heavier, S, by_hand); }), "(no InputError)");
}

}  // namespace
}  // namespace fixel
