// Vec2's named predicates and contact_wrench (include/fixel/geometry.h).
#include "fixel/geometry.h"

#include <gtest/gtest.h>

#include "fixel/error.h"

namespace fixel {
namespace {

GTEST_TEST(Geometry, AContactWrenchIsTheForceAndItsMomentAboutTheCentreOfMass) {
  // r = (1, 2), d = (3, 4): moment r × d = 1·4 − 2·3 = −2 (by hand).
  const VectorQ w3 = contact_wrench({1, 2}, {3, 4}, 3);
  ASSERT_EQ(w3.size(), 3);
  EXPECT_EQ(w3[0], 3);
  EXPECT_EQ(w3[1], 4);
  EXPECT_EQ(w3[2], -2);
  const VectorQ w2 = contact_wrench({1, 2}, {3, 4}, 2);
  ASSERT_EQ(w2.size(), 2);
  EXPECT_EQ(w2[1], 4);
}

// dof 0 wrote past an empty vector, dof 1 corrupted the heap, dof 4 gave a
// wrench without its moment.
GTEST_TEST(Geometry, AContactWrenchOfADofOtherThanTwoOrThreeIsAnInputError) {
  for (const int dof : {-1, 0, 1, 4}) {
    try {
      contact_wrench({1, 2}, {3, 4}, dof);
      ADD_FAILURE() << dof;
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "dof");
      EXPECT_EQ(e.value(), std::to_string(dof));
    }
  }
}

// The cone is closed, so the zero vector is in it whether or not its legs
// are parallel (it was out when they were).
GTEST_TEST(Geometry, TheZeroVectorIsInEveryClosedPlanarCone) {
  const Vec2 zero{0, 0};
  EXPECT_TRUE(in_cone(zero, {1, 0}, {0, 1}));
  EXPECT_TRUE(in_cone(zero, {1, 0}, {2, 0}));
  // A ray: along it in, against it or off it out.
  EXPECT_TRUE(in_cone({3, 0}, {1, 0}, {2, 0}));
  EXPECT_FALSE(in_cone({-3, 0}, {1, 0}, {2, 0}));
  EXPECT_FALSE(in_cone({1, 1}, {1, 0}, {2, 0}));
  // A quarter plane: its edges in, outside out.
  EXPECT_TRUE(in_cone({0, 5}, {1, 0}, {0, 1}));
  EXPECT_FALSE(in_cone({-1, 1}, {1, 0}, {0, 1}));
}

}  // namespace
}  // namespace fixel
