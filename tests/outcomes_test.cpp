#include "fixel/outcomes.h"

#include <gtest/gtest.h>

#include "fixel/error.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/lcp.h"
#include "fixel/lemke.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::vec;

// Rebuilds an LCP solution z = (p_n, p_f, s) from an outcome and checks it
// with the independent checker: the outcome really solves the step LCP.
void expect_outcome_solves_lcp(const Scene& scene, const VectorQ& p, const Outcome& o) {
  const int nc = scene.num_contacts();
  const TimeSteppingLcp lcp = build_lcp(scene);
  VectorQ z = VectorQ::Zero(4 * nc);
  for (int i = 0; i < nc; ++i) {
    z[i] = o.p_n[i];
    z[nc + 2 * i] = o.p_t[i] > 0 ? o.p_t[i] : Rational(0);
    z[nc + 2 * i + 1] = o.p_t[i] < 0 ? Rational(-o.p_t[i]) : Rational(0);
    z[3 * nc + i] = boost::multiprecision::abs(lcp.W.Wt.col(i).dot(o.velocity));  // s = |v_t|
  }
  const VectorQ b = lcp.b(p);
  EXPECT_TRUE(is_solution(lcp.B, b, VectorQ(lcp.B * z + b), z));
}

GTEST_TEST(Outcomes, PaperExample2HasExactlyOneOutcomeAndItSeats) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const auto outcomes = enumerate_outcomes(scene, vec({-1, -1, -1}));
  ASSERT_EQ(outcomes.size(), 1u);
  EXPECT_TRUE(outcomes[0].seated);
  EXPECT_EQ(outcomes[0].p_n, vec({Rational(161, 202), Rational(183, 505), Rational(337, 505)}));
}

GTEST_TEST(Outcomes, NonuniquenessSceneHasASeatingAndANonSeatingOutcome) {
  const Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/nonunique.json");
  // DESIGN §3: p = apex − Σ g_i, i.e. λ = p_n = (1, 1, 1).
  const VectorQ p = vec({Rational(29157, 10540), Rational(-71119, 105400), Rational(-1169839, 263500)});
  const SeatingSet S = seating_set(scene);
  VectorQ apex_minus_g = S.apex;
  for (const auto& g : S.generators) apex_minus_g -= g;
  EXPECT_EQ(apex_minus_g, p);
  EXPECT_TRUE(S.contains(p));

  const auto outcomes = enumerate_outcomes(scene, p);
  int seating = 0, non_seating = 0;
  for (const auto& o : outcomes) {
    expect_outcome_solves_lcp(scene, p, o);
    EXPECT_TRUE(o.isolated);
    if (o.seated) {
      ++seating;
      EXPECT_EQ(o.p_n, vec({1, 1, 1}));
      EXPECT_EQ(o.velocity, S.nu_plus);
    } else {
      ++non_seating;
      EXPECT_TRUE((o.gaps.array() > Rational(0)).any());
    }
  }
  EXPECT_EQ(seating, 1);
  EXPECT_GE(non_seating, 1);
  EXPECT_EQ(non_seating, 2);  // (open, slide+, open) and (slide+, slide+, open)
}

// A sticking contact with the others closed leaves a family of outcomes
// (docs/theory.md §5): Example 2 with gaps (1/10, 0, 0) under p = (−1, −1, −1).
// The listed outcomes are the family's ends; their midpoint solves the step
// LCP too (checked by is_solution), so none of them is isolated. Both were
// marked isolated: the family's own point was dropped as a duplicate of one.
GTEST_TEST(Outcomes, OutcomesOnAFamilyAreNotMarkedIsolated) {
  Scene scene = load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/example2.json");
  ASSERT_EQ(scene.fixels[0].gap, Rational(1, 10));
  scene.fixels[1].gap = 0;
  scene.fixels[2].gap = 0;
  const VectorQ p = vec({-1, -1, -1});
  const auto outcomes = enumerate_outcomes(scene, p);
  ASSERT_EQ(outcomes.size(), 2u);
  EXPECT_NE(outcomes[0].p_n, outcomes[1].p_n);
  for (const auto& o : outcomes) {
    expect_outcome_solves_lcp(scene, p, o);
    EXPECT_FALSE(o.isolated);
  }
  Outcome mid = outcomes[0];
  mid.velocity = (outcomes[0].velocity + outcomes[1].velocity) / Rational(2);
  mid.p_n = (outcomes[0].p_n + outcomes[1].p_n) / Rational(2);
  mid.p_t = (outcomes[0].p_t + outcomes[1].p_t) / Rational(2);
  expect_outcome_solves_lcp(scene, p, mid);
}

