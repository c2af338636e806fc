// Interval pre-tests of the pushing region (internal/region_filter.h): the
// decisions of segment_bounds, segment_wrench_cone (tight), push_extremes
// and the target's ray and OUT tests, each on a certified sign of an
// enclosure; the first sign the enclosures cannot certify abandons the
// pre-test (Quick::kUnknown) and the exact path decides.
#include "fixel/internal/region_filter.h"

#include <algorithm>
#include <boost/container/small_vector.hpp>
#include <cmath>
#include <limits>

#include "fixel/internal/cone_extremes.h"
#include "fixel/internal/paper_cone_filter.h"
#include "fixel/internal/wrench_cone_detail.h"

namespace fixel::internal {

// The extremes of enclosed directions (internal/enclosed_plane.h).
bool enclosed::extremes(const FVecs& v, std::size_t& first, std::size_t& last) {
  auto orient = [&](std::size_t i, std::size_t j) { return i == j ? 0 : sign_of(fcross(v[i], v[j])); };
  return cone_extremes(
      v.size(), orient, [&](std::size_t i, std::size_t j) { return sign_of(fdot(v[i], v[j])); }, first, last);
}

namespace {

using enclosed::extremes;
using enclosed::fcross;
using enclosed::fdot;
using enclosed::FGens;
using enclosed::frot90;
using enclosed::fsub;
using enclosed::FVecs;
using enclosed::Open;
using enclosed::sign_of;
using Cones = boost::container::small_vector<FGens, 2>;
using Tags = boost::container::small_vector<boost::container::small_vector<int, 8>, 2>;

// is_zero(v), certified.
bool is_zero_f(const FVec2& v) {
  const int sx = certain_sign(v.x), sy = certain_sign(v.y);
  if ((sx != 0 && sx != kUndecided) || (sy != 0 && sy != kUndecided)) return false;
  if (sx == 0 && sy == 0) return true;
  throw Open{};
}

// push_direction (wrench_cone.cpp) on enclosures, the same formula.
FVec2 fpush(const FVec2& tangent, EdgeFamily family, const FI& mu) {
  const FVec2 n = frot90(tangent);
  return push_direction_from(n, frot90(n), family, mu);
}

// min_k and max_k of (P_k − c) ⊗ d enclosed (the tight cone's moments; the
// exact path takes the same extremes of the same values), and the k that
// is certainly the only one to attain each (its enclosure entirely below,
// resp. above, every other's), else −1.
void moment_range(const FVecs& r, const FVec2& d, FI& lo, FI& hi, int& lo_at, int& hi_at) {
  double lo_inf = 0, lo_sup = 0, hi_inf = 0, hi_sup = 0;
  lo_at = hi_at = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const FI m = fcross(r[k], d);
    if (k == 0 || m.sup() < lo_sup) lo_at = static_cast<int>(k);
    if (k == 0 || m.inf() > hi_inf) hi_at = static_cast<int>(k);
    lo_inf = k ? std::min(lo_inf, m.inf()) : m.inf();
    lo_sup = k ? std::min(lo_sup, m.sup()) : m.sup();
    hi_inf = k ? std::max(hi_inf, m.inf()) : m.inf();
    hi_sup = k ? std::max(hi_sup, m.sup()) : m.sup();
  }
  lo = FI(lo_inf, lo_sup);
  hi = FI(hi_inf, hi_sup);
  // The candidates: the least upper end, the greatest lower end; each must
  // be certainly below (above) every other point's moment.
  for (std::size_t k = 0; k < r.size(); ++k) {
    const FI m = fcross(r[k], d);
    if (lo_at >= 0 && static_cast<int>(k) != lo_at && !(lo_sup < m.inf())) lo_at = -1;
    if (hi_at >= 0 && static_cast<int>(k) != hi_at && !(hi_inf > m.sup())) hi_at = -1;
  }
}

FI fmax(const FI& a, const FI& b) { return FI(std::max(a.inf(), b.inf()), std::max(a.sup(), b.sup())); }
FI fmin(const FI& a, const FI& b) { return FI(std::min(a.inf(), b.inf()), std::min(a.sup(), b.sup())); }

// common_magnitudes (region_targets.cpp) enclosed: lo = max_j T_j.lo ·
// sqrt_upper(|f_j|²), hi = min_j T_j.hi · sqrt_lower(|f_j|²) · c, where
// sqrt_upper(x) ∈ [√x, √x + 2^-20] and sqrt_lower(x) ∈ [√x − 2^-20, √x].
// False when a sign is open or the ends may touch.
bool common_bounds(const FGens& gens, const FVec2& first, const FVec2& last, const IntervalTarget& target,
                   MagnitudeBounds& m) {
  Protect guard;
  FI c;
  if (!cos_half_bounds(first, last, c)) return false;
  const FI step(1.0 / 1048576);
  m = MagnitudeBounds{};
  m.lo = FI(0);
  for (const auto& g : gens) {
    FMagnitudes T;
    if (!target.interval_magnitudes(g, T)) return false;
    const FI f = CGAL::sqrt(g[0] * g[0] + g[1] * g[1]);
    m.lo = fmax(m.lo, T.lo * FI(f.inf(), (f + step).sup()));
    m.lo_closed = m.lo_closed && T.lo_closed;
    m.all_half = m.all_half && !T.has_hi;
    if (T.has_hi) {
      const FI hi = T.hi * FI(std::max(0.0, (f - step).inf()), f.sup()) * c;
      m.hi = m.has_hi ? fmin(m.hi, hi) : hi;
      m.has_hi = true;
    }
  }
  // Ends that certainly cross make the exact answer empty (ends_cross),
  // whatever the closedness; ends that may touch leave it to the exact path.
  if (m.has_hi && m.hi.sup() < m.lo.inf()) m.empty = true;
  return m.empty || !m.has_hi || m.hi.inf() > m.lo.sup();
}

// The ray tests of every generator; kIn when all hit, else the OUT tests of
// each cone in order (as classify asks target.misses), else partial. A ray
// test left undecided matters only where its answer could change the
// outcome: when no generator certainly misses (IN is possible), and in a
// cone with no certain hit (the exact path's OUT test, and its LP count,
// depend on it).
Quick decide(const Cones& cones, const Tags* tags, IntervalTarget& target, bool segment) {
  target.paired_generators = segment;  // a segment's cones: (d, lo), (d, hi) per force part d
  // The tags are read only during the calls below.
  struct Clear {
    IntervalTarget& t;
    ~Clear() { t.generator_points = nullptr; }
  } clear{target};
  boost::container::small_vector<boost::container::small_vector<int, 8>, 2> hits(cones.size());
  FGens all;
  boost::container::small_vector<int, 16> all_hits, all_points;
  for (std::size_t c = 0; c < cones.size(); ++c)
    for (std::size_t k = 0; k < cones[c].size(); ++k) {
      hits[c].push_back(target.interval_ray_hits(cones[c][k]));
      all.push_back(cones[c][k]);
      all_hits.push_back(hits[c].back());
      all_points.push_back(tags ? (*tags)[c][k] : -1);
    }
  target.generator_points = all_points.data();
  const int in = target.interval_contains(all.data(), all_hits.data(), all.size());
  if (in == kUndecided) throw Open{};
  if (in == 1) return Quick::kIn;
  if (!segment) return Quick::kOut;
  for (std::size_t c = 0; c < cones.size(); ++c) {
    if (!target.out_test_sees_hits()) {
      if (std::find(hits[c].begin(), hits[c].end(), 1) != hits[c].end()) continue;  // does not miss
      // An undecided ray could be a hit, which would spare the LP a certified
      // answer counts (RegionStats::lp_tests): the exact tests decide.
      if (std::find(hits[c].begin(), hits[c].end(), kUndecided) != hits[c].end()) throw Open{};
    }
    target.generator_points = tags ? (*tags)[c].data() : nullptr;
    const int missed = target.certify_out_test(cones[c].data(), cones[c].size());
    if (missed == 1) return Quick::kOut;
    if (missed == kUndecided) throw Open{};  // the exact LP decides
  }
  return Quick::kPartial;
}

// On kIn: the enclosure of the answer's magnitudes (force parts spanning
// first to last), when certified.
void in_bounds(const Cones& cones, const FVec2& first, const FVec2& last, const IntervalTarget& target,
               std::optional<MagnitudeBounds>* bounds) {
  if (!target.in_answers_have_magnitudes()) {  // a cone target: no magnitudes, as the exact answer says
    MagnitudeBounds none;
    none.empty = true;
    *bounds = none;
    return;
  }
  FGens gens;
  for (const auto& cone : cones) gens.insert(gens.end(), cone.begin(), cone.end());
  MagnitudeBounds m;
  if (common_bounds(gens, first, last, target, m)) *bounds = m;
}

}  // namespace

