#include "fixel/region.h"

#include <gtest/gtest.h>

#include <random>
#include <string>

#include "filter_test_util.h"
#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/internal/region_context.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/io.h"
#include "fixel/lcp.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/sustained.h"
#include "other_scene_region.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::scene_file;
using test::v3;

// Status of the interval holding (curve, u); corner points (zero-length
// intervals) take precedence over the intervals they bound.
const RegionInterval* interval_at(const Region& region, int curve, const Rational& u) {
  const RegionInterval* found = nullptr;
  for (const auto& r : region.intervals) {
    if (r.curve != curve || u < r.u0 || u > r.u1) continue;
    if (r.u0 == r.u1) return &r;
    if (!found) found = &r;
  }
  return found;
}

GTEST_TEST(RayMagnitudes, AgreeWithDirectMembershipAlongRandomRays) {
  std::mt19937_64 rng(71);
  const Scene scene = scene_file("example2");
  const SeatingSet S = seating_set(scene);
  int hits = 0, misses = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const VectorQ g = v3(test::random_rational(rng, -2, 1, 5), test::random_rational(rng, -2, 1, 5),
                         test::random_rational(rng, -2, 1, 5));
    const VectorQ b0 = trial % 3 == 0 ? VectorQ(S.apex + v3(-1, -1, -1) / 2) : VectorQ(VectorQ::Zero(3));
    const Magnitudes T = ray_magnitudes(S, b0, g);
    (T.empty ? misses : hits)++;
    for (int k = 1; k <= 40; ++k) {
      const Rational tau(k, 8);
      EXPECT_EQ(T.contains(tau), S.contains(VectorQ(b0 + tau * g))) << trial << " tau " << to_string(tau);
    }
    if (!T.empty) {  // the ends are exact
      if (T.lo > 0) {
        EXPECT_EQ(S.contains(VectorQ(b0 + T.lo * g)), T.lo_closed);
      }
      if (T.hi) {
        EXPECT_TRUE(S.contains(VectorQ(b0 + *T.hi * g)));
      }
    }
  }
  EXPECT_GT(hits, 30);
  EXPECT_GT(misses, 30);
}

GTEST_TEST(RayMagnitudes, PaperImpulseDirectionIsAHalfLine) {
  const Scene scene = scene_file("example2");
  const Magnitudes T = ray_magnitudes(seating_set(scene), VectorQ::Zero(3), v3(-1, -1, -1));
  EXPECT_TRUE(T.contains(1));
  EXPECT_TRUE(T.half_line());
}

// Soundness: on random blobs, for frictionless and frictional pushers,
// every exact rational sample inside an IN interval passes the exact point
// test and every one inside an OUT interval fails it.
GTEST_TEST(Region, IsSoundOnRandomBlobsByExactSampling) {
  std::mt19937_64 rng(73);
  long samples = 0;
  int scenes_with_in = 0, scenes_with_out = 0;
  for (int trial = 0; trial < 12; ++trial) {
    const Rational mu = trial % 2 == 0 ? Rational(0) : Rational(trial % 4 == 1 ? 1 : 3, 10);
    Scene scene = test::random_blob_scene(rng, mu);
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const Error&) {
      continue;
    }
    RegionOptions opt;
    opt.resolution = Rational(1, 64);
    const Region region = compute_region(scene, S, opt);
    bool any_in = false, any_out = false;
    for (const auto& r : region.intervals) {
      if (r.status == RegionStatus::kPartial) continue;
      any_in = any_in || r.status == RegionStatus::kIn;
      any_out = any_out || r.status == RegionStatus::kOut;
      const int k_max = r.u0 == r.u1 ? 0 : 400;
      for (int k = 0; k <= k_max; ++k) {
        const Rational u = k_max == 0 ? r.u0 : r.u0 + (r.u1 - r.u0) * Rational(k, k_max);
        const RegionInterval* owner = interval_at(region, r.curve, u);
        if (owner != &r) continue;  // a corner decides its own point
        Magnitudes m;
        const RegionStatus p = point_status(scene, S, r.curve, u, mu, &m);
        ASSERT_EQ(p, r.status) << "trial " << trial << " u " << to_string(u);
        if (r.status == RegionStatus::kIn && !r.magnitudes.empty) {
          // A certified common magnitude works at this point too.
          EXPECT_FALSE(m.empty);
        }
        ++samples;
      }
    }
    scenes_with_in += any_in;
    scenes_with_out += any_out;
  }
  EXPECT_GE(samples, 10000);
  EXPECT_GE(scenes_with_in, 4);
  EXPECT_GE(scenes_with_out, 8);
}

