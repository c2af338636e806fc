#include "fixel/stepper.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/internal/paper_reference.h"
#include "fixel/lcp.h"
#include "fixel/lemke.h"
#include "fixel/progress.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::vec;

GTEST_TEST(Simulate, PaperExample2ImpulseSeatsInOneStep) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const Simulation sim = simulate(scene, {vec({-1, -1, -1})}, 1);
  ASSERT_EQ(sim.steps.size(), 1u);
  EXPECT_TRUE(sim.seated);
  EXPECT_TRUE(sim.steps[0].gaps.isZero());
  EXPECT_EQ(sim.steps[0].p_n, vec({Rational(161, 202), Rational(183, 505), Rational(337, 505)}));
  // q moved by h ν⁺ = the seating velocity.
  EXPECT_EQ(sim.steps[0].q, seating_set(scene).nu_plus);
}

GTEST_TEST(Simulate, AnImpulseOutsideSDoesNotSeat) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  EXPECT_FALSE(simulate(scene, {vec({1, 1, 1})}, 1).seated);
}

GTEST_TEST(Simulate, StateCarriesOverBetweenStepsConsistently) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  const Simulation sim = simulate(scene, {vec({Rational(-1, 2), Rational(-1, 4), 0})}, 4);
  ASSERT_EQ(sim.steps.size(), 4u);
  const ContactMatrices W = contact_matrices(scene);
  VectorQ q = VectorQ::Zero(3), gaps(3);
  gaps << Rational(1, 10), Rational(1, 20), Rational(1, 5);
  for (const auto& s : sim.steps) {
    q += scene.time_step * s.velocity;
    EXPECT_EQ(s.q, q);
    for (int i = 0; i < 3; ++i) {
      gaps[i] += scene.time_step * W.Wn.col(i).dot(s.velocity);
      EXPECT_GE(gaps[i], 0);
    }
    EXPECT_EQ(s.gaps, gaps);
  }
}

// The stepper builds the LCP once and sets only a (ν, ψ) at each step;
// the second method builds the whole LCP again from each step's state, as
// eq. (16)–(19) define it, and solves it forced exact. Every step's
// impulses must be that LCP's solution, on random scenes over five steps.
GTEST_TEST(Simulate, EachStepSolvesTheLcpBuiltAfreshFromThatStepsState) {
  std::mt19937_64 rng(41);
  int scenes = 0, contact_steps = 0;
  for (int trial = 0; trial < 200 && scenes < test::sanitizer_scaled(12); ++trial) {
    const Scene scene = test::random_scene(rng, 3);
    std::vector<VectorQ> impulses;
    for (int k = 0; k < 3; ++k)
      impulses.push_back(vec({test::random_rational(rng, -2, 1, 5), test::random_rational(rng, -2, 1, 5),
                              test::random_rational(rng, -1, 1, 5)}));
    Simulation sim;
    try {
      sim = simulate(scene, impulses, 5);
    } catch (const Error&) {
      continue;  // no seating-type contacts, or a contact situation Lemke does not solve
    }
    ++scenes;
    Scene state = scene;
    for (std::size_t k = 0; k < sim.steps.size(); ++k) {
      const TimeSteppingLcp lcp = build_lcp(state);
      const VectorQ p = k < impulses.size() ? impulses[k] : VectorQ(VectorQ::Zero(3));
      ForceExactScope exact;
      const LemkeResult r = solve_lcp_lemke(lcp.B, lcp.b(p));
      ASSERT_EQ(r.status, LemkeStatus::kSolved) << "scene " << scenes << ", step " << k;
      const int nc = scene.num_contacts();
      EXPECT_EQ(sim.steps[k].p_n, r.z.head(nc)) << "scene " << scenes << ", step " << k;
      EXPECT_EQ(sim.steps[k].p_f, r.z.segment(nc, 2 * nc)) << "scene " << scenes << ", step " << k;
      contact_steps += !r.z.head(nc).isZero();
      state.body.velocity = sim.steps[k].velocity;
      for (int i = 0; i < nc; ++i) state.fixels[i].gap = sim.steps[k].gaps[i];
    }
  }
  EXPECT_EQ(scenes, test::sanitizer_scaled(12));
  EXPECT_GT(contact_steps, scenes);  // steps where a fixel pushed back, not just free flight
}

GTEST_TEST(Simulate, RejectsBadStepsAndImpulseLength) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  try {
    simulate(scene, {vec({-1, -1, -1})}, 0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "simulate(steps): 0 must be >= 1");
  }
  EXPECT_THROW(simulate(scene, {vec({-1, -1})}, 1), InputError);
}

GTEST_TEST(Simulate, ACancelledRunStopsAtTheNextStepAndSaysWhatWasDone) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  RunControl control;
  control.cancel = true;
  try {
    simulate(scene, {vec({-1, -1, -1})}, 1000000000, &control);
    FAIL();
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kInterrupted);
    EXPECT_EQ(std::string(e.what()), "simulate: interrupted after 0 of 1000000000 steps; no result");
  }
}

GTEST_TEST(Simulate, ARunPastItsDeadlineStopsAndReportsProgressOnTheWay) {
  const Scene scene = parse_scene(internal::paper::kExample2Scene);
  RunControl control;
  control.deadline = RunControl::Clock::now() + std::chrono::milliseconds(300);
  control.interval = std::chrono::milliseconds(50);
  long reports = 0;
  control.on_progress = [&](const char*, long, long total, const char*) {
    EXPECT_EQ(total, 1000000000);
    ++reports;
  };
  try {
    simulate(scene, {vec({-1, -1, -1})}, 1000000000, &control);
    FAIL();
  } catch (const StoppedError& e) {
    EXPECT_EQ(e.reason(), StopReason::kTimeLimit);
    EXPECT_GT(e.done(), 0);
  }
  EXPECT_GE(reports, 1);
}

}  // namespace
}  // namespace fixel
