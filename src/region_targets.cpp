// What the targets of the pushing region share: the default answer to the
// exact region's question, and the common magnitudes of a cone's rays.
#include <array>
#include <string>

#include "fixel/error.h"
#include "fixel/internal/region_targets.h"
#include "fixel/internal/wrench_cone_detail.h"
#include "fixel/region_target.h"

namespace fixel {

std::vector<Polynomial> RegionTarget::sign_polynomials(const std::vector<std::array<Polynomial, 3>>&) const {
  throw UnsupportedError("RegionOptions.exact", "",
                         std::string("is not supported for the push model \"") + push_model() +
                             "\" of this target (it gives no sign polynomials)");
}

namespace internal {

Magnitudes common_magnitudes(const std::vector<VectorQ>& gens, const std::vector<Magnitudes>& T, const Vec2& d_first,
                             const Vec2& d_last) {
  Magnitudes m;
  m.empty = false;
  m.lo = 0;
  m.lo_closed = true;
  m.hi_closed = true;
  const Rational c = internal::cos_half_angle_lower(d_first, d_last);
  if (c <= 0) return Magnitudes{};
  // |f_j|² and its root bounds, computed again only when the force part
  // changes (generators come in pairs with one force part).
  Rational f2, f_up, f_low;
  bool have_low = false;
  for (std::size_t j = 0; j < gens.size(); ++j) {
    if (T[j].empty) return Magnitudes{};
    if (j == 0 || gens[j][0] != gens[j - 1][0] || gens[j][1] != gens[j - 1][1]) {
      f2 = gens[j][0] * gens[j][0] + gens[j][1] * gens[j][1];
      f_up = internal::sqrt_upper(f2);
      have_low = false;
    }
    const Rational lo = T[j].lo * f_up;
    if (lo > m.lo) m.lo = lo;
    m.lo_closed = m.lo_closed && T[j].lo_closed;
    if (T[j].hi) {
      if (!have_low) f_low = internal::sqrt_lower(f2), have_low = true;
      // m·K must stay below hi_j |f_j|, K = 1/cos(Δ/2) <= 1/c.
      const Rational hi = *T[j].hi * f_low * c;
      if (!m.hi || hi < *m.hi) m.hi = hi;
      m.hi_closed = m.hi_closed && T[j].hi_closed;
    }
  }
  if (Magnitudes::ends_cross(m.lo, m.lo_closed, m.hi, m.hi_closed)) return Magnitudes{};
  return m;
}

}  // namespace internal

}  // namespace fixel
