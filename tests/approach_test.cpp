#include "fixel/approach.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../bench/random_parts.h"  // the physics studies' seeded random parts
#include "approach_oracle.h"
#include "fixel/design.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/approach_data.h"
#include "fixel/internal/exact_lp.h"
#include "fixel/internal/polyline_edge.h"
#include "fixel/internal/polynomial.h"
#include "fixel/internal/quadratic_field.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/seated_pose.h"
#include "test_util.h"

namespace fixel {
namespace {

using internal::Q2;
using test::direct_pose;
using test::DirectPose;
using test::in_cone_lp;

// Random convex parts whose seats turn (gaps up to 1/5, μ up to 1/2) with
// a decided J′ and a non-empty J.
struct Part {
  Scene scene;
  SustainedSet J;
  ApproachSet A;
};

std::vector<Part> turning_parts(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<Part> out;
  for (int k = 0; static_cast<int>(out.size()) < count && k < 2000; ++k) {
    auto scene = bench::random_part(rng, k, 200, 500);
    if (!scene) continue;
    try {
      SustainedSet J = sustained_set(*scene, false);
      if (J.empty || J.pieces.empty() || J.pose.at_scene_pose) continue;
      ApproachSet A = approach_set(*scene, J);
      if (!A.decided || A.data->pairs.empty()) continue;
      out.push_back({*scene, std::move(J), std::move(A)});
    } catch (const Error&) {
    }
  }
  return out;
}

const std::vector<Part>& parts() {
  static const std::vector<Part> p = turning_parts(12, 11);
  return p;
}

Q2 eval(const Polynomial& p, const Q2& x) {
  Q2 v(0);
  for (std::size_t i = p.size(); i-- > 0;) v = v * x + Q2(p[i]);
  return v;
}

// A wrench of J: a positive combination of one piece's rays, rounded to
// rationals, kept when J contains it exactly.
std::optional<VectorQ> wrench_in_J(const SustainedSet& J, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> weight(1, 1000);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto& piece = J.pieces[rng() % J.pieces.size()];
    VectorQ w = VectorQ::Zero(3);
    for (const auto& ray : piece.rays)
      for (int c = 0; c < 3; ++c)
        w[c] += Rational(weight(rng)) * Rational(std::llround(ray[c].approx() * 1e6), 1000000);
    if (J.contains(w)) return w;
  }
  return std::nullopt;
}

// The same in frame B at the seat: J's rays turned by −θ* in doubles and
// rounded, kept when J contains the rational frame-B wrench exactly.
std::optional<VectorQ> part_frame_wrench_in_J(const SustainedSet& J, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> weight(1, 1000);
  const double c = std::cos(J.pose.approx[2]), s = std::sin(J.pose.approx[2]);
  for (int attempt = 0; attempt < 100; ++attempt) {
    const auto& piece = J.pieces[rng() % J.pieces.size()];
    VectorQ w = VectorQ::Zero(3);
    for (const auto& ray : piece.rays) {
      const double x = ray[0].approx(), y = ray[1].approx();
      const std::array<double, 3> b{c * x + s * y, -s * x + c * y, ray[2].approx()};
      for (int k = 0; k < 3; ++k) w[k] += Rational(weight(rng)) * Rational(std::llround(b[k] * 1e6), 1000000);
    }
    if (internal::why_not_in_frame_B(J, w).empty()) return w;
  }
  return std::nullopt;
}

// −R(θ*)·w_B: the world-frame v of a frame-B wrench, in Q(√d).
internal::V3 world_v(const SustainedSet& J, const VectorQ& w_B) {
  const Q2 c = internal::from_public((*J.pose.exact)[2]), s = internal::from_public((*J.pose.exact)[3]);
  return {-(c * Q2(w_B[0]) - s * Q2(w_B[1])), -(s * Q2(w_B[0]) + c * Q2(w_B[1])), Q2(-w_B[2])};
}

// v ∈ cone(gens) for v in Q(√d), directly at one pose: v is in the cone of
// a linearly independent subset (Carathéodory), each tried by Cramer's
// rule. No polynomials, no root isolation.
bool in_cone_q2(const std::vector<VectorQ>& gens, const internal::V3& v) {
  using internal::cross;
  using internal::dot;
  if (internal::is_zero(v)) return true;
  std::vector<internal::V3> G;
  for (const auto& g : gens) G.push_back(internal::lift(g));
  const std::size_t m = G.size();
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b)
      for (std::size_t c = b + 1; c < m; ++c) {
        const Q2 D = dot(G[a], cross(G[b], G[c]));
        if (internal::sign(D) == 0) continue;
        const int sd = internal::sign(D);
        if (internal::sign(dot(v, cross(G[b], G[c]))) * sd >= 0 &&
            internal::sign(dot(G[a], cross(v, G[c]))) * sd >= 0 && internal::sign(dot(G[a], cross(G[b], v))) * sd >= 0)
          return true;
      }
  for (std::size_t a = 0; a < m; ++a)
    for (std::size_t b = a + 1; b < m; ++b) {
      const internal::V3 X = cross(G[a], G[b]);
      if (internal::is_zero(X) || internal::sign(dot(v, X)) != 0) continue;
      if (internal::sign(dot(cross(v, G[b]), X)) >= 0 && internal::sign(dot(cross(G[a], v), X)) >= 0) return true;
    }
  for (const auto& g : G)
    if (internal::is_zero(cross(v, g)) && internal::sign(dot(v, g)) > 0) return true;
  return false;
}