// Where the picture's push arrow points: the boundary point at the middle
// parameter, on the curve, not the midpoint of the chord between the ends
// (on blob's curved pieces the two differ; arrows once floated inside it).
GTEST_TEST(Region, EachIntervalsMiddleIsOnTheCurveAtItsMiddleParameter) {
  const Scene blob = scene_file("blob");
  const Region region = compute_region(blob, seating_set(blob), RegionOptions{});
  ASSERT_EQ(region.places.size(), region.intervals.size());
  int off_chord = 0;
  for (std::size_t k = 0; k < region.intervals.size(); ++k) {
    const RegionInterval& r = region.intervals[k];
    const IntervalPlace& at = region.places[k];
    ASSERT_TRUE(at.middle_A.has_value());
    const Vec2 on_curve = blob.body.boundary->curves[r.curve].point((r.u0 + r.u1) / 2);
    EXPECT_EQ((*at.middle_A)[0], to_double(on_curve.x));
    EXPECT_EQ((*at.middle_A)[1], to_double(on_curve.y));
    const Vec2 chord{(at.start_A.x + at.end_A.x) / 2, (at.start_A.y + at.end_A.y) / 2};
    off_chord += chord.x != on_curve.x || chord.y != on_curve.y;
  }
  EXPECT_GT(off_chord, 0);
}

GTEST_TEST(Region, CertifiedMagnitudesSeatEveryPushDirection) {
  // At sample points of IN intervals with a common magnitude range, the
  // lower end (and a larger value) pushed along the exact normal lands in S.
  for (const char* name : {"example2_rounded", "polygon", "blob"}) {
    const Scene scene = scene_file(name);
    const SeatingSet S = seating_set(scene);
    RegionOptions opt;
    opt.resolution = Rational(1, 256);
    const Region region = compute_region(scene, S, opt);
    int checked = 0;
    for (const auto& r : region.intervals) {
      if (r.status != RegionStatus::kIn || r.magnitudes.empty || r.u0 == r.u1) continue;
      for (const auto& piece : scene.body.boundary->pieces) {
        if (piece.curve != r.curve || piece.u1 <= r.u0 || piece.u0 >= r.u1) continue;
        for (int k = 0; k <= 8; ++k) {
          const Rational u =
              std::max(piece.u0, r.u0) + (std::min(piece.u1, r.u1) - std::max(piece.u0, r.u0)) * Rational(k, 8);
          const Vec2 T = piece.derivative(piece.local(u)), p = piece.point(piece.local(u));
          const Vec2 n{-T.y, T.x};
          const Rational L = internal::sqrt_upper(n.x * n.x + n.y * n.y);
          const Rational lo = r.magnitudes.lo * Rational(1001, 1000) + Rational(1, 1000000);
          std::vector<Rational> ms = {lo, r.magnitudes.lo * 2 + 1};
          if (r.magnitudes.hi) ms = {lo, (r.magnitudes.lo + *r.magnitudes.hi) / 2};
          for (const Rational& m : ms) {
            if (!r.magnitudes.contains(m)) continue;
            const VectorQ w = contact_wrench({p.x - scene.body.p_AoCm_A.x, p.y - scene.body.p_AoCm_A.y}, n, 3);
            const Magnitudes Tn = ray_magnitudes(S, scene.background_impulse, w);
            // The impulse of magnitude m along n is τ n with τ = m / |n|,
            // bracketed by m / L and m / L' (L' <= |n| <= L). T is an
            // interval, so both ends inside puts τ inside.
            EXPECT_TRUE(Tn.contains(m / L) && Tn.contains(m / internal::sqrt_lower(n.x * n.x + n.y * n.y)))
                << name << " u " << to_string(u) << " m " << to_string(m) << " T " << Tn.describe();
            ++checked;
          }
        }
      }
    }
    EXPECT_GT(checked, 0) << name;
  }
}

GTEST_TEST(Region, HalvingTheResolutionNeverTurnsADecidedPointPartial) {
  std::mt19937_64 rng(79);
  for (int trial = 0; trial < 4; ++trial) {
    Scene scene = test::random_blob_scene(rng);
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const Error&) {
      continue;
    }
    RegionOptions coarse, fine;
    coarse.resolution = Rational(1, 32);
    fine.resolution = Rational(1, 64);
    const Region a = compute_region(scene, S, coarse), b = compute_region(scene, S, fine);
    for (const auto& r : a.intervals) {
      if (r.status == RegionStatus::kPartial) continue;
      for (int k = 0; k <= 16; ++k) {
        const Rational u = r.u0 + (r.u1 - r.u0) * Rational(k, 16);
        if (interval_at(a, r.curve, u) != &r) continue;
        EXPECT_EQ(interval_at(b, r.curve, u)->status, r.status);
      }
    }
    EXPECT_LE(b.stats.partial_length, a.stats.partial_length);
  }
}

