#pragma once
// Outward-rounded interval arithmetic (Boost.Interval) for certified
// enclosures: the seated pose on curved pieces and the decisions made there.

#include <boost/numeric/interval.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "fixel/rational.h"

namespace fixel::internal {

using IV = boost::numeric::interval<double>;

// An interval that certainly holds q: the nearest double widened by one ulp
// each way (exact when q is a double).
inline IV enclose(const Rational& q) {
  const double d = to_double(q);
  if (Rational(d) == q) return IV(d);
  return IV(std::nextafter(d, -std::numeric_limits<double>::infinity()),
            std::nextafter(d, std::numeric_limits<double>::infinity()));
}

// A sign the enclosure cannot decide.
struct Undecided : std::runtime_error {
  Undecided() : std::runtime_error("undecided at the enclosure's width") {}
};

inline int sign(const IV& x) {
  if (x.lower() > 0) return 1;
  if (x.upper() < 0) return -1;
  if (x.lower() == 0 && x.upper() == 0) return 0;
  throw Undecided();
}

}  // namespace fixel::internal