// Rational t strictly between 0 and t*, k/n of the way.
Rational inside(const ApproachSet& A, int k, int n) {
  // t_lo < t* < t_hi: the bound on 0's side of t* keeps every point in [0, t*].
  const Rational& end = internal::sign(internal::from_public(A.t_star)) > 0 ? A.data->t_lo : A.data->t_hi;
  return end * Rational(k, n);
}

// J of another scene: example2 has no outline for J' to read (it
// segfaulted); a J with other fixels is refused too, each naming J.
TEST(Approach, AJOfAnotherSceneIsAnErrorNotACrash) {
  const Scene polygon = test::scene_file("polygon");
  const SustainedSet J = sustained_set(polygon);
  try {
    approach_set(test::scene_file("example2"), J);
    ADD_FAILURE() << "J of the polygon was taken beside example2";
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "J");
    EXPECT_NE(std::string(e.what()).find("body.boundary is absent here, given in the scene it was built from"),
              std::string::npos)
        << e.what();
  }
  Scene fewer = polygon;
  fewer.fixels.pop_back();
  EXPECT_THROW(approach_set(fewer, J), InputError);
  EXPECT_NO_THROW(approach_set(polygon, J));
}

// A designed layout of blob: every gap 0, the contacts on its curved
// pieces, where seated_pose locates none (curve −1). J′ is then undecided
// with its reason; it was refused as "J of another scene".
TEST(Approach, ASeatWithContactsOnCurvedPiecesLeavesJPrimeUndecidedNotAnError) {
  const Scene part = test::scene_file("blob");
  const auto candidates = parse_candidates(part, R"({"candidates": [{"curve": 0, "u": "545/128"},
      {"curve": 0, "u": "3053/512"}, {"curve": 0, "u": "10599/1024"}]})");
  DesignOptions o;
  o.mu = Rational(1, 10);
  const Scene layout = layout_scene(part, candidates, {0, 1, 2}, o, false);
  const SustainedSet J = sustained_set(layout);
  ASSERT_TRUE(J.pose.exact);
  ASSERT_EQ(J.pose.contact_curve, std::vector<int>(3, -1));
  const ApproachSet A = approach_set(layout, J);
  EXPECT_FALSE(A.decided);
  EXPECT_EQ(A.undecided_reason, "a contact lies on a curved piece; J' needs every contact on a polyline edge");
  // Beside a scene whose fixels have gaps, the same J is still another scene's.
  EXPECT_THROW(approach_set(test::scene_file("polygon"), J), InputError);
}