GTEST_TEST(Region, PartialLengthShrinksWithTheResolution) {
  const Scene scene = scene_file("blob");
  const SeatingSet S = seating_set(scene);
  // Asymptotically each transition leaves O(R) partial; from R = 1/1024 on
  // the bundled blob shows it (coarser R still resolve the region itself).
  Rational previous = -1;
  for (int k = 10; k <= 16; k += 2) {
    RegionOptions opt;
    opt.resolution = Rational(1, 1 << k);
    const Rational partial = compute_region(scene, S, opt).stats.partial_length;
    // Quartering R at least halves the partial length, and does not remove
    // it faster than R itself shrinks (roughly proportional).
    if (previous >= 0) {
      EXPECT_LE(partial, previous / 2) << "R = 1/" << (1 << k);
      EXPECT_GE(partial, previous / 8) << "R = 1/" << (1 << k);
    }
    EXPECT_GT(partial, 0);
    previous = partial;
  }
}

GTEST_TEST(Region, BundledExamplesAtResolutionRangeOver4096LeaveLittlePartial) {
  for (const char* name : {"example2_rounded", "blob", "polygon"}) {
    const Scene scene = scene_file(name);
    Rational total = 0;
    for (const auto& c : scene.body.boundary->curves) total += c.u_end() - c.u_begin();
    // Per-curve ranges differ; use the smallest so every curve gets at least
    // 1/4096 of its range.
    Rational smallest = total;
    for (const auto& c : scene.body.boundary->curves) smallest = std::min(smallest, Rational(c.u_end() - c.u_begin()));
    RegionOptions opt;
    opt.resolution = smallest / 4096;
    const Region region = compute_region(scene, seating_set(scene), opt);
    EXPECT_LE(region.stats.partial_length * 200, total) << name;
  }
}

GTEST_TEST(Region, IntervalsTileEveryCurveExactly) {
  for (const char* name : {"example2_rounded", "blob", "polygon", "fig6"}) {
    const Scene scene = scene_file(name);
    const Region region = compute_region(scene, seating_set(scene), RegionOptions{});
    for (std::size_t c = 0; c < scene.body.boundary->curves.size(); ++c) {
      Rational at = scene.body.boundary->curves[c].u_begin();
      for (const auto& r : region.intervals) {
        if (r.curve != static_cast<int>(c)) continue;
        EXPECT_EQ(r.u0, at) << name;
        EXPECT_LE(r.u0, r.u1);
        at = r.u1;
      }
      EXPECT_EQ(at, scene.body.boundary->curves[c].u_end()) << name;
    }
  }
}

GTEST_TEST(Region, SamplingBaselineAgreesWithEveryDecidedInterval) {
  for (const char* name : {"example2_rounded", "blob", "polygon"}) {
    const Scene scene = scene_file(name);
    const SeatingSet S = seating_set(scene);
    const Region region = compute_region(scene, S, RegionOptions{});
    const Region samples = sample_region(scene, S, 200);
    int compared = 0;
    for (const auto& s : samples.intervals) {
      const RegionInterval* r = interval_at(region, s.curve, s.u0);
      ASSERT_NE(r, nullptr);
      if (r->status == RegionStatus::kPartial) continue;
      EXPECT_EQ(s.status, r->status) << name << " u " << to_string(s.u0);
      ++compared;
    }
    EXPECT_GT(compared, 150) << name;
  }
}

// region_reaches stops at the first interval that is not OUT; its answer
// is whether compute_region has one (second method: the whole region).
// S of every bundled part with a boundary (fig6's region is all OUT), with
// and without pusher friction, two resolutions and the exact region; J of
// the polygon.
GTEST_TEST(RegionReaches, IsWhetherTheWholeRegionHasAnIntervalThatIsNotOut) {
  auto any_not_out = [](const Region& r) {
    for (const auto& i : r.intervals)
      if (i.status != RegionStatus::kOut) return true;
    return false;
  };
  int reached = 0, not_reached = 0;
  auto check = [&](const Scene& scene, RegionTarget& target, const RegionOptions& o, const std::string& what) {
    const bool answer = internal::region_reaches(scene, target, o);
    EXPECT_EQ(answer, any_not_out(compute_region(scene, target, o))) << what;
    (answer ? reached : not_reached) += 1;
  };
  for (const std::string name : {"example2_rounded", "fig6", "blob32", "polygon", "nonunique_part"}) {
    const Scene scene = scene_file(name);
    const SeatingSet S = seating_set(scene);
    for (const Rational& mu : {Rational(0), Rational(1, 10)})
      for (const Rational& resolution : {Rational(1, 16), Rational(1, 256)}) {
        RegionOptions o;
        o.pusher_mu = mu;
        o.resolution = resolution;
        const auto target = seating_target(S, scene.background_impulse);
        check(scene, *target, o, name + " S, mu " + to_string(mu) + ", resolution " + to_string(resolution));
      }
    RegionOptions exact;
    exact.exact = true;
    const auto target = seating_target(S, scene.background_impulse);
    check(scene, *target, exact, name + " S, exact region");
  }
  const Scene polygon = scene_file("polygon");
  const SustainedSet J = sustained_set(polygon);
  const auto sustained = sustained_target(J);
  check(polygon, *sustained, RegionOptions{}, "polygon J");
  EXPECT_GE(reached, 5);
  EXPECT_GE(not_reached, 3);
}

