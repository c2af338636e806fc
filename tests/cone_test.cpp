#include "fixel/cone.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/error.h"
#include "fixel/internal/exact_lu.h"
#include "test_util.h"

namespace fixel {
namespace {

using test::vec;

bool in_cone(const std::vector<VectorQ>& normals, const VectorQ& x) {
  for (const auto& a : normals)
    if (a.dot(x) < 0) return false;
  return true;
}

GTEST_TEST(ConeFacets, PositiveOrthantHasTheThreeAxisFacets) {
  const auto f = cone_facet_normals({vec({1, 0, 0}), vec({0, 1, 0}), vec({0, 0, 1})}, 3);
  ASSERT_EQ(f.size(), 3u);
  for (const auto& a : f) EXPECT_EQ(a.sum(), Rational(1));  // each a unit axis
}

GTEST_TEST(ConeFacets, FourRayPyramidHasFourFacetsAndRedundantRaysAreIgnored) {
  std::vector<VectorQ> rays = {vec({1, 1, 1}), vec({-1, 1, 1}), vec({-1, -1, 1}), vec({1, -1, 1}), vec({0, 0, 1})};
  const auto f = cone_facet_normals(rays, 3);
  EXPECT_EQ(f.size(), 4u);
  EXPECT_TRUE(in_cone(f, vec({0, 0, 1})));
  EXPECT_TRUE(in_cone(f, vec({1, 1, 1})));  // on an edge
  EXPECT_FALSE(in_cone(f, vec({2, 0, 1})));
}

GTEST_TEST(ConeFacets, HalfSpaceConeHasOneFacet) {
  const auto f =
      cone_facet_normals({vec({1, 0, 0}), vec({-1, 0, 0}), vec({0, 1, 0}), vec({0, -1, 0}), vec({0, 0, 1})}, 3);
  ASSERT_EQ(f.size(), 1u);
  EXPECT_EQ(f[0], vec({0, 0, 1}));
}

GTEST_TEST(ConeFacets, WholeSpaceHasNoFacets) {
  EXPECT_TRUE(cone_facet_normals({vec({1, 0, 0}), vec({0, 1, 0}), vec({0, 0, 1}), vec({-1, -1, -1})}, 3).empty());
}

GTEST_TEST(ConeFacets, FlatConeGetsItsPlaneAsTwoOppositeFacets) {
  const auto f = cone_facet_normals({vec({1, 0, 0}), vec({1, 1, 0})}, 3);
  EXPECT_EQ(f.size(), 4u);  // z >= 0, z <= 0, and two in-plane edges
  EXPECT_TRUE(in_cone(f, vec({3, 1, 0})));
  EXPECT_FALSE(in_cone(f, vec({3, 1, Rational(1, 1000)})));
  EXPECT_FALSE(in_cone(f, vec({0, 1, 0})));
}

GTEST_TEST(ConeFacets, SingleRayAndZeroRaysAreHandled) {
  const auto ray = cone_facet_normals({vec({0, 2, 0})}, 3);
  EXPECT_TRUE(in_cone(ray, vec({0, 5, 0})));
  EXPECT_FALSE(in_cone(ray, vec({0, -5, 0})));
  EXPECT_FALSE(in_cone(ray, vec({1, 5, 0})));
  const auto origin = cone_facet_normals({vec({0, 0, 0})}, 3);
  EXPECT_TRUE(in_cone(origin, vec({0, 0, 0})));
  EXPECT_FALSE(in_cone(origin, vec({0, 0, 1})));
}

GTEST_TEST(ConeFacets, PlanarConesWork) {
  const auto f = cone_facet_normals({vec({1, 0}), vec({1, 1})}, 2);
  EXPECT_EQ(f.size(), 2u);
  EXPECT_TRUE(in_cone(f, vec({2, 1})));
  EXPECT_FALSE(in_cone(f, vec({1, 2})));
  EXPECT_TRUE(cone_facet_normals({vec({1, 0}), vec({-1, 1}), vec({-1, -1})}, 2).empty());
}

GTEST_TEST(ConeFacets, RejectsWrongDimensions) {
  EXPECT_THROW(cone_facet_normals({vec({1, 0})}, 3), InputError);
  EXPECT_THROW(cone_facet_normals({}, 4), InputError);
}

GTEST_TEST(PrimitiveDirection, ScalesToCoprimeIntegers) {
  EXPECT_EQ(primitive_direction(vec({Rational(2, 3), Rational(4, 9), 0})), vec({6, 4, 0}) / Rational(2));
  EXPECT_EQ(primitive_direction(vec({Rational(-3, 2), Rational(3, 4)})), vec({-2, 1}));
}

// Second method: a random point is in cone(rays) iff the LP-free test
// "some nonnegative combination of 3 independent rays equals it" holds; for
// 3 independent rays that is λ = R⁻¹ x ≥ 0.
GTEST_TEST(ConeFacets, AgreesWithGeneratorCoordinatesForSimplicialCones) {
  std::mt19937_64 rng(3);
  int checked = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<VectorQ> rays;
    MatrixQ R(3, 3);
    for (int k = 0; k < 3; ++k) {
      rays.push_back(vec({test::random_rational(rng, -2, 2, 3), test::random_rational(rng, -2, 2, 3),
                          test::random_rational(rng, -2, 2, 3)}));
      R.col(k) = rays.back();
    }
    if (internal::exact_rank(rays, 3) < 3) continue;
    const auto f = cone_facet_normals(rays, 3);
    ASSERT_EQ(f.size(), 3u);
    for (int s = 0; s < 20; ++s) {
      const VectorQ x = vec({test::random_rational(rng, -3, 3, 5), test::random_rational(rng, -3, 3, 5),
                             test::random_rational(rng, -3, 3, 5)});
      const VectorQ lambda = internal::exact_lu(R).solve(x);
      EXPECT_EQ(in_cone(f, x), (lambda.array() >= Rational(0)).all());
      ++checked;
    }
  }
  EXPECT_GT(checked, 3000);
}

}  // namespace
}  // namespace fixel