TEST(Approach, SomeTestPartsTurnFarEnoughToMatter) {
  ASSERT_EQ(parts().size(), 12u);
  int large = 0;
  for (const auto& p : parts()) large += std::abs(p.A.theta_star) > 0.2;
  EXPECT_GE(large, 3);
}

TEST(Approach, EachFamilyKeepsBothFixelsOnTheirEdgeLinesAndEndsAtTheSeat) {
  for (const auto& p : parts()) {
    const Q2 t_star = internal::from_public(p.A.t_star);
    const Q2 scale = Q2(1) + t_star * t_star;
    for (const auto& fam : p.A.data->pairs) {
      for (int s = 0; s < 2; ++s) {
        const int k = fam.fixels[s];
        const Fixel& fx = p.scene.fixels[k];
        const auto e = *internal::polyline_edge_through(*p.scene.body.boundary, fx.p_AoF_A, fx.n_A);
        // On the line at every rational t (the polynomial n·(g − a(1 + t²)) is zero).
        const Polynomial on_line = internal::padd(internal::padd(internal::pscale(fam.contact_B[s][0], e.inward.x),
                                                                 internal::pscale(fam.contact_B[s][1], e.inward.y)),
                                                  internal::pscale(Polynomial{Rational(1), Rational(0), Rational(1)},
                                                                   -(e.inward.x * e.a.x + e.inward.y * e.a.y)));
        EXPECT_TRUE(on_line.empty()) << p.scene.name;
        // At t*, the contact of the seated pose (frame B).
        EXPECT_EQ(eval(fam.contact_B[s][0], t_star), internal::from_public(p.J.pose.p_BoG_B[k][0]) * scale);
        EXPECT_EQ(eval(fam.contact_B[s][1], t_star), internal::from_public(p.J.pose.p_BoG_B[k][1]) * scale);
      }
      // At t*, the generators of J's jam cone of the pair (world frame, negated there).
      const JamCone* jam = nullptr;
      for (const auto& j : p.J.jam_cones)
        if (j.fixels == fam.fixels) jam = &j;
      ASSERT_NE(jam, nullptr);
      ASSERT_EQ(jam->cone.rays.size(), fam.gens.size());
      for (std::size_t g = 0; g < fam.gens.size(); ++g)
        for (int c = 0; c < 3; ++c)
          EXPECT_EQ(eval(fam.gens[g][c], t_star), -internal::from_public(jam->cone.rays[g][c]) * scale)
              << p.scene.name << " generator " << g;
    }
  }
}

TEST(Approach, EachFamilyAgreesWithTheDirectlySolvedPoseAtRationalT) {
  for (const auto& p : parts())
    for (const auto& fam : p.A.data->pairs)
      for (int k = 0; k <= 4; ++k) {
        const Rational t = inside(p.A, k, 4);
        const DirectPose d = direct_pose(p.scene, p.J.mu, fam.fixels[0], fam.fixels[1], t);
        ASSERT_EQ(d.gens.size(), 4u);  // the direct pose always lists ± (μ may be 0)
        std::size_t g = 0;
        for (int s = 0; s < 2; ++s) {
          const int fixel = fam.fixels[s];
          for (int sign = 0; sign < (p.J.mu[fixel] == 0 ? 1 : 2); ++sign, ++g) {
            const auto value = internal::eval3(fam.gens[g], t);
            for (int c = 0; c < 3; ++c) EXPECT_EQ(value[c], d.gens[2 * s + sign][c] * (1 + t * t));
          }
        }
      }
}

