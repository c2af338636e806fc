// The exact pushing region (RegionOptions::exact, docs/theory.md §12):
// hand-derived endpoints, sign checks at every endpoint on seeded random
// B-spline parts, and agreement with subdivision.
#include <gtest/gtest.h>

#include <chrono>
#include <random>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/sustained.h"
#include "test_util.h"

namespace fixel {
namespace {

// A target with a known answer: a push is IN iff a·w > 0 for every
// generator w (a half-space of wrench directions).
class HalfspaceTarget final : public RegionTarget {
 public:
  explicit HalfspaceTarget(VectorQ a) : a_(std::move(a)) {}
  const char* push_model() const override { return "sustained"; }
  const char* name() const override { return "half-space"; }
  bool contains_cone(const std::vector<VectorQ>& gens, const Vec2*, const Vec2*, RegionInterval*) override {
    for (const auto& g : gens)
      if (a_.dot(g) <= 0) return false;
    return true;
  }
  bool misses(const std::vector<VectorQ>& gens) override {
    for (const auto& g : gens)
      if (a_.dot(g) > 0) return false;
    return true;
  }
  std::vector<Polynomial> sign_polynomials(const std::vector<std::array<Polynomial, 3>>& gens) const override {
    std::vector<Polynomial> out;
    for (const auto& g : gens) {
      Polynomial p;
      for (int k = 0; k < 3; ++k) {
        if (p.size() < g[k].size()) p.resize(g[k].size(), Rational(0));
        for (std::size_t i = 0; i < g[k].size(); ++i) p[i] += a_[k] * g[k][i];
      }
      out.push_back(p);
    }
    return out;
  }

