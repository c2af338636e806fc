#include "fixel/rational.h"

#include <gmp.h>

#include <cctype>
#include <cfenv>

#include "fixel/error.h"

namespace fixel {

namespace {

bool all_digits(const std::string& s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Boost reads a leading 0 as an octal prefix ("010" would be 8), so strip
// leading zeros before converting a run of decimal digits.
Integer decimal_integer(const std::string& digits) {
  const auto first = digits.find_first_not_of('0');
  return first == std::string::npos ? Integer(0) : Integer(digits.substr(first));
}

[[noreturn]] void fail(const std::string& text, const std::string& field) {
  throw ParseError(field, "\"" + text + "\"", "is not an exact number (use 3, -3/7, 0.1 or 1e-3)");
}

// Exponents beyond this would build astronomically large integers from a few
// bytes of input; no physical scene needs them.
constexpr long kMaxExponent = 10000;

Rational pow10(long e) {
  Integer p = boost::multiprecision::pow(Integer(10), static_cast<unsigned>(e < 0 ? -e : e));
  return e < 0 ? Rational(Integer(1), p) : Rational(p);
}

}  // namespace

Rational parse_rational(const std::string& text, const std::string& field) {
  std::string s = text;
  bool negative = false;
  std::size_t pos = 0;
  if (pos < s.size() && (s[pos] == '-' || s[pos] == '+')) {
    negative = s[pos] == '-';
    ++pos;
  }
  std::string body = s.substr(pos);
  Rational value;
  const auto slash = body.find('/');
  if (slash != std::string::npos) {
    std::string num = body.substr(0, slash), den = body.substr(slash + 1);
    if (!all_digits(num) || !all_digits(den)) fail(text, field);
    const Integer d = decimal_integer(den);
    if (d == 0) throw ParseError(field, "\"" + text + "\"", "has a zero denominator");
    value = Rational(decimal_integer(num), d);
  } else {
    std::string mantissa = body;
    long exponent = 0;
    const auto e = body.find_first_of("eE");
    if (e != std::string::npos) {
      mantissa = body.substr(0, e);
      std::string exp = body.substr(e + 1);
      bool exp_negative = false;
      if (!exp.empty() && (exp[0] == '-' || exp[0] == '+')) {
        exp_negative = exp[0] == '-';
        exp = exp.substr(1);
      }
      if (!all_digits(exp)) fail(text, field);
      if (exp.size() > 6 || std::stol(exp) > kMaxExponent)
        throw ParseError(field, "\"" + text + "\"", "has an exponent beyond ±10000");
      exponent = std::stol(exp) * (exp_negative ? -1 : 1);
    }
    const auto dot = mantissa.find('.');
    std::string int_part = mantissa, frac_part;
    if (dot != std::string::npos) {
      int_part = mantissa.substr(0, dot);
      frac_part = mantissa.substr(dot + 1);
    }
    if ((int_part.empty() && frac_part.empty()) || (!int_part.empty() && !all_digits(int_part)) ||
        (!frac_part.empty() && !all_digits(frac_part)) ||
        (dot != std::string::npos && int_part.empty() && frac_part.empty()))
      fail(text, field);
    value = Rational(decimal_integer(int_part + frac_part)) * pow10(exponent - static_cast<long>(frac_part.size()));
  }
  return negative ? Rational(-value) : value;
}

std::vector<Rational> parse_rational_list(const std::string& text, const std::string& field) {
  std::vector<Rational> out;
  std::size_t start = 0;
  while (true) {
    const auto comma = text.find(',', start);
    const std::string item = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    out.push_back(parse_rational(item, field + "[" + std::to_string(out.size()) + "]"));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

std::string to_string(const Rational& value) {
  const Integer num = boost::multiprecision::numerator(value);
  const Integer den = boost::multiprecision::denominator(value);
  if (den == 1) return num.str();
  return num.str() + "/" + den.str();
}

double to_double(const Rational& value) {
  // Numerator and denominator exact in double: IEEE division rounds the
  // quotient correctly, as the general conversion does, in a tenth of the time.
  const auto* q = value.backend().data();
  const mpz_srcptr num = mpq_numref(q), den = mpq_denref(q);
  if (mpz_size(num) <= 1 && mpz_size(den) == 1 && std::fegetround() == FE_TONEAREST) {
    constexpr mp_limb_t kExact = mp_limb_t(1) << 53;
    const mp_limb_t n = mpz_getlimbn(num, 0), d = mpz_getlimbn(den, 0);
    if (n < kExact && d < kExact)
      return (mpz_sgn(num) < 0 ? -static_cast<double>(n) : static_cast<double>(n)) / static_cast<double>(d);
  }
  return value.convert_to<double>();
}

int sign(const Rational& value) { return value.sign(); }

}  // namespace fixel