// The convex target's rule: every generator's ray hits.
int IntervalTarget::interval_contains(const FGen*, const int* hits, std::size_t n) const {
  bool undecided = false;
  for (std::size_t k = 0; k < n; ++k) {
    if (hits[k] == 0) return 0;
    undecided = undecided || hits[k] == kUndecided;
  }
  return undecided ? kUndecided : 1;
}

// With C = cos(Δ/2) exact: cos_half_angle_lower's answer c passed the
// exact test c <= C; it starts at the double estimate floored to 2^-20
// (within 10^-6 + 2^-20 below C: the estimate's error is far below 10^-6
// once a, b are normalised), and each step down from a c' > C lands at
// c'(1 − 1/1024) − 2^-20 > C(1 − 1/1024) − 2^-20. Certified only when that
// lower end is positive (then c > 0).
bool cos_half_bounds(const FVec2& a, const FVec2& b, FI& out) {
  const FI Q = fdot(a, a) * fdot(b, b);
  if (!(Q.inf() > 0)) return false;
  const FI h = (1 + fdot(a, b) / CGAL::sqrt(Q)) / 2;
  if (!(h.sup() > 0)) return false;
  const FI C = CGAL::sqrt(FI(std::max(0.0, h.inf()), h.sup()));
  const FI step(1.0 / 1048576);
  const double low = std::min((C - FI(1e-6) - step).inf(), (C * FI(1 - 1.0 / 1024) - step).inf());
  if (!(low > 0) || !(C.sup() >= low)) return false;
  out = FI(low, C.sup());
  return true;
}