TEST(Approach, AHoldAtAnyRationalPoseOfAFamilyExcludesTheWrench) {
  std::mt19937_64 rng(5);
  int held_somewhere = 0, in_prime = 0, witnesses_checked = 0;
  for (const auto& p : parts()) {
    for (int sample = 0; sample < 6; ++sample) {
      const auto w = wrench_in_J(p.J, rng);
      if (!w) continue;
      const VectorQ v = -*w;
      bool held = false;
      for (const auto& fam : p.A.data->pairs)
        for (int k = 0; k <= 16 && !held; ++k) {
          const DirectPose d = direct_pose(p.scene, p.J.mu, fam.fixels[0], fam.fixels[1], inside(p.A, k, 16));
          held = in_cone_lp(d.gens, v);
        }
      ApproachHold hold;
      const std::string why = p.A.why_not(*w, &hold);
      if (held) {
        ++held_somewhere;
        EXPECT_FALSE(why.empty()) << p.scene.name;
      }
      if (why.empty()) ++in_prime;
      // A rational witness is a pose where the LP finds the hold too.
      if (!why.empty() && p.A.on_edges && hold.t && hold.t->is_rational()) {
        const DirectPose d = direct_pose(p.scene, p.J.mu, hold.fixels[0], hold.fixels[1], hold.t->lo);
        EXPECT_TRUE(in_cone_lp(d.gens, v)) << p.scene.name;
        ++witnesses_checked;
      }
    }
  }
  // Not vacuous: holds found both ways, and wrenches that J′ keeps.
  EXPECT_GT(held_somewhere, 0);
  EXPECT_GT(witnesses_checked, 0);
  EXPECT_GT(in_prime, 0);
}

TEST(Approach, ThePiecesFilterChangesNoAnswerAndRootIsolationStillRuns) {
  std::mt19937_64 rng(9);
  reset_filter_stats();
  int compared = 0, kept = 0;
  std::uniform_int_distribution<int> coord(-30, 30);
  for (const auto& p : parts()) {
    if (!p.A.on_edges) continue;
    for (int sample = 0; sample < test::sanitizer_scaled(12); ++sample) {
      // Wrenches of J, and wrenches near J's (a random shift): both sides.
      auto w = wrench_in_J(p.J, rng);
      if (!w) continue;
      if (sample % 2) *w += test::vec({Rational(coord(rng), 40), Rational(coord(rng), 40), Rational(coord(rng), 40)});
      bool filtered = false, exact = false;
      std::string filtered_why, exact_why;  // the reason names a pose: the filter must not move it
      {
        const ForceExactScope on(false);
        filtered = p.A.contains(*w);
        filtered_why = p.A.why_not(*w);
      }
      {
        const ForceExactScope forced;
        exact_why = p.A.why_not(*w);
        exact = exact_why.empty();
      }
      EXPECT_EQ(filtered, exact) << p.scene.name;
      EXPECT_EQ(filtered_why, exact_why) << p.scene.name;
      ++compared;
      kept += exact;
    }
  }
  const FilterStats stats = filter_stats();
  const FilterCounts& c = stats.at(FilterSite::kApproach);
  EXPECT_GE(compared, 5 * test::sanitizer_scaled(4));  // 20 plain, 5 under the sanitizers
  EXPECT_GT(kept, 0);
  EXPECT_GT(c.certified, 0);
  EXPECT_GT(c.fallbacks, 0);
}

TEST(Approach, AContactSampledOffItsEdgeEmptiesJPrime) {
  int off = 0;
  for (const auto& p : parts())
    for (const auto& fam : p.A.data->pairs)
      for (int k = 0; k <= 64; ++k) {
        const DirectPose d = direct_pose(p.scene, p.J.mu, fam.fixels[0], fam.fixels[1], inside(p.A, k, 64));
        const bool leaves = d.along[0] < 0 || d.along[0] > 1 || d.along[1] < 0 || d.along[1] > 1;
        if (leaves) {
          ++off;
          EXPECT_FALSE(p.A.on_edges) << p.scene.name;
          EXPECT_TRUE(p.A.empty);
          break;
        }
      }
  EXPECT_GT(off, 0);
  int on = 0;
  for (const auto& p : parts()) on += p.A.on_edges;
  EXPECT_GT(on, 0);
}

