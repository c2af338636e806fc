// Real algebraic numbers and root isolation (docs/theory.md §12). Reference
// values are closed forms: √2, √3, the golden ratio, simple rationals.
#include "fixel/algebraic.h"

#include <gtest/gtest.h>

#include <functional>
#include <thread>

#include "fixel/error.h"
#include "fixel/internal/root_isolation.h"

namespace fixel {
namespace {

using internal::real_roots;

std::vector<Integer> ints(std::initializer_list<int> c) {
  std::vector<Integer> out;
  for (int x : c) out.push_back(x);
  return out;
}

GTEST_TEST(Algebraic, RootIsolationFindsSqrtTwoWithItsMinimalPolynomial) {
  const auto roots = real_roots({Polynomial{-2, 0, 1}}, Rational(0), Rational(2));
  ASSERT_EQ(roots.size(), 1u);
  EXPECT_EQ(roots[0].poly, ints({-2, 0, 1}));
  EXPECT_LT(roots[0].lo * roots[0].lo, 2);
  EXPECT_GT(roots[0].hi * roots[0].hi, 2);
  EXPECT_EQ(compare(roots[0], Rational(141421, 100000)), 1);
  EXPECT_EQ(compare(roots[0], Rational(141422, 100000)), -1);
}

GTEST_TEST(Algebraic, RationalRootsComeOutExactAndEveryRootIsSortedAndSeparated) {
  // (2x − 1)(x² − 3)(3x − 5) and x − 1/2 again: roots 1/2, √3, 5/3 in (0, 3);
  // −√3 lies outside and the repeated 1/2 is reported once.
  const Polynomial p{3, -6, -1, 2};        // (2x − 1)(x² − 3) = 2x³ − x² − 6x + 3
  const Polynomial q{-5, 3};               // 3x − 5
  const Polynomial r{Rational(-1, 2), 1};  // x − 1/2
  const auto roots = real_roots({p, q, r}, Rational(0), Rational(3));
  ASSERT_EQ(roots.size(), 3u);
  EXPECT_TRUE(roots[0].is_rational());
  EXPECT_EQ(roots[0].lo, Rational(1, 2));
  EXPECT_TRUE(roots[1].is_rational());
  EXPECT_EQ(roots[1].lo, Rational(5, 3));
  EXPECT_EQ(roots[2].poly, ints({-3, 0, 1}));
  EXPECT_LT(roots[1].hi, roots[2].lo);  // √3 > 5/3: 3 > 25/9
  EXPECT_GT(roots[2].lo, Rational(5, 3));
}

GTEST_TEST(Algebraic, TheUnitIntervalKeepsEveryRootInsideAndNoneOutside) {
  // 8x² − 8x + 1: roots (2 ± √2)/4 ≈ 0.146, 0.854, both inside; (x − 2)(x + 1): none.
  const auto roots = real_roots({Polynomial{1, -8, 8}, Polynomial{-2, -1, 1}}, Rational(0), Rational(1));
  ASSERT_EQ(roots.size(), 2u);
  EXPECT_EQ(roots[0].poly, ints({1, -8, 8}));
  EXPECT_EQ(compare(roots[0], Rational(146, 1000)), 1);
  EXPECT_EQ(compare(roots[0], Rational(147, 1000)), -1);
  EXPECT_EQ(compare(roots[1], Rational(853, 1000)), 1);
  EXPECT_EQ(compare(roots[1], Rational(854, 1000)), -1);
  EXPECT_TRUE(real_roots({Polynomial{-2, -1, 1}}, Rational(0), Rational(1)).empty());
}

GTEST_TEST(Algebraic, ZeroAndConstantPolynomialsHaveNoRoots) {
  EXPECT_TRUE(real_roots({Polynomial{}, Polynomial{7}, Polynomial{0, 0}}, Rational(0), Rational(1)).empty());
  EXPECT_THROW(real_roots({Polynomial{0, 1}}, Rational(1), Rational(1)), InputError);
}

GTEST_TEST(Algebraic, RefinementShrinksTheIntervalAndDecimalsAreCertified) {
  const auto roots = real_roots({Polynomial{-2, 0, 1}}, Rational(0), Rational(2));
  const AlgebraicReal x = refined(roots[0], Rational(1, 10000000000LL));
  EXPECT_LE(x.hi - x.lo, Rational(1, 10000000000LL));
  EXPECT_LT(x.lo * x.lo, 2);
  EXPECT_GT(x.hi * x.hi, 2);
  const std::string s = certified_decimal(x);
  EXPECT_EQ(s.substr(0, 10), "1.41421356") << s;  // √2 = 1.4142135623…
  EXPECT_EQ(s.substr(s.size() - 3), "...");
  EXPECT_EQ(certified_decimal(AlgebraicReal::rational(Rational(3, 8))), "0.375");
  EXPECT_EQ(certified_decimal(AlgebraicReal::rational(Rational(-1, 3)), 4), "-0.3333...");
  // Bounded: a billion digits would take years (quadratic time).
  EXPECT_THROW(certified_decimal(AlgebraicReal::rational(Rational(1, 3)), 100001), InputError);
  AlgebraicReal vague = AlgebraicReal::rational(Rational(1));  // no polynomial, yet an interval
  vague.hi = Rational(2);
  EXPECT_THROW(certified_decimal(vague), InputError);
  EXPECT_THROW(refined(x, Rational(0)), InputError);
}

GTEST_TEST(Algebraic, AnAffineImageKeepsTheRootExact) {
  // y = 1 + 2x for x = √2: y² − 2y − 7 = 0.
  const auto roots = real_roots({Polynomial{-2, 0, 1}}, Rational(0), Rational(2));
  const AlgebraicReal y = affine_image(roots[0], Rational(1), Rational(2));
  EXPECT_EQ(y.poly, ints({-7, -2, 1}));
  EXPECT_EQ(compare(y, Rational(3828, 1000)), 1);  // 1 + 2√2 = 3.8284…
  EXPECT_EQ(compare(y, Rational(3829, 1000)), -1);
  EXPECT_TRUE(internal::is_root(roots[0], Polynomial{-4, 0, 2}));
  EXPECT_FALSE(internal::is_root(roots[0], Polynomial{-3, 0, 1}));
}

// Root isolation in a thread that then ends, as a Python thread pool runs
// it: the roots are the main thread's, and FLINT's per-thread caches (Arb's
// constants among them) are freed with the thread (LeakSanitizer in CI's
// sanitizer build reports them otherwise).
GTEST_TEST(Algebraic, RootsIsolatedInAThreadThatEndsAreTheMainThreadsAndLeaveNothingBehind) {
  // x³ − 3x + 1: three irrational roots 2cos(2πk/9) in (−2, 2), near
  // −1.879, 0.347 and 1.532.
  const Polynomial cubic{1, -3, 0, 1};
  const auto here = real_roots({cubic}, Rational(-2), Rational(2));
  ASSERT_EQ(here.size(), 3u);
  std::vector<AlgebraicReal> there;
  Polynomial common;
  bool root_there = false;
  std::thread worker([&] {
    there = real_roots({cubic}, Rational(-2), Rational(2));
    common = internal::gcd(Polynomial{-2, 1, 1}, Polynomial{-1, 1});  // (x + 2)(x − 1) and x − 1
    root_there = internal::is_root(there[1], Polynomial{2, -6, 0, 2});
  });
  worker.join();
  ASSERT_EQ(there.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(there[i].poly, ints({1, -3, 0, 1}));
    EXPECT_EQ(there[i].lo, here[i].lo);  // the same isolating interval
    EXPECT_EQ(there[i].hi, here[i].hi);
  }
  EXPECT_EQ(compare(there[1], Rational(347, 1000)), 1);  // 2cos(4π/9) = 0.3472…
  EXPECT_EQ(compare(there[1], Rational(348, 1000)), -1);
  EXPECT_EQ(common, (Polynomial{-1, 1}));
  EXPECT_TRUE(root_there);
}

// An AlgebraicReal made by the caller: a reducible polynomial's rational
// root met by a bisection was an InternalError ("a bug in fixel"), and an
// interval without a root was refined as if it had one.
GTEST_TEST(Algebraic, AnIntervalThatIsolatesNoIrrationalRootIsTheCallersInputError) {
  AlgebraicReal reducible;  // x² − 1 on [0, 2]: its root 1 is rational
  reducible.poly = ints({-1, 0, 1});
  reducible.lo = 0;
  reducible.hi = 2;
  EXPECT_THROW(compare(reducible, Rational(1)), InputError);
  EXPECT_THROW(refined(reducible, Rational(1, 10)), InputError);
  AlgebraicReal rootless;  // x² + 1 on [0, 2]: no sign change
  rootless.poly = ints({1, 0, 1});
  rootless.lo = 0;
  rootless.hi = 2;
  for (const auto& ask : std::vector<std::function<void()>>{
           [&] { compare(rootless, Rational(1)); }, [&] { refined(rootless, Rational(1, 10)); },
           [&] { certified_decimal(rootless, 3); }, [&] { affine_image(rootless, Rational(0), Rational(1)); }}) {
    try {
      ask();
      ADD_FAILURE();
    } catch (const InputError& e) {
      EXPECT_EQ(e.field(), "x");
    }
  }
  // A true one still answers: √2 in [1, 2] lies between 1.41 and 1.42.
  AlgebraicReal sqrt2;
  sqrt2.poly = ints({-2, 0, 1});
  sqrt2.lo = 1;
  sqrt2.hi = 2;
  EXPECT_EQ(compare(sqrt2, Rational(141, 100)), 1);
  EXPECT_EQ(compare(sqrt2, Rational(142, 100)), -1);
}

}  // namespace
}  // namespace fixel