Quick quick_segment(const LazyPiece::Enclosures& control, const LazyPiece::Enclosures& leg_enclosures, const Vec2& c,
                    const Rational& mu, const std::vector<EdgeFamily>& families, ConeMethod method,
                    IntervalTarget& target, std::optional<MagnitudeBounds>* bounds) {
  Cones cones;
  Tags tags;  // per cone, per generator: the control point whose moment it certainly is, or −1
  FVecs forces;
  try {
    {
      Protect guard;
      const FVec2 fc = to_interval(c);
      const FI fmu = to_interval(mu);
      FVecs P, r, legs;
      if (control.empty()) throw Open{};
      for (const auto& p : control) {
        P.push_back(p);
        r.push_back(fsub(P.back(), fc));
      }
      if (leg_enclosures.size() + 1 != control.size()) throw Open{};
      for (const FVec2& leg : leg_enclosures)
        if (!is_zero_f(leg)) legs.push_back(leg);
      if (legs.empty()) throw Open{};  // the exact path reports the degenerate segment
      std::size_t s = 0, e = 0;
      if (!extremes(legs, s, e)) return Quick::kPartial;  // not pointed: split
      for (const EdgeFamily f : families) {
        const FVec2 ds = fpush(legs[s], f, fmu);
        const FVec2 de = fpush(legs[e], f == EdgeFamily::kWholeCone ? EdgeFamily::kPlus : f, fmu);
        // One leg (a straight piece): ds = de exactly, a nonzero vector, which
        // its enclosure alone cannot show (x·y − y·x is not a point).
        const bool same = s == e && f != EdgeFamily::kWholeCone;
        const int span = same ? 0 : sign_of(fcross(ds, de));
        if (span < 0 || (span == 0 && !same && sign_of(fdot(ds, de)) < 0)) return Quick::kPartial;
        if (method == ConeMethod::kPaper) {
          if (!enclosed::paper_cone(ds, de, r, leg_enclosures, cones.emplace_back(), forces)) return Quick::kPartial;
          tags.emplace_back(cones.back().size(), -1);
          continue;
        }
        forces.push_back(ds);
        if (!same) forces.push_back(de);     // equal vectors: no undecidable cross product below
        FGens& gens = cones.emplace_back();  // filled in place: no small_vector move
        // de = ds exactly (one leg): its two generators would repeat ds's,
        // the same cone, and make cross products no enclosure shows nonzero.
        auto& points = tags.emplace_back();
        for (const FVec2& d : {ds, de}) {
          if (same && gens.size() == 2) break;
          FI lo, hi;
          int lo_at = -1, hi_at = -1;
          moment_range(r, d, lo, hi, lo_at, hi_at);
          gens.push_back({d.x, d.y, lo});
          gens.push_back({d.x, d.y, hi});
          points.push_back(lo_at);
          points.push_back(hi_at);
        }
      }
    }
    const Quick q = decide(cones, &tags, target, true);
    if (q != Quick::kIn || !bounds) return q;
  } catch (const Open&) {
    return Quick::kUnknown;
  }
  try {  // IN is decided; the bounds are optional
    std::size_t s = 0, e = 0;
    bool pointed = false;
    {
      Protect guard;
      pointed = extremes(forces, s, e);
    }
    if (pointed) in_bounds(cones, forces[s], forces[e], target, bounds);
  } catch (const Open&) {
  }
  return Quick::kIn;
}

Quick quick_point(const FVec2& t_in, const FVec2& t_out, const Vec2& point, const Vec2& c, const Rational& mu,
                  const std::vector<EdgeFamily>& families, IntervalTarget& target,
                  std::optional<MagnitudeBounds>* bounds) {
  Cones cones(1);
  FVec2 first, last;
  try {
    {
      Protect guard;
      const FVec2 &ti = t_in, &to = t_out;
      if (is_zero_f(ti) || is_zero_f(to)) return Quick::kPartial;  // undefined normal (cusp)
      const FI fmu = to_interval(mu);
      FVecs dirs;
      for (const EdgeFamily f : families) {
        dirs.push_back(fpush(ti, f, fmu));
        dirs.push_back(fpush(to, f, fmu));
      }
      std::size_t s = 0, e = 0;
      if (!extremes(dirs, s, e)) return Quick::kPartial;  // fan of π or more
      const FVec2 r = fsub(to_interval(point), to_interval(c));
      for (const std::size_t k : {s, e}) cones[0].push_back({dirs[k].x, dirs[k].y, fcross(r, dirs[k])});
      first = dirs[s];
      last = dirs[e];
    }
    const Quick q = decide(cones, nullptr, target, false);
    if (q != Quick::kIn || !bounds) return q;
  } catch (const Open&) {
    return Quick::kUnknown;
  }
  try {
    in_bounds(cones, first, last, target, bounds);
  } catch (const Open&) {
  }
  return Quick::kIn;
}

}  // namespace fixel::internal
