#include "fixel/seating.h"

#include <gtest/gtest.h>

#include "fixel/guaranteed.h"

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/outcomes.h"
#include "fixel/scene_json.h"
#include "fixel/stepper.h"
#include "test_util.h"

#include <functional>
#include <tuple>

namespace fixel {
namespace {

namespace paper = internal::paper;

// An exact vector from the paper's printed fractions.
template <std::size_t N>
VectorQ parsed(const std::array<const char*, N>& a) {
  VectorQ v(static_cast<int>(N));
  for (std::size_t k = 0; k < N; ++k) v[static_cast<int>(k)] = parse_rational(a[k]);
  return v;
}

using test::v2;

GTEST_TEST(SeatingSet, Example1ApexIsMinusPsiAndRaysAreMinusOneMu) {
  const SeatingSet S = seating_set(parse_scene(paper::kExample1Scene));
  // Paper eq. (26) prints +ψ; the unit mass must move by −ψ in h = 1.
  EXPECT_EQ(S.apex, v2(Rational(-3, 10), Rational(-1, 5)));
  ASSERT_EQ(S.rays.size(), 2u);
  EXPECT_EQ(S.rays[0], v2(-1, Rational(-1, 5)));   // −(1, μ₁)
  EXPECT_EQ(S.rays[1], v2(Rational(-1, 10), -1));  // −(μ₂, 1)
  EXPECT_EQ(S.sliding, (std::vector<int>{-1, 1}));
}

GTEST_TEST(SeatingSet, Example1HFormIsTheTwoEdgesOfTheCone) {
  const SeatingSet S = seating_set(parse_scene(paper::kExample1Scene));
  ASSERT_EQ(S.halfspaces.size(), 2u);
  // Independent check: p = apex − a (1, μ₁) − b (μ₂, 1) with a, b ≥ 0.
  for (int i = -6; i <= 6; ++i)
    for (int j = -6; j <= 6; ++j) {
      const VectorQ p = v2(Rational(i, 10), Rational(j, 10));
      const VectorQ d = S.apex - p;  // = a (1, 1/5) + b (1/10, 1)
      const Rational det = Rational(1) - Rational(1, 50);
      const Rational a = (d[0] - Rational(1, 10) * d[1]) / det, b = (d[1] - Rational(1, 5) * d[0]) / det;
      EXPECT_EQ(S.contains(p), a >= 0 && b >= 0) << i << "," << j;
    }
}

GTEST_TEST(SeatingSet, ARayOfTheWrongLengthIsAnInputErrorNamingIt) {
  const SeatingSet S = seating_set(test::scene_file("example2"));
  const VectorQ three = test::v3(0, -1, 0), two = test::v2(1, 2);
  EXPECT_NO_THROW(ray_magnitudes(S, three, three));  // the right lengths are answered
  for (const auto& [b0, g, field] : {std::make_tuple(two, three, "b0"), std::make_tuple(three, two, "g")}) {
    try {
      ray_magnitudes(S, b0, g);
      FAIL() << field;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_EQ(e.value(), "2 components");
    }
  }
}

// A scene built in code skips the parser's checks; the analyses check the
// values they read (they once read past a short vector, or divided by h = 0
// in a way no fixel::Error reported).
GTEST_TEST(SeatingSet, AHandBuiltSceneWithABadValueIsASceneErrorNamingTheField) {
  const Scene good = test::scene_file("example2");
  struct Case {
    const char* field;
    void (*spoil)(Scene&);
  };
  const Case cases[] = {
      {"body.velocity", [](Scene& s) { s.body.velocity = VectorQ(); }},
      {"time_step", [](Scene& s) { s.time_step = 0; }},
      {"body.mass", [](Scene& s) { s.body.mass = 0; }},
      {"body.inertia", [](Scene& s) { s.body.inertia = -1; }},
      {"body.dof", [](Scene& s) { s.body.dof = 4; }},
      {"fixels[1].gap", [](Scene& s) { s.fixels[1].gap = -1; }},
      {"background_impulse", [](Scene& s) { s.background_impulse = VectorQ(2); }},
  };
  for (const Case& c : cases) {
    Scene bad = good;
    c.spoil(bad);
    const std::function<void()> calls[] = {
        [&] { seating_set(bad); },
        [&] { simulate(bad, {VectorQ::Zero(3)}, 1); },
        [&] { enumerate_outcomes(bad, VectorQ::Zero(3)); },
    };
    for (const auto& call : calls) {
      try {
        call();
        ADD_FAILURE() << c.field;
      } catch (const SceneError& e) {
        EXPECT_EQ(e.field(), c.field);
      }
    }
  }
}

GTEST_TEST(SeatingSet, ContainsPaperExample2Impulse) {
  const Scene scene = parse_scene(paper::kExample2Scene);
  const SeatingSet S = seating_set(scene);
  EXPECT_TRUE(S.contains(parsed(paper::kExample2Impulse)));
  EXPECT_EQ(S.sliding, (std::vector<int>{1, 1, 1}));
  EXPECT_EQ(S.tangential_velocity, parsed(paper::kExample2SlideSpeed));
}

GTEST_TEST(SeatingSystem, Example2ReproducesThePrintedEq27TableExactly) {
  const Scene scene = parse_scene(paper::kExample2Scene);
  const SeatingSystem sys = seating_system(scene, seating_set(scene));
  const VectorQ p = parsed(paper::kExample2Impulse);
  EXPECT_EQ(sys.linear_part(p), parsed(paper::kExample2LinearExact));
  EXPECT_EQ(sys.threshold(), parsed(paper::kExample2ThresholdExact));
  const std::vector<std::string> names = {"rho_f[0]+", "rho_f[1]+", "rho_f[2]+", "p_n[0]", "p_n[1]", "p_n[2]",
                                          "p_f[0]-",   "p_f[1]-",   "p_f[2]-",   "s[0]",   "s[1]",   "s[2]"};
  EXPECT_EQ(sys.y_names, names);
  EXPECT_EQ(MatrixQ(sys.K * sys.K_inv), MatrixQ::Identity(12, 12));
}

// With gaps (1/10, 0, 0) the seating velocity is ν⁺ = (−1/10, 0, 0), along
// fixel 0's normal, so its tangential velocity W_t,0ᵀ ν⁺ = (0, 1, −1)·ν⁺ is 0.
Scene sticking_scene() {
  std::string text = paper::kExample2Scene;
  text.replace(text.find(R"("gap": "1/20")"), 13, R"("gap": "0")");
  text.replace(text.find(R"("gap": "1/5")"), 12, R"("gap": "0")");
  return parse_scene(text);
}

GTEST_TEST(SeatingSet, StickingContactGetsBothFrictionEdgesAsGenerators) {
  const Scene scene = sticking_scene();
  const SeatingSet S = seating_set(scene);
  EXPECT_EQ(S.sliding[0], 0);
  ASSERT_EQ(S.generators.size(), 4u);  // W_n,0 ± μ W_t,0, then one per sliding fixel
  EXPECT_EQ(S.generator_fixel, (std::vector<int>{0, 0, 1, 2}));
  const ContactMatrices W = contact_matrices(scene);
  EXPECT_EQ(S.generators[0], VectorQ(W.Wn.col(0) + Rational(1, 10) * W.Wt.col(0)));
  EXPECT_EQ(S.generators[1], VectorQ(W.Wn.col(0) - Rational(1, 10) * W.Wt.col(0)));
  // The H-form comes from the hull of 4 rays: every generator satisfies it,
  // and it is tight at the apex.
  EXPECT_GE(S.halfspaces.size(), 4u);
  for (const auto& h : S.halfspaces) EXPECT_EQ(h.a.dot(S.apex), h.c);
  for (const auto& r : S.rays) EXPECT_TRUE(S.contains(VectorQ(S.apex + r)));
  // Eq. (21)-(27) assume sliding contacts.
  EXPECT_THROW(seating_system(scene, S), UnsupportedError);
}

// Solves apex − Σ λ_k g_k = p for λ (the V-form coordinates of p).
VectorQ generator_coordinates(const SeatingSet& S, const VectorQ& p) {
  MatrixQ G(S.dof, S.dof);
  for (int k = 0; k < S.dof; ++k) G.col(k) = S.generators[k];
  return internal::exact_lu(G).solve(VectorQ(S.apex - p));
}

class RandomScenes : public ::testing::Test {
 protected:
  // Up to `count` random scenes whose fixture is nonsingular and whose
  // contacts all slide, with their seating sets.
  std::vector<std::pair<Scene, SeatingSet>> make(int count, int dof, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::vector<std::pair<Scene, SeatingSet>> out;
    for (int attempt = 0; attempt < 10 * count && static_cast<int>(out.size()) < count; ++attempt) {
      Scene s = test::random_scene(rng, dof);
      try {
        SeatingSet S = seating_set(s);
        if (internal::exact_rank(S.generators, dof) < dof) continue;  // flat S: eq. (27) has no K⁻¹
        out.emplace_back(std::move(s), std::move(S));
      } catch (const SceneError&) {
      }
    }
    EXPECT_EQ(static_cast<int>(out.size()), count);
    return out;
  }
};

TEST_F(RandomScenes, EveryGeneratorSatisfiesTheHFormAndEveryFacetIsTightAtApexAndTwoRays) {
  for (const auto& [scene, S] : make(60, 3, 11)) {
    ASSERT_EQ(S.halfspaces.size(), 3u);
    EXPECT_TRUE(S.contains(S.apex));
    for (const auto& r : S.rays) EXPECT_TRUE(S.contains(VectorQ(S.apex + r)));
    for (const auto& h : S.halfspaces) {
      EXPECT_EQ(h.a.dot(S.apex), h.c);
      int tight = 0;
      for (const auto& r : S.rays) tight += h.a.dot(r) == 0 ? 1 : 0;
      EXPECT_EQ(tight, 2);
    }
  }
}

TEST_F(RandomScenes, PointsOnAFacetAreInAndPointsTenToTheMinus30OutsideAreNot) {
  const Rational eps = parse_rational("1e-30");
  std::mt19937_64 rng(5);
  for (const auto& [scene, S] : make(40, 3, 12)) {
    for (const auto& h : S.halfspaces) {
      // The facet is spanned by the two rays it is tight on.
      std::vector<VectorQ> edge;
      for (const auto& r : S.rays)
        if (h.a.dot(r) == 0) edge.push_back(r);
      ASSERT_EQ(edge.size(), 2u);
      // Strictly positive weights keep the point off the facet's edges, so a
      // step of 10⁻³⁰ inward crosses no other facet.
      const VectorQ on = S.apex + (test::random_rational(rng, 0, 3, 7) + Rational(1, 7)) * edge[0] +
                         (test::random_rational(rng, 0, 3, 7) + Rational(1, 7)) * edge[1];
      EXPECT_EQ(h.a.dot(on), h.c);
      EXPECT_TRUE(S.contains(on));
      EXPECT_FALSE(S.contains(VectorQ(on - eps * h.a)));
      EXPECT_TRUE(S.contains(VectorQ(on + eps * h.a)));
    }
  }
}

TEST_F(RandomScenes, VFormHFormAndEq27AgreeOnRandomPoints) {
  std::mt19937_64 rng(6);
  int inside = 0, outside = 0;
  for (const auto& [scene, S] : make(40, 3, 13)) {
    const SeatingSystem sys = seating_system(scene, S);
    for (int k = 0; k < 50; ++k) {
      // Sample around the apex so that both outcomes occur.
      VectorQ p = S.apex;
      for (int j = 0; j < 3; ++j) p[j] += test::random_rational(rng, -2, 2, 9);
      const VectorQ lambda = generator_coordinates(S, p);
      const bool by_v = (lambda.array() >= Rational(0)).all();
      const VectorQ y = sys.y(p);
      const bool by_eq27 = (y.array() >= Rational(0)).all();
      EXPECT_EQ(S.contains(p), by_v);
      EXPECT_EQ(by_eq27, by_v);
      // Eq. (27)'s p_n entries are exactly the V-form coordinates λ.
      EXPECT_EQ(VectorQ(y.segment(3, 3)), lambda);
      (by_v ? inside : outside)++;
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

TEST_F(RandomScenes, PointMassScenesHaveTwoRayCones) {
  std::mt19937_64 rng(8);
  for (const auto& [scene, S] : make(30, 2, 14)) {
    ASSERT_EQ(S.halfspaces.size(), 2u);
    for (int k = 0; k < 20; ++k) {
      const VectorQ p = S.apex + v2(test::random_rational(rng, -2, 2, 9), test::random_rational(rng, -2, 2, 9));
      EXPECT_EQ(S.contains(p), (generator_coordinates(S, p).array() >= Rational(0)).all());
    }
  }
}

// A seating set of another shape beside a scene: an InputError naming S
// (guaranteed_set and seating_system read past its vectors).
GTEST_TEST(SeatingSet, ASetOfAnotherShapeBesideASceneIsAnInputErrorNamingS) {
  const Scene example2 = test::scene_file("example2"), example1 = test::scene_file("example1");
  const SeatingSet of_example1 = seating_set(example1);
  const std::function<void()> calls[] = {
      [&] { guaranteed_set(example2, of_example1); },
      [&] { seating_system(example2, of_example1); },
      [&] { seating_system(example2, SeatingSet{}); },
      [&] { seat_and_stay(example2, of_example1); },
  };
  for (const auto& call : calls) {
    try {
      call();
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "S");
    }
  }
  const SeatingSystem system = seating_system(example2, seating_set(example2));
  EXPECT_THROW(system.y(test::v2(1, 2)), InputError);
  EXPECT_THROW(system.linear_part(test::v2(1, 2)), InputError);
}

// A set of another scene of the same shape is refused too (it used to pass
// and give that scene's answers), naming the first part that differs; a set
// of an equal scene, or of one that differs only in what S does not read
// (b₀), is accepted.
GTEST_TEST(SeatingSet, ASetOfAnotherSceneOfTheSameShapeIsAnInputErrorNamingWhatDiffers) {
  const Scene example2 = test::scene_file("example2"), polygon = test::scene_file("polygon");
  const SeatingSet of_polygon = seating_set(polygon), of_example2 = seating_set(example2);
  const auto message = [&](const Scene& scene, const SeatingSet& S) -> std::string {
    try {
      seating_system(scene, S);
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "S");
      return e.what();
    }
    return "";
  };
  EXPECT_NE(message(example2, of_polygon).find("its seating velocity nu_plus is not this scene's"), std::string::npos);
  EXPECT_THROW(guaranteed_set(example2, of_polygon), InputError);
  EXPECT_THROW(seat_and_stay(example2, of_polygon), InputError);
  EXPECT_EQ(message(example2, of_example2), "");
  EXPECT_EQ(message(test::scene_file("example2"), of_example2), "");
  Scene pushed = example2;
  pushed.background_impulse[0] += 1;  // S does not depend on b₀
  EXPECT_EQ(message(pushed, of_example2), "");
  // Each part changed alone is named.
  Scene faster = example2;
  faster.body.velocity[1] += 1;  // ν⁺ and v_t stay; the apex M(ν⁺ − ν) moves
  EXPECT_NE(message(faster, of_example2).find("its apex is"), std::string::npos);
  Scene rougher = example2;
  rougher.fixels[0].mu += Rational(1, 7);
  EXPECT_NE(message(rougher, of_example2).find("its generator list is"), std::string::npos);
  SeatingSet edited = of_example2;
  edited.halfspaces[0].c += 1;
  EXPECT_NE(message(example2, edited).find("its halfspace list is"), std::string::npos);
  edited = of_example2;
  edited.halfspaces[0].a = -edited.halfspaces[0].a;  // through the apex, but the rays leave it
  edited.halfspaces[0].c = -edited.halfspaces[0].c;
  EXPECT_NE(message(example2, edited).find("its halfspace list is"), std::string::npos);
  edited = of_example2;
  edited.halfspaces.pop_back();  // a facet dropped: S (and its region) would grow
  EXPECT_NE(message(example2, edited).find("its halfspace list is"), std::string::npos);
  edited.halfspaces.clear();
  EXPECT_NE(message(example2, edited).find("its halfspace list is"), std::string::npos);
  edited = of_example2;
  edited.rays[1] = VectorQ(2);  // a ray of the wrong length: refused, not an Eigen assertion
  EXPECT_NE(message(example2, edited).find("its ray list is"), std::string::npos);
  edited = of_example2;
  edited.sliding[2] = -edited.sliding[2];
  EXPECT_NE(message(example2, edited).find("its sliding sign list is"), std::string::npos);
}

}  // namespace
}  // namespace fixel