// Joins made once for many regions on one outline (fixture design) give
// each region exactly as compute_region makes it; joins of another outline
// are refused.
GTEST_TEST(Region, JoinsMadeBeforehandGiveTheSameRegion) {
  for (const std::string name : {"example2_rounded", "blob32", "polygon"}) {
    const Scene scene = scene_file(name);
    const SeatingSet S = seating_set(scene);
    const std::vector<internal::Join> js = internal::joins(*scene.body.boundary);
    for (const Rational& mu : {Rational(0), Rational(1, 10)}) {
      RegionOptions o;
      o.pusher_mu = mu;
      const auto target = seating_target(S, scene.background_impulse);
      const Region whole = compute_region(scene, *target, o);
      const Region joined = internal::compute_region_joined(scene, *target, o, &js);
      EXPECT_EQ(test::masked(region_json(scene, joined)), test::masked(region_json(scene, whole))) << name;
      EXPECT_EQ(internal::region_reaches(scene, *target, o, &js), internal::region_reaches(scene, *target, o));
    }
  }
  const Scene scene = scene_file("polygon"), other = scene_file("blob32");
  const SeatingSet S = seating_set(scene);
  const auto target = seating_target(S, scene.background_impulse);
  const std::vector<internal::Join> wrong = internal::joins(*other.body.boundary);
  EXPECT_THROW(internal::compute_region_joined(scene, *target, RegionOptions{}, &wrong), InternalError);
}

GTEST_TEST(Region, Fig6sRegionIsOutEverywhere) {
  const Scene scene = scene_file("fig6");
  const Region region = compute_region(scene, seating_set(scene), RegionOptions{});
  ASSERT_FALSE(region.intervals.empty());
  for (const auto& r : region.intervals) EXPECT_EQ(r.status, RegionStatus::kOut);
}

GTEST_TEST(Region, WholeBoundaryWhenTheBackgroundImpulseIsInsideS) {
  Scene scene = scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  // b0 = apex − Σ g_i is interior to S: every ray starts inside.
  scene.background_impulse = S.apex;
  for (const auto& g : S.generators) scene.background_impulse -= g;
  const Region region = compute_region(scene, S, RegionOptions{});
  ASSERT_EQ(region.intervals.size(), scene.body.boundary->curves.size());
  for (const auto& r : region.intervals) {
    EXPECT_EQ(r.status, RegionStatus::kIn);
    EXPECT_FALSE(r.magnitudes.empty);
    EXPECT_EQ(r.magnitudes.lo, 0);
    EXPECT_FALSE(r.magnitudes.lo_closed);
  }
}

GTEST_TEST(Region, NonZeroBackgroundImpulseShiftsTheRegion) {
  Scene scene = scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  const Region base = compute_region(scene, S, RegionOptions{});
  scene.background_impulse = v3(0, Rational(-1, 2), 0);  // e.g. gravity · h
  const Region shifted = compute_region(scene, S, RegionOptions{});
  Rational in_base = 0, in_shifted = 0;
  for (const auto& r : base.intervals) in_base += r.status == RegionStatus::kIn ? Rational(r.u1 - r.u0) : Rational(0);
  for (const auto& r : shifted.intervals)
    in_shifted += r.status == RegionStatus::kIn ? Rational(r.u1 - r.u0) : Rational(0);
  EXPECT_NE(in_base, in_shifted);
  // Sound under b0 too.
  for (const auto& r : shifted.intervals)
    if (r.status != RegionStatus::kPartial && r.u0 < r.u1) {
      const Rational mid = (r.u0 + r.u1) / 2;
      EXPECT_EQ(point_status(scene, S, r.curve, mid, 0), r.status);
    }
}