TEST(Approach, AnUnturnedSeatGivesJPrimeEqualToJ) {
  std::mt19937_64 rng(3);
  int compared = 0;
  for (int k = 0; k < 400 && compared < 300; ++k) {
    auto scene = bench::random_part(rng, k);
    if (!scene) continue;
    for (auto& f : scene->fixels) f.gap = 0;  // q* = 0
    try {
      const SustainedSet J = sustained_set(*scene, false);
      const ApproachSet A = approach_set(*scene, J);
      ASSERT_TRUE(A.decided);
      EXPECT_EQ(A.t_star.a, 0);
      EXPECT_EQ(A.empty, J.empty);
      std::uniform_int_distribution<int> c(-20, 20);
      for (int s = 0; s < 30; ++s, ++compared) {
        const VectorQ w = test::vec({Rational(c(rng), 7), Rational(c(rng), 7), Rational(c(rng), 11)});
        EXPECT_EQ(A.contains(w), J.contains(w));
      }
    } catch (const SceneError&) {
    }
  }
  EXPECT_GE(compared, 300);
}

// A random part with two fixels on one edge (equal gaps `gap`, or
// `gap` and `gap2`) and a third on another edge: a pair on parallel edges.
std::optional<Scene> two_on_one_edge(std::mt19937_64& rng, int k, const Rational& gap, const Rational& gap2) {
  auto scene = bench::random_part(rng, k, 200, 500);
  if (!scene) return std::nullopt;
  const Fixel f0 = scene->fixels[0], f1 = scene->fixels[1];
  const auto e0 = *internal::polyline_edge_through(*scene->body.boundary, f0.p_AoF_A, f0.n_A);
  const auto e1 = *internal::polyline_edge_through(*scene->body.boundary, f1.p_AoF_A, f1.n_A);
  if (e0.inward.x * e1.inward.y - e0.inward.y * e1.inward.x == 0) return std::nullopt;
  Fixel a = f0, b = f0;
  const Vec2 d{e0.b.x - e0.a.x, e0.b.y - e0.a.y};
  a.p_AoF_A = {e0.a.x + Rational(1, 10) * d.x, e0.a.y + Rational(1, 10) * d.y};
  b.p_AoF_A = {e0.a.x + Rational(1, 2) * d.x, e0.a.y + Rational(1, 2) * d.y};  // an uneven slide range
  a.gap = gap;
  b.gap = gap2;
  scene->fixels = {a, b, f1};
  return scene;
}

// two_on_one_edge's part with its J and J′; nothing when the scene is refused.
std::optional<Part> slide_part(std::mt19937_64& rng, int k, const Rational& gap1, const Rational& gap2) {
  auto scene = two_on_one_edge(rng, k, gap1, gap2);
  if (!scene) return std::nullopt;
  try {
    SustainedSet J = sustained_set(*scene, false);
    ApproachSet A = approach_set(*scene, J);
    return Part{*scene, std::move(J), std::move(A)};
  } catch (const SceneError&) {
    return std::nullopt;
  }
}

