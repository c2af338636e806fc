// Joins and runs of the pushing region's pieces (internal/region_runs.h).
#include "fixel/internal/region_runs.h"

#include <algorithm>
#include <limits>

#include "fixel/internal/filtered.h"

namespace fixel::internal {

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

namespace {

// Whether the enclosure certainly excludes 0 (1), is the point 0 (0), or
// cannot tell (kUndecided).
int nonzero(const FVec2& v) {
  const int sx = certain_sign(v.x), sy = certain_sign(v.y);
  if ((sx != 0 && sx != kUndecided) || (sy != 0 && sy != kUndecided)) return 1;
  return sx == 0 && sy == 0 ? 0 : kUndecided;
}

// start_tangent (from_end false) or end_tangent enclosed: the first
// difference certainly non-zero after certain zeros; false when a zero test
// is undecided. Needs a Protect scope.
bool tangent_enclosure(const BezierPiece& p, bool from_end, FVec2& out) {
  const std::size_t n = p.control.size();
  const FVec2 base = to_interval(from_end ? p.control.back() : p.control.front());
  for (std::size_t i = 1; i < n; ++i) {
    const FVec2 q = to_interval(p.control[from_end ? n - 1 - i : i]);
    const FVec2 d = from_end ? FVec2{base.x - q.x, base.y - q.y} : FVec2{q.x - base.x, q.y - base.y};
    const int z = nonzero(d);
    if (z == kUndecided) return false;
    if (z == 1) {
      out = d;
      return true;
    }
  }
  out = {FI(0), FI(0)};
  return true;
}

}  // namespace

std::vector<Join> joins(const Boundary& b) {
  std::vector<Join> out;
  const std::size_t n = b.pieces.size();
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    Join j{(k + n - 1) % n, k, {}, {}, false};
    int c = kUndecided;
    if (!force_exact()) {  // the enclosures serve the filters only
      Protect guard;
      if (!tangent_enclosure(b.pieces[j.prev], true, j.t_in)) j.t_in = to_interval(end_tangent(b.pieces[j.prev]));
      if (!tangent_enclosure(b.pieces[k], false, j.t_out)) j.t_out = to_interval(start_tangent(b.pieces[k]));
      // A tangent discontinuity: cross(t_in, t_out) != 0 || dot(t_in, t_out) < 0.
      {
        const int o = certain_sign(j.t_in.x * j.t_out.y - j.t_in.y * j.t_out.x);
        const int d = certain_sign(j.t_in.x * j.t_out.x + j.t_in.y * j.t_out.y);
        if (o != kUndecided && o != 0)
          c = 1;
        else if (o == 0 && d != kUndecided)
          c = d < 0;
        record_filter(FilterSite::kOrientation, c != kUndecided);
      }
    }
    if (c == kUndecided) {
      const Vec2 t_in = end_tangent(b.pieces[j.prev]), t_out = start_tangent(b.pieces[k]);
      c = cross(t_in, t_out) != 0 || dot(t_in, t_out) < 0;
    }
    j.corner = c == 1;
    out.push_back(j);
  }
  return out;
}

std::vector<RegionInterval> merge_runs(std::vector<RegionInterval> in) {
  std::vector<RegionInterval> out;
  for (auto& r : in) {
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
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<RegionCorner> corner_ends(const std::vector<RegionInterval>& raw, const std::vector<std::size_t>& corners) {
  std::vector<RegionCorner> out;
  const std::size_t n = raw.size();
  for (const std::size_t i : corners) {
    const RegionInterval& c = raw[i];
    bool differs = false;
    // The loop is closed: the first corner's neighbour before it is the last interval.
    for (const std::size_t j : {(i + n - 1) % n, (i + 1) % n}) {
      const RegionStatus s = raw[j].status;
      differs = differs || (j != i && s != RegionStatus::kPartial && s != c.status);
    }
    if (differs) out.push_back({c.curve, c.u0, c.status});
  }
  return out;
}

Magnitudes neutral_magnitudes() { return Magnitudes::make(Rational(0), true, std::nullopt, false); }

namespace {

// The exact magnitudes of a deferred IN answer. When its lower end's
// enclosure is a point and it has no upper end, that is the answer
// common_magnitudes gives (lo the point, the conjunction of the lower
// ends' closedness, as the bounds hold it), with no exact work; this is
// the rule where b0 is the apex of S, every lower end 0. Else the exact path.
Magnitudes exact_magnitudes(const Deferred& d, long& computed) {
  const MagnitudeBounds& b = d.bounds;
  if (!b.has_hi && b.lo.inf() == b.lo.sup()) {
    Magnitudes m;
    m.empty = false;
    m.lo = Rational(b.lo.inf());
    m.lo_closed = b.lo_closed;
    m.hi_closed = true;  // as common_magnitudes leaves it without an upper end
    return m;
  }
  ++computed;
  return d.exact();
}

}  // namespace

void settle(std::vector<RegionInterval>& raw, const std::vector<Deferred>& deferred, bool merging) {
  if (!merging) {
    long computed = 0;
    for (const auto& d : deferred) raw[d.index].magnitudes = exact_magnitudes(d, computed);
    record_filter(FilterSite::kInMagnitudes, static_cast<long>(deferred.size()) - computed, computed);
    return;
  }
  long computed = 0;
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
        raw[k].magnitudes = exact_magnitudes(*of[k], computed);
  }
  record_filter(FilterSite::kInMagnitudes, static_cast<long>(deferred.size()) - computed, computed);
}

}  // namespace fixel::internal
