// Joins and runs of the pushing region's pieces (internal/region_runs.h).
#include "fixel/internal/region_runs.h"

#include <algorithm>
#include <limits>

#include "fixel/internal/filtered.h"

namespace fixel::internal {

namespace {

// Limiting tangent directions at the ends of a Bézier piece: the first
// non-zero forward difference P_k − P_0 (resp. P_p − P_k).
Vec2 start_tangent(const BezierPiece& p) {
  for (std::size_t k = 1; k < p.control.size(); ++k) {
    Vec2 t = sub(p.control[k], p.control[0]);
    if (!is_zero(t)) return t;
  }
  return {0, 0};
}
Vec2 end_tangent(const BezierPiece& p) {
  const Vec2& last = p.control.back();
  for (std::size_t k = p.control.size() - 1; k-- > 0;) {
    Vec2 t = sub(last, p.control[k]);
    if (!is_zero(t)) return t;
  }
  return {0, 0};
}

// A tangent discontinuity between consecutive pieces (the cross product's
// sign filtered; the dot product only for exactly parallel tangents).
bool is_corner(const Vec2& t_in, const Vec2& t_out) {
  return internal::orientation_filtered(t_in, t_out) != 0 || dot(t_in, t_out) < 0;
}

}  // namespace

// Tangents on both sides of every piece start (in loop order).
std::vector<Join> joins(const Boundary& b) {
  std::vector<Join> out;
  const std::size_t n = b.pieces.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 t_in = end_tangent(b.pieces[(k + n - 1) % n]), t_out = start_tangent(b.pieces[k]);
    out.push_back({t_in, t_out, is_corner(t_in, t_out)});
  }
  return out;
}

std::vector<RegionInterval> merge_runs(const std::vector<RegionInterval>& in) {
  std::vector<RegionInterval> out;
  for (const auto& r : in) {
    if (!out.empty() && out.back().curve == r.curve && out.back().status == r.status && out.back().u1 == r.u0) {
      out.back().u1 = r.u1;
      out.back().exact_u1 = r.exact_u1;
      out.back().half_line = out.back().half_line && r.half_line;
      out.back().magnitudes = out.back().magnitudes.intersect(r.magnitudes);
      if (!out.back().magnitude_set.empty() && !r.magnitude_set.empty() && !out.back().magnitudes.empty)
        out.back().magnitude_set = {out.back().magnitudes};  // certified pieces intersect to one interval
      else
        out.back().magnitude_set.clear();
      continue;
    }
    out.push_back(r);
  }
  return out;
}

Magnitudes neutral_magnitudes() { return Magnitudes::make(Rational(0), true, std::nullopt, false); }

void settle(std::vector<RegionInterval>& raw, const std::vector<Deferred>& deferred, bool merging) {
  if (!merging) {
    for (const auto& d : deferred) raw[d.index].magnitudes = d.exact();
    return;
  }
  std::vector<const Deferred*> of(raw.size(), nullptr);
  for (const auto& d : deferred) of[d.index] = &d;
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0, j = 0; i < raw.size(); i = j) {
    // One run of merge_runs(): same curve and status, each starting where the last ended.
    for (j = i + 1;
         j < raw.size() && raw[j].curve == raw[i].curve && raw[j].status == raw[i].status && raw[j - 1].u1 == raw[j].u0;
         ++j) {
    }
    if (raw[i].status != RegionStatus::kIn) continue;
    double max_lo = -inf, min_hi = inf;  // largest certain lower end, smallest certain upper end
    for (std::size_t k = i; k < j; ++k) {
      if (of[k]) {
        max_lo = std::max(max_lo, of[k]->bounds.lo.inf());
        if (of[k]->bounds.has_hi) min_hi = std::min(min_hi, of[k]->bounds.hi.sup());
        continue;
      }
      const Magnitudes& m = raw[k].magnitudes;
      if (m.empty) continue;
      max_lo = std::max(max_lo, to_interval(m.lo).inf());
      if (m.hi) min_hi = std::min(min_hi, to_interval(*m.hi).sup());
    }
    for (std::size_t k = i; k < j; ++k)
      if (of[k] && (of[k]->bounds.lo.sup() >= max_lo || (of[k]->bounds.has_hi && of[k]->bounds.hi.inf() <= min_hi)))
        raw[k].magnitudes = of[k]->exact();
  }
}

}  // namespace fixel::internal