TEST(Approach, APairSlidingOnOneEdgeHoldsWhereAnExactLpSaysSo) {
  // Equal gaps on the shared edge: the seat does not turn (θ* = 0), the
  // slide family is rational, and the second method is an exact LP at
  // rational slides. Random wrenches, not only J's: on these parts no
  // wrench of J was held on a slide, so J's alone would test nothing.
  std::mt19937_64 rng(21);
  int parts_checked = 0, held_direct = 0, free_direct = 0, held_off_seat = 0;
  std::uniform_int_distribution<int> coord(-30, 30);
  for (int k = 0; k < 400 && parts_checked < 8; ++k) {
    const auto part = slide_part(rng, k, Rational(1, 10), Rational(1, 10));
    if (!part) continue;
    const Scene* const scene = &part->scene;
    const SustainedSet& J = part->J;
    const ApproachSet& A = part->A;
    ASSERT_TRUE(A.decided) << A.undecided_reason;
    ASSERT_EQ(A.t_star.a, 0);
    ASSERT_EQ(A.data->slides.size(), 1u);
    const internal::SlideFamily& fam = A.data->slides[0];
    EXPECT_TRUE(fam.at_seat);
    ++parts_checked;
    const Vec2& c = scene->body.p_AoCm_A;
    const Vec2 x_star{(*J.pose.exact)[0].a, (*J.pose.exact)[1].a};
    const auto edge =
        *internal::polyline_edge_through(*scene->body.boundary, scene->fixels[0].p_AoF_A, scene->fixels[0].n_A);
    const Vec2 d{edge.b.x - edge.a.x, edge.b.y - edge.a.y};
    for (int sample = 0; sample < 40; ++sample) {
      const VectorQ v = test::vec({Rational(coord(rng), 10), Rational(coord(rng), 10), Rational(coord(rng), 10)});
      bool held = false, held_at_seat = false;
      for (int step = -40; step <= 40; ++step) {
        // The part at θ = 0 translated by x* + s d: contacts at f − x (frame B).
        const Rational s(step, 40);
        const Vec2 x{x_star.x + s * d.x, x_star.y + s * d.y};
        std::vector<VectorQ> gens;
        bool on_edge = true;
        for (int f = 0; f < 2; ++f) {
          const Fixel& fx = scene->fixels[f];
          const Vec2 g{fx.p_AoF_A.x - fx.gap * fx.n_A.x - x.x, fx.p_AoF_A.y - fx.gap * fx.n_A.y - x.y};
          const Rational u = ((g.x - edge.a.x) * d.x + (g.y - edge.a.y) * d.y) / (d.x * d.x + d.y * d.y);
          on_edge = on_edge && u >= 0 && u <= 1;
          const Vec2 rho{g.x - c.x, g.y - c.y};
          const Vec2& n = edge.inward;
          const Rational m = J.mu[f];
          for (int sign : {1, -1}) {
            const Vec2 b{n.x - sign * m * n.y, n.y + sign * m * n.x};
            gens.push_back(test::vec({b.x, b.y, rho.x * b.y - rho.y * b.x}));
          }
        }
        const bool here = on_edge && in_cone_lp(gens, v);
        held = held || here;
        if (step == 0) held_at_seat = here;
      }
      held_off_seat += held && !held_at_seat;
      const bool found = internal::slide_hold(fam, v).has_value();
      if (held) {
        ++held_direct;
        EXPECT_TRUE(found) << scene->name;
      } else {
        ++free_direct;
      }
      // And through J′: a wrench held on the slide is not in J′.
      if (held && J.contains(-v)) {
        EXPECT_FALSE(A.contains(-v));
      }
    }
  }
  EXPECT_EQ(parts_checked, 8);
  EXPECT_GT(held_direct, 0);
  EXPECT_GT(held_off_seat, 0);  // held only away from the seat: the slide itself is tested
  EXPECT_GT(free_direct, 0);
}

