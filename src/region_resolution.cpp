// The per-piece resolution of the pushing region (RegionOptions::
// resolution_length): an exact upper bound on a Bézier piece's speed and the
// parameter width that keeps every stretch at most a given length.
#include <cmath>
#include <limits>

#include "fixel/error.h"
#include "fixel/region.h"

namespace fixel {

Rational speed_bound(const BezierPiece& piece) {
  Rational longest = 0;
  for (const Vec2& leg : piece.legs()) {
    const Rational sq = leg.x * leg.x + leg.y * leg.y;
    if (sq == 0) continue;
    // An upper bound on sqrt(sq): the double square root rounded up, checked
    // exactly; |x| + |y| when that check fails (or the double overflows).
    Rational up = boost::multiprecision::abs(leg.x) + boost::multiprecision::abs(leg.y);
    const double d = std::sqrt(to_double(sq));
    if (std::isfinite(d) && d > 0) {
      for (const double candidate : {d, std::nextafter(d * (1 + 1e-12), std::numeric_limits<double>::infinity())}) {
        const Rational guess(candidate);  // exact conversion of the double
        if (guess * guess >= sq) {        // (d itself when the root is exact)
          if (guess < up) up = guess;
          break;
        }
      }
    }
    longest = std::max(longest, up);
  }
  return Rational(piece.degree()) * longest;
}

Rational resolution_width(const BezierPiece& piece, const Rational& length) {
  if (length <= 0) throw InputError("RegionOptions.resolution_length", to_string(length), "must be > 0");
  const Rational speed = speed_bound(piece);
  Rational width = piece.u1 - piece.u0, bound = speed;
  for (int d = 0; bound > length; ++d) {
    if (d >= 64)
      throw InputError("RegionOptions.resolution_length", to_string(length),
                       "is too small for curve " + std::to_string(piece.curve) + ", u in [" + to_string(piece.u0) +
                           ", " + to_string(piece.u1) + "]: it needs more than 2^64 parts");
    width /= 2;
    bound /= 2;
  }
  return width;
}

}  // namespace fixel
