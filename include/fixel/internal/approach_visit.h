#pragma once
// The exact visit of a pair's family (src/approach_visit.cpp): every point
// of the closed interval between t = 0 and t* where a sign of the given
// polynomials may change, and one rational point inside each cell between
// them, from 0 towards t* (docs/theory.md §10.7). A polynomial may have
// coefficients in Q(√d), the seat's field: a + √d·b.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "fixel/algebraic.h"
#include "fixel/internal/approach_data.h"

namespace fixel::internal {

// A point between 0 and t*, ends included: rational, an irrational root of
// one of the polynomials, or t* itself.
struct Point {
  enum Kind { kRational, kRoot, kStar } kind = kRational;
  Rational q;
  AlgebraicReal root;
};

// a + √d·b, d the root of t*'s field (b empty for a rational polynomial).
struct FieldPolynomial {
  Polynomial a, b;
};

// The signs of the visited polynomials at one point, computed on first use.
using Signs = std::function<int(std::size_t)>;

// The first visited point where `pred` holds, if any.
std::optional<Point> first_point(const std::vector<Polynomial>& polys, const ApproachData& d,
                                 const std::function<bool(const Signs&)>& pred);
std::optional<Point> first_point(const std::vector<FieldPolynomial>& polys, const ApproachData& d,
                                 const std::function<bool(const Signs&)>& pred);

// θ at a visited point (rad, display), and θ for a message.
double theta_of(const Point& x, double theta_star);
std::string theta_text(double theta);

}  // namespace fixel::internal
