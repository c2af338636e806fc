#include "fixel/interval.h"

#include "fixel/error.h"
#include "fixel/internal/readable.h"

namespace fixel {

bool Magnitudes::ends_cross(const Rational& lo, bool lo_closed, const std::optional<Rational>& hi, bool hi_closed) {
  return hi && (*hi < lo || (*hi == lo && !(lo_closed && hi_closed)));
}

Magnitudes Magnitudes::make(const Rational& lo, bool lo_closed, const std::optional<Rational>& hi, bool hi_closed) {
  if (lo < 0) throw InputError("lo", to_string(lo), "must be >= 0 (an interval of magnitudes)");
  Magnitudes m;
  m.lo = lo;
  m.lo_closed = lo_closed;
  m.hi = hi;
  m.hi_closed = hi.has_value() && hi_closed;
  m.empty = ends_cross(lo, lo_closed, hi, hi_closed);
  return m;
}

bool Magnitudes::contains(const Rational& x) const {
  if (empty) return false;
  if (x < lo || (x == lo && !lo_closed)) return false;
  if (hi && (x > *hi || (x == *hi && !hi_closed))) return false;
  return true;
}

Magnitudes Magnitudes::intersect(const Magnitudes& b) const {
  if (empty || b.empty) return Magnitudes{};
  Magnitudes m = *this;
  if (b.lo > m.lo || (b.lo == m.lo && !b.lo_closed)) {
    m.lo_closed = b.lo == m.lo ? (m.lo_closed && b.lo_closed) : b.lo_closed;
    m.lo = b.lo;
  }
  if (b.hi && (!m.hi || *b.hi < *m.hi || (*b.hi == *m.hi && !b.hi_closed))) {
    m.hi_closed = m.hi && *b.hi == *m.hi ? (m.hi_closed && b.hi_closed) : b.hi_closed;
    m.hi = b.hi;
  }
  if (ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
  return m;
}

std::vector<Magnitudes> Magnitudes::subtract(const Magnitudes& B) const {
  const Magnitudes& A = *this;
  if (A.empty) return {};
  if (B.empty) return {A};
  std::vector<Magnitudes> out;
  const Magnitudes left = make(A.lo, A.lo_closed, B.lo, !B.lo_closed);
  if (!left.empty) {
    // Clip to A's upper end.
    Magnitudes l = left;
    if (A.hi && (*A.hi < *l.hi || (*A.hi == *l.hi && !A.hi_closed))) l = make(A.lo, A.lo_closed, A.hi, A.hi_closed);
    if (!l.empty) out.push_back(l);
  }
  if (B.hi) {
    Magnitudes right = make(*B.hi, !B.hi_closed, A.hi, A.hi_closed);
    if (right.lo < A.lo || (right.lo == A.lo && !A.lo_closed)) right = make(A.lo, A.lo_closed, A.hi, A.hi_closed);
    if (!right.empty) out.push_back(right);
  }
  return out;
}

std::string Magnitudes::describe() const {
  if (empty) return "no common magnitude";
  return std::string(lo_closed ? "[" : "(") + to_string(lo) + ", " + (hi ? to_string(*hi) : "inf") +
         (hi && hi_closed ? "]" : ")");
}

std::string Magnitudes::describe_readable() const {
  if (empty) return "no common magnitude";
  return std::string(lo_closed ? "[" : "(") + internal::readable(lo) + ", " + (hi ? internal::readable(*hi) : "inf") +
         (hi && hi_closed ? "]" : ")");
}

}  // namespace fixel
