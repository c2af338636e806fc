#pragma once
// Numbers a person can read in text reports: an exact rational with a
// decimal beside it. Display only; JSON keeps the exact strings (and gets
// `<key>_approx` doubles beside them, see add_approx).

#include <string>

#include "fixel/rational.h"

namespace fixel::internal {

// A double with `digits` significant digits, without trailing zeros.
std::string decimal(double x, int digits = 6);

// "3" for an integer; "1/8 = 0.125" when the decimal is exact and short;
// "145003/7 ≈ 20714.7" for a short fraction; "≈ 4.8e-05 (exact in --json)"
// when the fraction has more than 24 characters.
std::string readable(const Rational& q);

// "(a, b, c)" for integers; otherwise "(a, b, c) ≈ (x, y, z)", with long
// fractions shown by their decimals only.
std::string readable(const VectorQ& v);

}  // namespace fixel::internal