GTEST_TEST(Region, FrictionalPusherWithOneEdgeInAndOneOutIsOutNotPartial) {
  // On the right edge of the rounded rectangle with μ_p = 7/10 the n + μt
  // rays all hit S and the n − μt rays all miss. One classification must
  // settle the whole edge as OUT (the paper's single friction-cone bound
  // would leave it PARTIAL).
  const Scene scene = scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  RegionOptions opt;
  opt.pusher_mu = Rational(7, 10);
  opt.resolution = 2;  // no splitting at all
  const Region region = compute_region(scene, S, opt);
  const RegionInterval* edge = interval_at(region, 2, Rational(1, 2));
  ASSERT_NE(edge, nullptr);
  EXPECT_EQ(edge->status, RegionStatus::kOut);
  // The single-cone bound of the whole friction cone is neither IN nor OUT.
  const BezierPiece& piece = scene.body.boundary->pieces[2];
  const auto whole =
      segment_wrench_cone(piece, scene.body.p_AoCm_A, EdgeFamily::kWholeCone, Rational(7, 10), ConeMethod::kTight);
  ASSERT_TRUE(whole);
  int hit = 0;
  for (const auto& g : whole->generators) hit += ray_magnitudes(S, scene.background_impulse, g).empty ? 0 : 1;
  EXPECT_GT(hit, 0);
  EXPECT_LT(hit, static_cast<int>(whole->generators.size()));
}

GTEST_TEST(Region, RejectsBadOptionsAndScenesWithoutBoundary) {
  const Scene scene = scene_file("example2_rounded");
  const SeatingSet S = seating_set(scene);
  RegionOptions opt;
  opt.resolution = 0;
  EXPECT_THROW(compute_region(scene, S, opt), InputError);
  opt.resolution = 1;
  opt.pusher_mu = Rational(-1);
  EXPECT_THROW(compute_region(scene, S, opt), InputError);
  const Scene plain = scene_file("example2");
  EXPECT_THROW(compute_region(plain, seating_set(plain), RegionOptions{}), SceneError);
  EXPECT_THROW(sample_region(scene, S, 0), InputError);
  EXPECT_THROW(sample_region(scene, S, 1000001), InputError);  // bounded
}

// Each interval's curve, ends and status, as text.
std::string summary(const Region& r) {
  std::string out;
  for (const auto& i : r.intervals)
    out += std::to_string(i.curve) + " " + to_string(i.u0) + " " + to_string(i.u1) + " " + to_string(i.status) + "\n";
  return out;
}

// A target built from temporaries keeps its own copies of the sets (it kept
// references, and the region read freed memory), and a seating set that is
// not the scene's, or none at all, is refused (a default-constructed S read
// as all of R³: every push IN).
GTEST_TEST(Region, ATargetOfTemporarySetsGivesTheRegionOfNamedOnesAndAForeignSIsRefused) {
  const Scene scene = scene_file("example2_rounded");
  RegionOptions opt;
  opt.resolution = Rational(1, 64);
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const auto named = seating_target(S, scene.background_impulse);
  const auto temporary = seating_target(seating_set(scene), scene.background_impulse);
  EXPECT_EQ(summary(compute_region(scene, *temporary, opt)), summary(compute_region(scene, *named, opt)));
  const auto named_g = guaranteed_target(G, S, scene.background_impulse);
  const auto temporary_g =
      guaranteed_target(guaranteed_set(scene, seating_set(scene)), seating_set(scene), scene.background_impulse);
  EXPECT_EQ(summary(compute_region(scene, *temporary_g, opt)), summary(compute_region(scene, *named_g, opt)));
  EXPECT_THROW(compute_region(scene, SeatingSet{}, opt), InputError);
  EXPECT_THROW(seating_target(SeatingSet{}, scene.background_impulse), InputError);
  EXPECT_THROW(sample_region(scene, SeatingSet{}, 4), InputError);
  EXPECT_THROW(point_status(scene, SeatingSet{}, 0, Rational(1, 2), Rational(0)), InputError);
  const Scene polygon = scene_file("polygon");  // 3 fixels as well, but another S
  Scene fewer = polygon;
  fewer.fixels.pop_back();
  EXPECT_THROW(compute_region(fewer, seating_set(polygon), opt), InputError);
}

