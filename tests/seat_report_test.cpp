#include "fixel/seat_report.h"

#include <gtest/gtest.h>

#include "fixel/internal/paper_reference.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

namespace paper = internal::paper;

GTEST_TEST(SeatReport, ImpulseVerdictsAgreeWithTheSetsTheyCameFrom) {
  const Scene scene = parse_scene(paper::kExample2Scene);
  const SeatingSet S = seating_set(scene);
  const GuaranteedSet G = guaranteed_set(scene, S);
  const VectorQ p = test::v3(-1, -1, -1);
  const SeatReport r = seat_report(scene, S, p, &G, true);
  ASSERT_TRUE(r.impulse.has_value());
  EXPECT_EQ(r.impulse->in_S, S.contains(p));
  EXPECT_EQ(*r.impulse->guaranteed, G.contains(p, S));
  EXPECT_EQ(*r.impulse->seat_and_stay, seat_and_stay(scene, S).contains(p));
  EXPECT_EQ(*r.lost_fraction, lost_fraction(S, G));
  ASSERT_TRUE(r.impulse->y.has_value());  // Example 2 slides at every fixel
  EXPECT_EQ(*r.impulse->y, seating_system(scene, S).y(p));
  // And the paper's values: p = (−1, −1, −1) is in S and guaranteed (for
  // Example 2 no non-seating set meets S, so G = S and nothing is lost), and
  // y = linear − threshold of the paper's eq. (27) table, entry by entry.
  EXPECT_TRUE(r.impulse->in_S);
  EXPECT_EQ(r.impulse->guaranteed, std::optional<bool>(true));
  EXPECT_EQ(*r.lost_fraction, 0);
  ASSERT_EQ(r.impulse->y->size(), 12);
  for (int k = 0; k < 12; ++k)
    EXPECT_EQ((*r.impulse->y)[k],
              parse_rational(paper::kExample2LinearExact[k]) - parse_rational(paper::kExample2ThresholdExact[k]))
        << k;
}

GTEST_TEST(SeatReport, WithoutGOrStableItComputesNeither) {
  const Scene scene = parse_scene(paper::kExample2Scene);
  const SeatReport r = seat_report(scene, seating_set(scene), std::nullopt, nullptr, false);
  EXPECT_FALSE(r.impulse.has_value());
  EXPECT_FALSE(r.lost_fraction.has_value());
  EXPECT_FALSE(r.stable);
}

GTEST_TEST(SeatReport, WrenchVerdictAgreesWithJAndSaysWhyNot) {
  const Scene scene = test::scene_file("polygon");
  const SustainedSet J = sustained_set(scene);
  for (const VectorQ& w : {test::v3(0, 1, 0), test::v3(-1, -1, 0), test::v3(1, 0, 0)}) {
    const WrenchVerdict v = wrench_verdict(J, w);
    ASSERT_TRUE(v.contains.has_value());
    EXPECT_EQ(*v.contains, J.contains(w));
    EXPECT_EQ(v.why_not, J.why_not(w));
  }
  const WrenchVerdict zero = wrench_verdict(J, test::v3(0, 0, 0));  // J is an open cone
  EXPECT_EQ(zero.contains, std::optional<bool>(false));
  EXPECT_FALSE(zero.why_not.empty());
}

// It answered with the sets it was given, whatever their scene.
GTEST_TEST(SeatReport, RefusesAnSOrAGOfAnotherSceneNamingIt) {
  const test::SetCheckScenes s = test::set_check_scenes();
  const SeatingSet S = seating_set(s.scene);
  const GuaranteedSet G = guaranteed_set(s.scene, S);
  const VectorQ p = test::v3(-1, -1, 0);
  const std::string s_named = test::input_error_of([&] { seat_report(s.gapped, S, std::nullopt, nullptr, false); });
  EXPECT_EQ(s_named.rfind("S: ", 0), 0u) << s_named;
  const std::string g_named = test::input_error_of([&] { seat_report(s.heavier, S, p, &G, false); });
  EXPECT_EQ(g_named.rfind("G: ", 0), 0u) << g_named;
  EXPECT_EQ(test::input_error_of([&] { seat_report(s.scene, S, p, &G, false); }), "(no InputError)");
}

}  // namespace
}  // namespace fixel
