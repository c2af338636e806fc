#include "fixel/internal/readable.h"

#include <cmath>
#include <cstdio>

namespace fixel::internal {

namespace {
constexpr std::size_t kLongFraction = 24;
}  // namespace

std::string decimal(double x, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::string readable(const Rational& q) {
  const std::string exact = to_string(q);
  if (boost::multiprecision::denominator(q) == 1) return exact;
  const std::string d = decimal(to_double(q));
  if (exact.size() > kLongFraction) return "≈ " + d + " (exact in --json)";
  if (parse_rational(d) == q) return exact + " = " + d;
  return exact + " ≈ " + d;
}

std::string readable(const VectorQ& v) {
  std::string exact = "(", approx = "(";
  bool integers = true, long_entry = false;
  for (int k = 0; k < v.size(); ++k) {
    const std::string s = to_string(v[k]);
    integers = integers && boost::multiprecision::denominator(v[k]) == 1;
    long_entry = long_entry || s.size() > kLongFraction;
    exact += (k ? ", " : "") + s;
    approx += (k ? ", " : "") + decimal(to_double(v[k]));
  }
  exact += ")", approx += ")";
  if (integers) return exact;
  if (long_entry) return "≈ " + approx + " (exact in --json)";
  return exact + " ≈ " + approx;
}

}  // namespace fixel::internal