// A point mass (dof 2) has a two-dimensional S. Every region question is a
// SceneError naming body.dof, asked before a target is built from S (the
// target read S's rows as three-dimensional and crashed), and S itself is
// no region target.
GTEST_TEST(Region, APointMassIsASceneErrorForEveryRegionQuestionAndItsSIsNoTarget) {
  const Scene point_mass = parse_scene(R"({"time_step": "1",
    "body": {"dof": 2, "mass": "1", "boundary": [{"type": "polyline",
      "points": [["0", "0"], ["2", "0"], ["2", "2"], ["0", "2"], ["0", "0"]]}]},
    "fixels": [{"point": ["0", "1"], "normal": ["1", "0"], "mu": "1/5", "gap": "3/10"},
               {"point": ["1", "0"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/5"}]})");
  const SeatingSet S = seating_set(point_mass);
  ASSERT_EQ(S.dof, 2);
  auto names_dof = [](const auto& ask) {
    try {
      ask();
      ADD_FAILURE() << "no error";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find("body.dof"), std::string::npos) << e.what();
    }
  };
  names_dof([&] { compute_region(point_mass, S, RegionOptions{}); });
  names_dof([&] { sample_region(point_mass, S, 4); });
  names_dof([&] { point_status(point_mass, S, 0, Rational(1, 2), Rational(0)); });
  // A curve that does not exist is named as the bad value (not u).
  const Scene polygon = scene_file("polygon");
  for (const int curve : {-1, 1, 99}) {
    try {
      point_status(polygon, seating_set(polygon), curve, Rational(0), Rational(0));
      ADD_FAILURE() << curve;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "curve");
      EXPECT_EQ(e.value(), std::to_string(curve));
    }
  }
  EXPECT_THROW(seating_target(S, point_mass.background_impulse), InputError);
  EXPECT_THROW(seating_target(S, VectorQ::Zero(3)), InputError);
  // A rigid body's S with a two-component b0 is no target either.
  const Scene rigid = scene_file("example2_rounded");
  EXPECT_THROW(seating_target(seating_set(rigid), VectorQ::Zero(2)), InputError);
  EXPECT_NO_THROW(seating_target(seating_set(rigid), rigid.background_impulse));
}

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

// Coordinates far outside double's comfortable range must not reach a
// double-to-integer cast (undefined behaviour) or stall a rounding loop: the
// same part scaled by 10^200 and 10^-200 gives the same tight-cone region.
// The paper cone's rounded unit directions depend on the scale, so its
// region may be partial elsewhere; it never contradicts the unscaled one
// (IN against OUT), since both are exact where they decide.
GTEST_TEST(Region, ExtremeCoordinateScalesGiveTheSameTightRegionAndNoContradictingPaperRegion) {
  const Scene base = test::scene_file("polygon");
  const Region reference = compute_region(base, seating_set(base), RegionOptions{});
  RegionOptions paper;
  paper.cone = ConeMethod::kPaper;
  const Region paper_reference = compute_region(base, seating_set(base), paper);
  for (const char* factor : {"1e200", "1e-200"}) {
    const Rational k = parse_rational(factor);
    Scene scaled = base;
    std::vector<Curve> curves = base.body.boundary->curves;
    for (auto& c : curves)
      for (auto& p : c.points) p = {p.x * k, p.y * k};
    scaled.body.boundary = std::make_shared<const Boundary>(make_boundary(curves));
    scaled.body.p_AoCm_A = {base.body.p_AoCm_A.x * k, base.body.p_AoCm_A.y * k};
    scaled.body.inertia = base.body.inertia * k * k;  // I scales with length²
    for (auto& f : scaled.fixels) {
      f.p_AoF_A = {f.p_AoF_A.x * k, f.p_AoF_A.y * k};
      f.gap *= k;
    }
    const SeatingSet S = seating_set(scaled);
    for (auto method : {ConeMethod::kTight, ConeMethod::kPaper}) {
      RegionOptions opt;
      opt.cone = method;
      const Region region = compute_region(scaled, S, opt);
      if (method == ConeMethod::kPaper) {
        int compared = 0, in = 0;
        for (const auto& a : region.intervals) {
          in += a.status == RegionStatus::kIn;
          for (const auto& b : paper_reference.intervals) {
            if (a.curve != b.curve || !(a.u0 < b.u1 && b.u0 < a.u1)) continue;  // no common interior
            ++compared;
            const bool contradict = (a.status == RegionStatus::kIn && b.status == RegionStatus::kOut) ||
                                    (a.status == RegionStatus::kOut && b.status == RegionStatus::kIn);
            EXPECT_FALSE(contradict) << factor << " at u in [" << a.u0 << ", " << a.u1 << "]";
          }
        }
        EXPECT_GT(compared, 0) << factor;
        EXPECT_GT(in, 0) << factor;
        continue;
      }
      ASSERT_EQ(region.intervals.size(), reference.intervals.size()) << factor;
      for (std::size_t i = 0; i < region.intervals.size(); ++i) {
        EXPECT_EQ(region.intervals[i].status, reference.intervals[i].status) << factor;
        EXPECT_EQ(region.intervals[i].u1, reference.intervals[i].u1) << factor;
      }
    }
  }
}

}  // namespace
}  // namespace fixel