 private:
  VectorQ a_;
};

// The square [−1, 1]² whose bottom edge is curve 0 (a polyline, or a cubic
// B-spline with control points (−1,−1), (−2/3,−1), (0,−1), (1,−1): the
// straight edge with x(s) = s² + s − 1), then the other three sides.
Scene square(bool cubic_bottom) {
  Curve bottom;
  if (cubic_bottom) {
    bottom.type = Curve::Type::kBSpline;
    bottom.degree = 3;
    bottom.points = {{-1, -1}, {Rational(-2, 3), -1}, {0, -1}, {1, -1}};
    bottom.knots = {0, 0, 0, 0, 1, 1, 1, 1};
  } else {
    bottom.points = {{-1, -1}, {1, -1}};
  }
  Curve rest;
  rest.points = {{1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
  Scene s = test::scene_file("polygon");
  s.body.boundary = std::make_shared<const Boundary>(make_boundary({bottom, rest}));
  s.body.p_AoCm_A = {0, 0};
  s.pusher_mu = 0;
  return s;
}

const RegionInterval* starting_at(const Region& region, int curve, const Rational& u) {
  for (const auto& r : region.intervals)
    if (r.curve == curve && r.u0 == u && r.u1 > r.u0) return &r;
  return nullptr;
}

GTEST_TEST(RegionExact, AStraightEdgeHasItsRationalEndpointInClosedForm) {
  // Bottom edge P(u) = (−1 + 2u, −1), tangent (2, 0), inward normal (0, 2):
  // w = (0, 2, 2(−1 + 2u)). With a = (0, −1, 3), a·w = 12u − 8: IN on (2/3, 1).
  const Scene scene = square(false);
  HalfspaceTarget target(test::v3(0, -1, 3));
  RegionOptions opt;
  opt.exact = true;
  const Region region = compute_region(scene, target, opt);
  const RegionInterval* in = starting_at(region, 0, Rational(2, 3));
  ASSERT_NE(in, nullptr);
  EXPECT_EQ(in->status, RegionStatus::kIn);
  EXPECT_EQ(in->u1, 1);
  EXPECT_FALSE(in->exact_u0.has_value());  // rational: u0 itself
  const RegionInterval* out = starting_at(region, 0, Rational(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->status, RegionStatus::kOut);
  EXPECT_EQ(out->u1, Rational(2, 3));
  for (const auto& r : region.intervals) EXPECT_NE(r.status, RegionStatus::kPartial);
}

GTEST_TEST(RegionExact, ACubicPieceHasTheGoldenRatioAsItsEndpoint) {
  // x(s) = s² + s − 1 along the cubic bottom edge, tangent (2s + 1, 0) > 0,
  // w = (0, 2s + 1, x(s)(2s + 1)). With a = (0, 0, 1) the push is IN iff
  // x(s) > 0, i.e. s > (√5 − 1)/2, the root of s² + s − 1.
  const Scene scene = square(true);
  HalfspaceTarget target(test::v3(0, 0, 1));
  RegionOptions opt;
  opt.exact = true;
  opt.digits = 12;
  const Region region = compute_region(scene, target, opt);
  const RegionInterval* in = nullptr;
  for (const auto& r : region.intervals)
    if (r.curve == 0 && r.exact_u0) in = &r;
  ASSERT_NE(in, nullptr);
  EXPECT_EQ(in->status, RegionStatus::kIn);
  EXPECT_EQ(in->u1, 1);
  const AlgebraicReal& e = *in->exact_u0;
  EXPECT_EQ(e.poly, (std::vector<Integer>{-1, 1, 1}));
  EXPECT_LE(e.hi - e.lo, Rational(1, 1000000000000LL));
  // (√5 − 1)/2 ∈ [lo, hi] ⇔ 2lo + 1 <= √5 <= 2hi + 1, squared exactly.
  EXPECT_LE((2 * e.lo + 1) * (2 * e.lo + 1), 5);
  EXPECT_GE((2 * e.hi + 1) * (2 * e.hi + 1), 5);
  EXPECT_EQ(certified_decimal(e).substr(0, 12), "0.6180339887");
}

// --max-seconds and Ctrl-C were not checked while the ends were refined to
// D digits (22 s at D = 1000 on a degree-20 piece, exit 0): the refining
// polls the run's control like every other stage.
GTEST_TEST(RegionExact, RefiningTheEndsPollsTheRunControl) {
  const Scene scene = square(true);
  HalfspaceTarget target(test::v3(0, 0, 1));
  RunControl control;
  control.interval = std::chrono::milliseconds(0);
  bool refining_seen = false;
  control.on_progress = [&](const char*, long, long, const char* unit) {
    if (std::string(unit) == "intervals' ends refined") {
      refining_seen = true;
      control.cancel = true;  // the next poll, still refining, stops the run
    }
  };
  RegionOptions opt;
  opt.exact = true;
  opt.digits = 12;
  opt.control = &control;
  EXPECT_THROW(compute_region(scene, target, opt), StoppedError);
  EXPECT_TRUE(refining_seen);
}

GTEST_TEST(RegionExact, RefusesTheGuaranteedSetWithAClearError) {
  const Scene scene = test::scene_file("nonunique_part");
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  RegionOptions opt;
  opt.exact = true;
  opt.guaranteed = &G;
  try {
    compute_region(scene, S, opt);
    FAIL() << "no error";
  } catch (const UnsupportedError& e) {
    EXPECT_NE(std::string(e.what()).find("RegionOptions.exact: against G is not supported"), std::string::npos)
        << e.what();
  }
  opt.guaranteed = nullptr;
  opt.digits = -1;
  EXPECT_THROW(compute_region(scene, S, opt), InputError);
}

// The end shared by intervals a and b, as an algebraic number.
AlgebraicReal end_of(const RegionInterval& a) { return a.exact_u1 ? *a.exact_u1 : AlgebraicReal::rational(a.u1); }
AlgebraicReal start_of(const RegionInterval& b) { return b.exact_u0 ? *b.exact_u0 : AlgebraicReal::rational(b.u0); }

// A rational strictly between algebraic numbers x < y.
Rational between(AlgebraicReal x, AlgebraicReal y) {
  for (int k = 0; k < 400 && !(x.hi < y.lo); ++k) {
    if (!x.is_rational()) x = refined(x, (x.hi - x.lo) / 2);
    if (!y.is_rational()) y = refined(y, (y.hi - y.lo) / 2);
  }
  EXPECT_LT(x.hi, y.lo);
  return (x.hi + y.lo) / 2;
}

// Every end between two stretches of positive length is a true change: the
// exact point test just inside each neighbour gives that neighbour's status,
// and the two differ. Returns the number of ends checked.
int check_ends(const Scene& scene, RegionTarget& target, const Region& region, const Rational& mu) {
  int checked = 0;
  const auto& iv = region.intervals;
  for (std::size_t i = 0; i + 1 < iv.size(); ++i) {
    const RegionInterval &a = iv[i], &b = iv[i + 1];
    if (a.curve != b.curve || a.u0 == a.u1 || b.u0 == b.u1) continue;
    EXPECT_EQ(a.u1, b.u0);
    EXPECT_NE(a.status, b.status) << "spurious end at " << to_string(a.u1);
    EXPECT_NE(a.status, RegionStatus::kPartial);
    EXPECT_NE(b.status, RegionStatus::kPartial);
    const AlgebraicReal e = end_of(a);
    const Rational left = between(start_of(a), e), right = between(e, end_of(b));
    EXPECT_EQ(point_status(scene, target, a.curve, left, mu), a.status) << to_string(left);
    EXPECT_EQ(point_status(scene, target, b.curve, right, mu), b.status) << to_string(right);
    ++checked;
  }
  return checked;
}

GTEST_TEST(RegionExact, EveryEndpointIsATrueChangeOnRandomPartsForSAndJ) {
  std::mt19937_64 rng(1501);
  int ends_S = 0, ends_J = 0, irrational = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const Rational mu = trial % 2 == 0 ? Rational(0) : Rational(1, 5);
    Scene scene = test::random_blob_scene(rng, mu);
    RegionOptions opt;
    opt.exact = true;
    try {
      const SeatingSet S = seating_set(scene);
      auto target = seating_target(S, scene.background_impulse);
      const Region region = compute_region(scene, *target, opt);
      ends_S += check_ends(scene, *target, region, mu);
      for (const auto& r : region.intervals) irrational += r.exact_u0.has_value();
    } catch (const SceneError&) {
    }
    for (auto& f : scene.fixels) f.gap = 0;  // q* = 0: J exact on a curved part
    try {
      const SustainedSet J = sustained_set(scene);
      auto target = sustained_target(J);
      const Region region = compute_region(scene, *target, opt);
      ends_J += check_ends(scene, *target, region, mu);
      for (const auto& r : region.intervals) irrational += r.exact_u0.has_value();
    } catch (const SceneError&) {
    }
  }
  EXPECT_GE(ends_S, 10);
  EXPECT_GE(ends_J, 10);
  EXPECT_GE(irrational, 10);
}

GTEST_TEST(RegionExact, JOverAQuadraticFieldGivesTrueEndpointsOnThePolygon) {
  // The polygon's seat is rotated: J's rows lie in Q(√d), the sign
  // polynomials are norms, and some of their roots belong to the conjugate.
  const Scene scene = test::scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  auto target = sustained_target(J);
  for (const Rational& mu : {Rational(0), Rational(1, 10)}) {
    RegionOptions opt;
    opt.exact = true;
    opt.pusher_mu = mu;
    const Region region = compute_region(scene, *target, opt);
    EXPECT_GE(check_ends(scene, *target, region, mu), 2);
  }
}

// Each IN/OUT stretch of the subdivision lies inside an exact stretch of
// the same status. Returns the number of stretches compared.
int check_agreement(const Region& a, const Region& b) {
  int compared = 0;
  for (const auto& r : a.intervals) {
    if (r.status == RegionStatus::kPartial) continue;
    bool inside = false;
    for (const auto& e : b.intervals)
      if (e.curve == r.curve && e.status == r.status && compare(start_of(e), r.u0) <= 0 &&
          compare(end_of(e), r.u1) >= 0)
        inside = true;
    EXPECT_TRUE(inside) << "[" << to_string(r.u0) << ", " << to_string(r.u1) << "] " << to_string(r.status);
    ++compared;
  }
  for (const auto& e : b.intervals) EXPECT_TRUE(e.status != RegionStatus::kPartial || e.u0 == e.u1);
  return compared;
}

GTEST_TEST(RegionExact, AgreesWithSubdivisionForJOnThePolygon) {
  const Scene scene = test::scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  auto target = sustained_target(J);
  int compared = 0;
  for (const Rational& mu : {Rational(0), Rational(1, 10)}) {
    RegionOptions sub;
    sub.resolution = Rational(1, 4096);
    sub.pusher_mu = mu;
    RegionOptions ex = sub;
    ex.exact = true;
    compared += check_agreement(compute_region(scene, *target, sub), compute_region(scene, *target, ex));
  }
  EXPECT_GE(compared, 4);
}

GTEST_TEST(RegionExact, AgreesWithSubdivisionAtResolution1Over4096) {
  std::mt19937_64 rng(4096);
  int compared = 0;
  for (int trial = 0; trial < 4; ++trial) {
    const Rational mu = trial % 2 == 0 ? Rational(0) : Rational(1, 5);
    const Scene scene = test::random_blob_scene(rng, mu);
    const SeatingSet S = seating_set(scene);
    RegionOptions sub;
    sub.resolution = Rational(1, 4096);
    RegionOptions ex;
    ex.exact = true;
    SCOPED_TRACE("trial " + std::to_string(trial));
    compared += check_agreement(compute_region(scene, S, sub), compute_region(scene, S, ex));
  }
  EXPECT_GE(compared, 10);
}

}  // namespace
}  // namespace fixel
