#pragma once
/// @file
/// The one exact number type of fixel, and exact parsing and printing.

#include <Eigen/Core>
#include <boost/multiprecision/eigen.hpp>
#include <boost/multiprecision/gmp.hpp>
#include <string>
#include <vector>

namespace fixel {

/// GMP rational without expression templates (so that Eigen and CGAL can use
/// it as a plain scalar). Every decision in fixel is made in this type.
using Rational = boost::multiprecision::number<boost::multiprecision::gmp_rational, boost::multiprecision::et_off>;
/// The matching GMP integer (numerators, denominators).
using Integer = boost::multiprecision::number<boost::multiprecision::gmp_int, boost::multiprecision::et_off>;

/// Exact dense vectors and matrices.
using VectorQ = Eigen::Matrix<Rational, Eigen::Dynamic, 1>;
using MatrixQ = Eigen::Matrix<Rational, Eigen::Dynamic, Eigen::Dynamic>;

/// Parses an exact number: an integer ("-3"), a fraction ("-3/7"), or a
/// decimal with optional exponent ("0.1", "1.5e-3", "2E4"). Surrounding
/// whitespace is not allowed. Throws ParseError naming `field` on failure.
Rational parse_rational(const std::string& text, const std::string& field = "number");

/// Parses a comma-separated list of exact numbers, e.g. "-1,-1,-1".
std::vector<Rational> parse_rational_list(const std::string& text, const std::string& field = "numbers");

/// Exact text: "p/q" in lowest terms, or "p" when the denominator is 1.
std::string to_string(const Rational& value);

/// Nearest double, for display only; never for a decision.
double to_double(const Rational& value);

/// Sign of `value`: -1, 0 or +1.
int sign(const Rational& value);

}  // namespace fixel