namespace fixel {
namespace {

GTEST_TEST(Region, RecordsItsTargetMethodResolutionAndPusherMu) {
  const Scene scene = test::scene_file("blob");
  const SeatingSet S = seating_set(scene);
  RegionOptions options;
  options.resolution = Rational(1, 16);
  options.cone = ConeMethod::kPaper;
  options.pusher_mu = Rational(1, 10);
  const Region r = compute_region(scene, S, options);
  EXPECT_EQ(r.target, "S");
  EXPECT_EQ(r.push, "step");
  EXPECT_EQ(method_of(r), "paper");
  EXPECT_EQ(*r.resolution, Rational(1, 16));
  EXPECT_EQ(r.pusher_mu, Rational(1, 10));
  const Region sampled = sample_region(scene, S, 4, std::nullopt);
  EXPECT_TRUE(sampled.sampled);
  EXPECT_EQ(method_of(sampled), "sample");
  EXPECT_FALSE(sampled.resolution.has_value());
  EXPECT_EQ(sampled.pusher_mu, scene.pusher_mu_upper());
}

GTEST_TEST(Region, LibraryErrorsNameTheOptionFieldNotACommandLineFlag) {
  const Scene scene = test::scene_file("blob");
  RegionOptions options;
  options.resolution = 0;
  try {
    compute_region(scene, seating_set(scene), options);
    FAIL() << "resolution 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "RegionOptions.resolution");
  }
}

GTEST_TEST(Region, ResolutionWidthIsTheLargestHalvingThatTheSpeedBoundAllows) {
  BezierPiece edge{0, Rational(2), Rational(3), {{Rational(0), Rational(0)}, {Rational(3, 4), Rational(1)}}};
  EXPECT_EQ(speed_bound(edge), Rational(5, 4));  // a 3-4-5 edge: its exact length
  EXPECT_EQ(resolution_width(edge, Rational(5, 4)), Rational(1));
  EXPECT_EQ(resolution_width(edge, Rational(5, 16)), Rational(1, 4));
  EXPECT_EQ(resolution_width(edge, Rational(5, 16) - Rational(1, 1000000)), Rational(1, 8));
  // An irrational length is rounded up: the edge (0,0)-(1,1) has speed sqrt 2.
  BezierPiece diagonal{0, Rational(0), Rational(1, 2), {{Rational(0), Rational(0)}, {Rational(1), Rational(1)}}};
  const Rational v = speed_bound(diagonal);
  EXPECT_GE(v * v, Rational(2));
  EXPECT_LT(v, Rational(1415, 1000));
  EXPECT_EQ(resolution_width(diagonal, Rational(1, 2)), Rational(1, 8));  // sqrt2/4 <= 1/2 < sqrt2/2
  // A quadratic piece: 2 × its longest leg.
  BezierPiece arc{1,
                  Rational(0),
                  Rational(1),
                  {{Rational(0), Rational(0)}, {Rational(3), Rational(4)}, {Rational(3), Rational(5)}}};
  EXPECT_EQ(speed_bound(arc), Rational(10));
  EXPECT_EQ(resolution_width(arc, Rational(1)), Rational(1, 16));
  EXPECT_THROW(resolution_width(edge, Rational(0)), InputError);
  EXPECT_THROW(resolution_width(edge, Rational(1, 1) / Rational(Integer(1) << 70)), InputError);
}

GTEST_TEST(Region, ResolutionLengthLeavesNoPartialStretchLongerThanIt) {
  for (const char* name : {"blob", "polygon", "example2_rounded"}) {
    const Scene scene = scene_file(name);
    const SeatingSet S = seating_set(scene);
    RegionOptions options;
    options.resolution_length = Rational(1, 8);
    options.merge = false;
    const Region region = compute_region(scene, S, options);
    ASSERT_TRUE(region.resolution_length.has_value());
    EXPECT_FALSE(region.resolution.has_value());
    const auto& pieces = scene.body.boundary->pieces;
    ASSERT_EQ(region.piece_widths.size(), pieces.size());
    int partial = 0;
    for (const auto& r : region.intervals) {
      if (r.status != RegionStatus::kPartial || r.u0 == r.u1) continue;
      ++partial;
      // The piece holding it, restricted to it: n·|leg| <= L for every leg
      // bounds its arc length by L (exactly, by squares).
      for (const auto& piece : pieces) {
        if (piece.curve != r.curve || r.u0 < piece.u0 || r.u1 > piece.u1) continue;
        const BezierPiece sub = piece.restrict_to(r.u0, r.u1);
        const Rational n = sub.degree();
        for (const Vec2& leg : sub.legs())
          EXPECT_LE(n * n * (leg.x * leg.x + leg.y * leg.y), *options.resolution_length * *options.resolution_length)
              << name << " curve " << r.curve << " [" << to_string(r.u0) << ", " << to_string(r.u1) << "]";
      }
    }
    EXPECT_GT(partial, 0) << name << ": nothing to check";
  }
  RegionOptions bad;
  bad.resolution_length = Rational(-1);
  const Scene scene = scene_file("polygon");
  EXPECT_THROW(compute_region(scene, seating_set(scene), bad), InputError);
}

// The bundled polygon with every gap 0. At the corner u = 2 (the point
// (3/2, 1/2)) the fan runs from the right edge's normal (−1, 0) to the
// roof's (−4, −5)/√41. By hand: (−1, 0)'s ray misses S and the roof
// normal's hits (ray_magnitudes below), so the corner is OUT while the IN
// interval on the roof starts there. The region lists that corner, and at
// every vertex end it does not list, the interval's status is the vertex's.
GTEST_TEST(Region, ACornerWhoseStatusAnIntervalEndingThereLacksIsListed) {
  Scene scene = scene_file("polygon");
  for (Fixel& f : scene.fixels) f.gap = 0;
  const SeatingSet S = seating_set(scene);
  const Vec2 c = scene.body.p_AoCm_A;
  const Vec2 r{Rational(3, 2) - c.x, Rational(1, 2) - c.y};
  auto wrench = [&](const Rational& nx, const Rational& ny) { return v3(nx, ny, r.x * ny - r.y * nx); };
  const VectorQ b0 = VectorQ::Zero(3);
  EXPECT_TRUE(ray_magnitudes(S, b0, wrench(-1, 0)).empty);
  EXPECT_FALSE(ray_magnitudes(S, b0, wrench(-4, -5)).empty);

  RegionOptions o;
  o.resolution = Rational(1, 1024);
  const Region region = compute_region(scene, S, o);
  ASSERT_EQ(region.corners.size(), 1u);
  EXPECT_EQ(region.corners[0].curve, 0);
  EXPECT_EQ(region.corners[0].u, 2);
  EXPECT_EQ(region.corners[0].status, RegionStatus::kOut);
  bool in_from_the_corner = false;
  for (const RegionInterval& i : region.intervals)
    in_from_the_corner = in_from_the_corner || (i.u0 == 2 && i.status == RegionStatus::kIn);
  EXPECT_TRUE(in_from_the_corner);
  // The vertices u = 1..4: an IN or OUT interval ending at one that is not
  // listed has the vertex's own status there (the whole fan).
  for (const RegionInterval& i : region.intervals) {
    if (i.status == RegionStatus::kPartial) continue;
    for (const Rational& end : {i.u0, i.u1}) {
      if (end <= 0 || end >= 5 || denominator(end) != 1) continue;
      const RegionCorner* listed = nullptr;
      for (const RegionCorner& k : region.corners)
        if (k.u == end) listed = &k;
      const RegionStatus own = point_status(scene, S, 0, end, Rational(0));
      EXPECT_EQ(own, listed ? listed->status : i.status) << to_string(end);
    }
  }
  // With the scene's own gaps no interval ends at a corner of another status.
  EXPECT_TRUE(compute_region(scene_file("polygon"), seating_set(scene_file("polygon")), o).corners.empty());
}

// Printed beside another scene, a region's stretches were labelled with
// that scene's name and placed on its outline.
GTEST_TEST(Region, ItsWritersRefuseAnotherScenesRegionNamingTheFieldThatDiffers) {
  const Scene rounded = test::scene_file("example2_rounded");
  const Scene polygon = test::scene_file("polygon");
  const Region region = test::rounded_region();
  const Region sampled = sample_region(rounded, seating_set(rounded), 3);
  for (const Region* r : {&region, &sampled}) {
    for (const std::string& e : {test::input_error_of([&] { region_json(polygon, *r); }),
                                 test::input_error_of([&] { region_text(polygon, *r); })}) {
      EXPECT_EQ(e.rfind("region: region: built from scene \"example2_rounded\" belongs to another scene than "
                        "\"polygon\": body.boundary has ",
                        0),
                0u)
          << e;
    }
  }
  // Where S's region looks: b0 (the background impulse) too.
  Scene pushed = rounded;
  pushed.background_impulse[0] += 1;
  EXPECT_NE(test::input_error_of([&] { region_json(pushed, region); }).find("background_impulse is ("),
            std::string::npos);
  // What no region reads (the name), and a region built by hand, pass.
  Scene renamed = rounded;
  renamed.name = "renamed";
  EXPECT_EQ(test::input_error_of([&] { region_json(renamed, region); }), "(no InputError)");
  Region by_hand = region;
  by_hand.built_from = nullptr;
  EXPECT_EQ(test::input_error_of([&] { region_text(pushed, by_hand); }), "(no InputError)");
}

// J's region reads the outline, mass properties and fixels only.
GTEST_TEST(Region, ASustainedRegionPassesASceneThatDiffersOnlyWhereJDoesNotLook) {
  const Scene polygon = test::scene_file("polygon");
  RegionOptions options;
  options.resolution = Rational(1, 16);
  const Region region = compute_region(polygon, *sustained_target(sustained_set(polygon)), options);
  Scene other = polygon;
  other.background_impulse[0] += 1;
  other.time_step *= 2;
  EXPECT_EQ(test::input_error_of([&] { region_json(other, region); }), "(no InputError)");
  other.fixels[2].gap += Rational(1, 100);
  EXPECT_NE(test::input_error_of([&] { region_json(other, region); }).find("fixels[2].gap is "), std::string::npos);
}

}  // namespace
}  // namespace fixel