GTEST_TEST(Outcomes, RejectsAnImpulseOfTheWrongLength) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  EXPECT_THROW(enumerate_outcomes(scene, vec({1, 2})), InputError);
}

// These threw std::out_of_range and std::length_error.
GTEST_TEST(Outcomes, AModeListOrCodeOutOfRangeIsAnInputError) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  EXPECT_THROW(mode_system(scene, contact_modes(0, 2), vec({1, 2, 3})), InputError);
  EXPECT_THROW(contact_modes(0, -1), InputError);
  EXPECT_THROW(contact_modes(64, 3), InputError);
  EXPECT_THROW(contact_modes(-1, 3), InputError);
  EXPECT_EQ(contact_modes(63, 3), std::vector<ContactMode>(3, ContactMode::kStick));  // 63 = 333 in base 4
}

// Random low-friction scenes: inside S some outcome seats, outside S none
// does, and Lemke's solution is always one of the enumerated outcomes.
GTEST_TEST(Outcomes, AgreeWithSeatingSetAndLemkeOnRandomLowFrictionScenes) {
  std::mt19937_64 rng(31);
  const int wanted = test::sanitizer_scaled(40);
  int scenes = 0, inside = 0, outside = 0;
  for (int attempt = 0; attempt < 400 && scenes < wanted; ++attempt) {
    Scene scene = test::random_scene(rng, 3, /*max_mu_tenths=*/3);
    SeatingSet S;
    try {
      S = seating_set(scene);
    } catch (const SceneError&) {
      continue;
    }
    ++scenes;
    const TimeSteppingLcp lcp = build_lcp(scene);
    for (int k = 0; k < 6; ++k) {
      VectorQ lambda(3);
      for (int j = 0; j < 3; ++j) lambda[j] = test::random_rational(rng, 0, 2, 9) + Rational(1, 9);
      const bool make_outside = k % 2 == 1;
      if (make_outside) lambda[k % 3] = -lambda[k % 3];
      VectorQ p = S.apex;
      for (int j = 0; j < 3; ++j) p -= lambda[j] * S.generators[j];
      ASSERT_EQ(S.contains(p), !make_outside);

      const auto outcomes = enumerate_outcomes(scene, p);
      bool any_seats = false;
      for (const auto& o : outcomes) any_seats = any_seats || o.seated;
      EXPECT_EQ(any_seats, !make_outside);
      (make_outside ? outside : inside)++;

      const LemkeResult r = solve_lcp_lemke(lcp.B, lcp.b(p));
      ASSERT_EQ(r.status, LemkeStatus::kSolved);
      const Outcome lemke = outcome_from_lcp_solution(scene, p, r.z);
      bool found = false;
      for (const auto& o : outcomes) found = found || same_outcome(o, lemke);
      EXPECT_TRUE(found);
    }
  }
  EXPECT_EQ(scenes, wanted);
  EXPECT_EQ(inside + outside, 6 * wanted);
}

GTEST_TEST(ModeSystem, HasOneEquationPerUnknown) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  for (auto m : {ContactMode::kOpen, ContactMode::kSlidePlus, ContactMode::kSlideMinus, ContactMode::kStick}) {
    const ModeSystem sys = mode_system(scene, {m, m, m}, vec({0, 0, 0}));
    EXPECT_EQ(sys.A_eq.rows(), 9);
    EXPECT_EQ(sys.A_eq.cols(), 9);
  }
}

// seat --impulse enumerates the outcomes with no control of its own: the
// caller's ControlScope stops it between contact modes (on a 20,000-digit
// vertex it ran 118 s past --max-seconds 2).
GTEST_TEST(Outcomes, TheCallersControlScopeStopsTheEnumeration) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const VectorQ p = test::vec({-1, -1, -1});
  EXPECT_EQ(test::stop_message([&] { enumerate_outcomes(scene, p); }), "(no stop)");
  const test::CancelledControl cancelled;
  const ControlScope scope(&cancelled.control);
  EXPECT_EQ(test::stop_message([&] { enumerate_outcomes(scene, p); }),
            "outcomes of one step: interrupted after 0 exact steps; no result");
}

}  // namespace
}  // namespace fixel
