#include "fixel/lcp.h"

#include <gtest/gtest.h>

#include "fixel/error.h"

#include "fixel/internal/paper_reference.h"
#include "fixel/scene_json.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::mat;

GTEST_TEST(Lcp, Example1MatricesMatchThePaper) {
  const ContactMatrices W = contact_matrices(parse_scene(internal::paper::kExample1Scene));
  EXPECT_EQ(W.M, mat({{1, 0}, {0, 1}}));
  EXPECT_EQ(W.Wn, mat({{1, 0}, {0, 1}}));
  EXPECT_EQ(W.Wf, mat({{0, 0, -1, 1}, {1, -1, 0, 0}}));  // printed in §3.1
  EXPECT_EQ(MatrixQ(W.E.transpose()), mat({{1, 1, 0, 0}, {0, 0, 1, 1}}));
  EXPECT_EQ(W.U(0, 0), Rational(1, 5));
  EXPECT_EQ(W.U(1, 1), Rational(1, 10));
}

GTEST_TEST(Lcp, Example2MatricesMatchThePaper) {
  const TimeSteppingLcp lcp = build_lcp(parse_scene(internal::paper::kExample2Scene));
  EXPECT_EQ(lcp.W.Wn, mat({{1, 0, 0}, {0, 1, 1}, {0, 0, 1}}));
  EXPECT_EQ(lcp.W.Wf, mat({{0, 0, -1, 1, -1, 1}, {1, -1, 0, 0, 0, 0}, {-1, 1, -1, 1, -1, 1}}));
  for (int r = 0; r < 12; ++r) {
    for (int c = 0; c < 12; ++c)
      EXPECT_EQ(lcp.B(r, c), parse_rational(internal::paper::kExample2B[r][c])) << "B(" << r + 1 << "," << c + 1 << ")";
    for (int c = 0; c < 3; ++c) EXPECT_EQ(lcp.P(r, c), parse_rational(internal::paper::kExample2P[r][c]));
    EXPECT_EQ(lcp.a[r], parse_rational(internal::paper::kExample2a[r]));
  }
}

GTEST_TEST(Lcp, PaperRow10TypoIsReallyATypo) {
  // The paper prints row 10 as (μ₁ 0 0 0 −1 −1 0 …): that would couple contact
  // 1's σ to p_f entries 2 and 3, which belong to contacts 1 and 2.
  const TimeSteppingLcp lcp = build_lcp(parse_scene(internal::paper::kExample2Scene));
  EXPECT_EQ(lcp.B(9, 3), Rational(-1));
  EXPECT_EQ(lcp.B(9, 4), Rational(-1));
  EXPECT_EQ(lcp.B(9, 5), Rational(0));
}

// Second method: w = Bz + b must equal the physical quantities computed from
// the post-step velocity ν⁺ = ν + M⁻¹ (W_n p_n + W_f p_f + p_ext).
GTEST_TEST(Lcp, BzPlusBEqualsGapsVelocitiesAndFrictionSlackOnRandomScenes) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 40; ++trial) {
    const int dof = trial % 4 == 0 ? 2 : 3;
    const Scene s = test::random_scene(rng, dof);
    const TimeSteppingLcp lcp = build_lcp(s);
    const int nc = s.num_contacts();
    VectorQ z(4 * nc), p(dof);
    for (int k = 0; k < z.size(); ++k) z[k] = test::random_rational(rng, 0, 2, 7);
    for (int k = 0; k < dof; ++k) p[k] = test::random_rational(rng, -2, 2, 5);
    const VectorQ w = lcp.B * z + lcp.b(p);

    const VectorQ pn = z.head(nc), pf = z.segment(nc, 2 * nc), sl = z.tail(nc);
    VectorQ rhs = lcp.W.Wn * pn + lcp.W.Wf * pf + p;
    VectorQ nu = s.body.velocity;
    for (int k = 0; k < dof; ++k) nu[k] += rhs[k] / lcp.W.M(k, k);
    for (int i = 0; i < nc; ++i) {
      EXPECT_EQ(w[i], lcp.W.Wn.col(i).dot(nu) + s.fixels[i].gap / s.time_step);  // ψ^{ℓ+1}/h
      EXPECT_EQ(w[nc + 2 * i], lcp.W.Wt.col(i).dot(nu) + sl[i]);
      EXPECT_EQ(w[nc + 2 * i + 1], -lcp.W.Wt.col(i).dot(nu) + sl[i]);
      EXPECT_EQ(w[3 * nc + i], s.fixels[i].mu * pn[i] - pf[2 * i] - pf[2 * i + 1]);
    }
  }
}

GTEST_TEST(Lcp, NamesFollowTheVariableOrder) {
  const TimeSteppingLcp lcp = build_lcp(parse_scene(internal::paper::kExample2Scene));
  const auto z = lcp.z_names(), w = lcp.w_names();
  ASSERT_EQ(z.size(), 12u);
  EXPECT_EQ(z[0], "p_n[0]");
  EXPECT_EQ(z[4], "p_f[0]-");
  EXPECT_EQ(z[11], "s[2]");
  EXPECT_EQ(w[9], "sigma[0]");
}

// The LCP's helpers take a later state or an impulse from the caller: each
// is checked (a short vector was read past its end; h = 0 threw a Boost
// error no catch of fixel::Error saw).
GTEST_TEST(Lcp, AStateOrImpulseThatDoesNotFitTheLcpIsAnErrorNamingIt) {
  const Scene scene = test::scene_file("example2");
  TimeSteppingLcp lcp = build_lcp(scene);
  try {
    lcp.b(VectorQ::Zero(2));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.field(), "p_ext");
  }
  struct Case {
    const char* field;
    void (*spoil)(Scene&);
  };
  const Case cases[] = {
      {"body.velocity", [](Scene& s) { s.body.velocity = VectorQ(); }},
      {"time_step", [](Scene& s) { s.time_step = 0; }},
      {"fixels", [](Scene& s) { s.fixels.pop_back(); }},
  };
  for (const Case& c : cases) {
    Scene later = scene;
    c.spoil(later);
    try {
      set_lcp_state(lcp, later);
      ADD_FAILURE() << c.field;
    } catch (const SceneError& e) {
      EXPECT_EQ(e.field(), c.field);
    }
  }
  Scene one_dof = scene;
  one_dof.body.dof = 1;
  EXPECT_THROW(normal_wrench_matrix(one_dof), SceneError);  // it segfaulted
  EXPECT_THROW(require_determined_fixture(one_dof), SceneError);
}

}  // namespace
}  // namespace fixel