TEST(Approach, ASlideFamilyAtATurnedSeatHoldsEveryWrenchOfItsJamConeThere) {
  // Unequal gaps on the shared edge: the seat turns, the slide family is
  // in Q(√d), and at s = 0 it is J's jam cone of the pair (J's own rows).
  std::mt19937_64 rng(23);
  int families = 0, jammed = 0;
  std::uniform_int_distribution<int> coord(-30, 30);
  for (int k = 0; k < 400 && families < 6; ++k) {
    const auto part = slide_part(rng, k, Rational(1, 20), Rational(3, 20));
    if (!part) continue;
    const Scene* const scene = &part->scene;
    const SustainedSet& J = part->J;
    const ApproachSet& A = part->A;
    ASSERT_TRUE(A.decided) << A.undecided_reason;
    const internal::SlideFamily* at_seat = nullptr;
    for (const auto& f : A.data->slides)
      if (f.at_seat) at_seat = &f;
    ASSERT_NE(at_seat, nullptr);
    EXPECT_NE(internal::sign(internal::from_public(A.t_star)), 0);
    ++families;
    const JamCone& jam = J.jam_cones[0];  // fixels 0 and 1, the pair on one edge
    ASSERT_EQ(jam.fixels, (std::array<int, 2>{0, 1}));
    for (int sample = 0; sample < 300; ++sample) {
      const VectorQ w = test::vec({Rational(coord(rng), 10), Rational(coord(rng), 10), Rational(coord(rng), 10)});
      bool in_jam = true;
      for (const auto& a : jam.cone.closed) {
        Q2 dot(0);
        for (int i = 0; i < 3; ++i) dot += internal::from_public(a[i]) * Q2(w[i]);
        in_jam = in_jam && internal::sign(dot) >= 0;
      }
      if (!in_jam) continue;
      ++jammed;
      EXPECT_TRUE(internal::slide_hold(*at_seat, -w).has_value()) << scene->name;
    }
  }
  EXPECT_EQ(families, 6);
  EXPECT_GT(jammed, 0);
}

TEST(Approach, ASeatInAHugeQuadraticFieldHasAFiniteRotation) {
  // The rotation's approximation once read a1·√d in doubles: √d overflowed
  // to inf for d beyond 10³⁰⁸, and inf · 0 gave NaN (θ* printed as nan).
  std::mt19937_64 rng(7);
  int huge = 0;
  for (int k = 0; k < 400 && huge < 3; ++k) {
    auto scene = bench::random_part(rng, k, 200, 500);
    if (!scene) continue;
    try {
      const SeatedPose q = seated_pose(*scene);
      if (!q.exact || (*q.exact)[3].b == 0 || to_double((*q.exact)[3].d) < 1e308) continue;
      ++huge;
      EXPECT_TRUE(std::isfinite(q.approx[2])) << scene->name;
      EXPECT_LE(q.enclosure[2][0], q.approx[2]);
      EXPECT_LE(q.approx[2], q.enclosure[2][1]);
      EXPECT_LT(q.enclosure[2][1] - q.enclosure[2][0], 1e-9);
      EXPECT_TRUE(std::isfinite((*q.exact)[3].approx()));
    } catch (const SceneError&) {
    }
  }
  EXPECT_EQ(huge, 3);
}

// Wrenches in frame B at the seat (a region's pushes): R(θ*)·w_B is in
// Q(√d), so J′'s polynomials get coefficients in Q(√d) (approach_visit.cpp).
TEST(Approach, AFrameBWrenchHeldAtARationalPoseIsNotInJPrimeAndTheFilterChangesNothing) {
  std::mt19937_64 rng(17);
  int irrational = 0, held_somewhere = 0, in_prime = 0, witnesses_checked = 0, compared = 0;
  for (std::size_t k = 0; k < parts().size() && k < 8; ++k) {
    const Part& p = parts()[k];
    irrational += p.A.t_star.b != 0;
    for (int sample = 0; sample < 3; ++sample) {
      const auto w = part_frame_wrench_in_J(p.J, rng);
      if (!w) continue;
      const internal::V3 v = world_v(p.J, *w);
      bool held = false;
      for (const auto& fam : p.A.data->pairs)
        for (int k = 0; k <= 16 && !held; ++k)
          held = in_cone_q2(direct_pose(p.scene, p.J.mu, fam.fixels[0], fam.fixels[1], inside(p.A, k, 16)).gens, v);
      ApproachHold hold;
      hold.fixels = {-1, -1};
      const std::string why = p.A.why_not_part_frame(*w, &hold);
      if (held) {
        ++held_somewhere;
        EXPECT_FALSE(why.empty()) << p.scene.name;
      }
      in_prime += why.empty();
      if (!why.empty() && p.A.on_edges && hold.t && hold.t->is_rational()) {
        EXPECT_TRUE(in_cone_q2(direct_pose(p.scene, p.J.mu, hold.fixels[0], hold.fixels[1], hold.t->lo).gens, v))
            << p.scene.name;
        ++witnesses_checked;
      }
      if (compared < test::sanitizer_scaled(4)) {  // forced exact: about 0.7 s each on these parts' numbers
        const ForceExactScope forced;
        EXPECT_EQ(p.A.why_not_part_frame(*w), why) << p.scene.name;
        ++compared;
      }
    }
  }
  // 8, 17, 8 and 4 here: not vacuous, and the Q(√d) path ran. Eight
  // parts, even under the sanitizers: the first two alone keep no wrench.
  EXPECT_GT(irrational, 0);
  EXPECT_GT(held_somewhere, 0);
  EXPECT_GT(witnesses_checked, 0);
  EXPECT_GT(in_prime, 0);
}

