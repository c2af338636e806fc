#include "fixel/cone.h"

#include <gtest/gtest.h>

#include <random>

#include "fixel/error.h"
#include "fixel/filter.h"
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

GTEST_TEST(ConeFacets, ASingleRayIsAHalfLineAndTheZeroRayTheOrigin) {
  const auto ray = cone_facet_normals({vec({0, 2, 0})}, 3);
  EXPECT_TRUE(in_cone(ray, vec({0, 5, 0})));
  EXPECT_FALSE(in_cone(ray, vec({0, -5, 0})));
  EXPECT_FALSE(in_cone(ray, vec({1, 5, 0})));
  const auto origin = cone_facet_normals({vec({0, 0, 0})}, 3);
  EXPECT_TRUE(in_cone(origin, vec({0, 0, 0})));
  EXPECT_FALSE(in_cone(origin, vec({0, 0, 1})));
}

GTEST_TEST(ConeFacets, APlanarConeHasTwoFacetsAndAConeOverAHalfPlaneOrMoreNone) {
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

// From the definition: the result is v times one positive rational, its
// entries are integers, and their gcd is 1. Entries up to 2^200 over
// denominators up to 2^100, with zeros and signs.
GTEST_TEST(PrimitiveDirection, IsAPositiveMultipleWithCoprimeIntegerEntries) {
  std::mt19937_64 rng(11);
  auto big = [&](int bits) {
    Integer x = 0;
    for (int b = 0; b < bits; b += 32) x = (x << 32) + Integer(rng() & 0xffffffffu);
    return x;
  };
  for (int trial = 0; trial < 400; ++trial) {
    const int dim = 2 + trial % 2;
    VectorQ v(dim);
    for (int k = 0; k < dim; ++k) {
      const int kind = static_cast<int>(rng() % 5);
      if (kind == 0) {
        v[k] = 0;
        continue;
      }
      Integer num = big(kind == 1 ? 32 : 200) + 1, den = big(kind == 2 ? 100 : 32) + 1;
      if (rng() % 2) num = -num;
      // A shared factor, so that the gcd is not 1 before scaling.
      v[k] = Rational(num * 6, den * 35);
    }
    const VectorQ p = primitive_direction(v);
    if (v.isZero()) {
      EXPECT_EQ(p, v);
      continue;
    }
    Rational factor = 0;
    for (int k = 0; k < dim; ++k)
      if (v[k] != 0) factor = p[k] / v[k];
    ASSERT_GT(factor, 0);
    EXPECT_EQ(p, VectorQ(v * factor));
    Integer g = 0;
    for (int k = 0; k < dim; ++k) {
      ASSERT_EQ(boost::multiprecision::denominator(p[k]), 1);
      g = boost::multiprecision::gcd(g, boost::multiprecision::numerator(p[k]));
    }
    EXPECT_EQ(g, 1);
  }
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

// The facets of full-rank rays are found on enclosures, with an exact sign
// only where an enclosure holds zero. Random sets of 3–9 rays with
// non-dyadic entries: generic ones, ones with a ray exactly in the plane of
// two others (a positive combination), a segment cone's pairs (the same
// force part, two moments), planar and collinear sets, zero rays and
// repeats. The filtered facets are the forced-exact ones, in their order;
// generic sets need no exact sign, and every set with a ray in the plane of
// two others needs one.
GTEST_TEST(ConeFacets, FilteredFacetsAreTheExactOnesInTheirOrderAndCoplanarRaysFallBack) {
  std::mt19937_64 rng(2611);
  auto ray = [&] {
    return vec({test::random_rational(rng, -3, 3, 7), test::random_rational(rng, -3, 3, 11),
                test::random_rational(rng, -3, 3, 13)});
  };
  auto positive = [&] { return test::random_rational(rng, 1, 3, 5); };
  int compared = 0, generic_fallbacks = 0, coplanar_fell_back = 0, coplanar = 0;
  for (int trial = 0; trial < 1200; ++trial) {
    const int kind = trial % 6, m = 3 + trial % 7;
    std::vector<VectorQ> rays;
    for (int k = 0; k < m; ++k) rays.push_back(ray());
    switch (kind) {
      case 1:  // a ray in the plane of two others
        rays.push_back(positive() * rays[0] + positive() * rays[1]);
        break;
      case 2:  // pairs with the same force part and two moments
        for (int k = 0; k + 1 < m; k += 2) rays[k + 1] = vec({rays[k][0], rays[k][1], rays[k][2] + positive()});
        break;
      case 3:  // planar
        for (int k = 2; k < m; ++k) rays[k] = test::random_rational(rng, -2, 2, 3) * rays[0] + positive() * rays[1];
        break;
      case 4:  // collinear, a zero ray and a repeat
        for (int k = 1; k < m; ++k) rays[k] = positive() * rays[0];
        rays.push_back(VectorQ::Zero(3));
        rays.push_back(rays[0]);
        break;
      case 5:  // a repeated ray among generic ones
        rays.push_back(rays[1]);
        break;
      default:
        break;
    }
    reset_filter_stats();
    std::vector<VectorQ> filtered, exact;
    {
      const ForceExactScope on(false);
      filtered = cone_facet_normals(rays, 3);
    }
    const FilterCounts counts = filter_stats().at(FilterSite::kCone);
    {
      const ForceExactScope forced;
      exact = cone_facet_normals(rays, 3);
    }
    ASSERT_EQ(filtered.size(), exact.size()) << "trial " << trial;
    for (std::size_t k = 0; k < exact.size(); ++k)
      EXPECT_EQ(filtered[k], exact[k]) << "trial " << trial << " facet " << k;
    ++compared;
    if (kind == 0) generic_fallbacks += static_cast<int>(counts.fallbacks);
    if (kind == 1) {
      ++coplanar;
      coplanar_fell_back += counts.fallbacks == 1 && counts.certified == 0;
    }
  }
  EXPECT_EQ(compared, 1200);
  EXPECT_EQ(generic_fallbacks, 0);
  EXPECT_EQ(coplanar, 200);
  EXPECT_EQ(coplanar_fell_back, 200);
}

}  // namespace
}  // namespace fixel