// The J′ region decides stretches by the pairs' outer and inner cones; a
// push inside an IN stretch is in J′ by the exact test, one inside an OUT
// stretch is not (seats with irrational rotations: frame-B pushes).
TEST(Approach, PushesInsideTheJPrimeRegionsStretchesGetTheirStatusFromTheExactFrameBTest) {
  int in = 0, out = 0;
  for (std::size_t k = 0; k < parts().size() && k < 8; ++k) {
    const Part& p = parts()[k];
    if (p.A.t_star.b == 0 || !p.A.on_edges) continue;
    RegionOptions options;
    options.resolution = Rational(1, 64);
    const Region r = compute_region(p.scene, *approach_target(p.A), options);
    for (const auto& i : r.intervals) {
      if (i.status == RegionStatus::kPartial || i.u0 == i.u1) continue;
      const Rational u = (i.u0 + i.u1) / 2;
      const Curve& curve = p.scene.body.boundary->curves[i.curve];
      const Vec2 t = curve.derivative(u), point = curve.point(u);
      const VectorQ g = contact_wrench(sub(point, p.scene.body.p_AoCm_A), {-t.y, t.x}, 3);
      const bool exact = p.A.contains_part_frame(g);
      EXPECT_EQ(exact, i.status == RegionStatus::kIn) << p.scene.name << " u = " << u;
      ++(exact ? in : out);
    }
  }
  EXPECT_GT(in, 0);
  EXPECT_GT(out, 0);
}

TEST(Approach, BadInputIsATypedErrorNamingTheField) {
  const Part& p = parts().front();
  try {
    p.A.contains(test::vec({Rational(1), Rational(0)}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("wrench"), std::string::npos);
  }
  EXPECT_THROW(approach_set(p.scene, SustainedSet{}), InputError);
  // A default-constructed J' says it has no data, as a default J does.
  try {
    ApproachSet{}.contains(test::vec({Rational(1), Rational(0), Rational(0)}));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("default-constructed ApproachSet"), std::string::npos) << e.what();
  }
  EXPECT_THROW(approach_target(ApproachSet{}), InputError);
  ApproachSet undecided;
  undecided.undecided_reason = "test";
  EXPECT_THROW(undecided.contains(test::vec({Rational(1), Rational(0), Rational(0)})), UnsupportedError);
}

// Building J' polls the calling thread's ControlScope, as J's does.
TEST(Approach, BuildingItStopsInsideACancelledControlScopeNamingJPrime) {
  const Scene polygon = test::scene_file("polygon");
  const SustainedSet J = sustained_set(polygon);
  EXPECT_EQ(test::stop_message([&] { approach_set(polygon, J); }), "(no stop)");
  const test::CancelledControl cancelled;
  const ControlScope scope(&cancelled.control);
  EXPECT_EQ(test::stop_message([&] { approach_set(polygon, J); }).rfind("approach-aware J': interrupted after ", 0),
            0u);
}
}  // namespace
}  // namespace fixel
