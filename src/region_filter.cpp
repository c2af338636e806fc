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

#include "fixel/internal/wrench_cone_detail.h"

namespace fixel::internal {

namespace {

// Small fixed-capacity vectors: no allocation for the usual few control
// points, generators and families.
using FVecs = boost::container::small_vector<FVec2, 8>;
using FGens = boost::container::small_vector<FGen, 8>;
using Cones = boost::container::small_vector<FGens, 2>;

// Thrown at the first uncertified sign; caught by the two entry points.
struct Undecided {};

int sign_of(const FI& x) {
  const int s = certain_sign(x);
  if (s == kUndecided) throw Undecided{};
  return s;
}

FI fcross(const FVec2& a, const FVec2& b) { return a.x * b.y - a.y * b.x; }
FI fdot(const FVec2& a, const FVec2& b) { return a.x * b.x + a.y * b.y; }
FVec2 fsub(const FVec2& a, const FVec2& b) { return {a.x - b.x, a.y - b.y}; }
FVec2 frot90(const FVec2& v) { return {-v.y, v.x}; }

// is_zero(v), certified.
bool is_zero_f(const FVec2& v) {
  const int sx = certain_sign(v.x), sy = certain_sign(v.y);
  if ((sx != 0 && sx != kUndecided) || (sy != 0 && sy != kUndecided)) return false;
  if (sx == 0 && sy == 0) return true;
  throw Undecided{};
}

// push_direction (wrench_cone.cpp) on enclosures, the same formula.
FVec2 fpush(const FVec2& tangent, EdgeFamily family, const FI& mu) {
  const FVec2 n = frot90(tangent);
  return push_direction_from(n, frot90(n), family, mu);
}

// direction_extremes (wrench_cone.cpp) on enclosures: the same decisions in
// the same order; the indices of the extremes. False when not pointed.
bool extremes(const FVecs& v, std::size_t& first, std::size_t& last) {
  auto orient = [&](std::size_t i, std::size_t j) { return i == j ? 0 : sign_of(fcross(v[i], v[j])); };
  int s = -1, e = -1;
  for (std::size_t i = 0; i < v.size(); ++i) {
    bool all_ccw = true, all_cw = true;
    for (std::size_t j = 0; j < v.size() && (all_ccw || all_cw); ++j) {
      const int o = orient(i, j);
      all_ccw = all_ccw && o >= 0;
      all_cw = all_cw && o <= 0;
    }
    if (all_ccw && s < 0) s = static_cast<int>(i);
    if (all_cw && e < 0) e = static_cast<int>(i);
  }
  if (s < 0 || e < 0) return false;
  const FVec2 &f = v[s], &l = v[e];
  const int c = orient(s, e);
  if (c < 0 || (c == 0 && sign_of(fdot(f, l)) < 0)) return false;
  for (std::size_t j = 0; j < v.size(); ++j) {
    const int a = orient(s, j);
    bool inside;
    if (c == 0)
      inside = a == 0 && sign_of(fdot(f, v[j])) > 0;
    else
      inside = a >= 0 && orient(j, e) >= 0;
    if (!inside && !(c == 0 && a == 0 && sign_of(fdot(f, v[j])) > 0)) return false;
  }
  first = static_cast<std::size_t>(s);
  last = static_cast<std::size_t>(e);
  return true;
}

// min_k and max_k of (P_k − c) ⊗ d enclosed (the tight cone's moments; the
// exact path takes the same extremes of the same values).
void moment_range(const FVecs& r, const FVec2& d, FI& lo, FI& hi) {
  double lo_inf = 0, lo_sup = 0, hi_inf = 0, hi_sup = 0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    const FI m = fcross(r[k], d);
    lo_inf = k ? std::min(lo_inf, m.inf()) : m.inf();
    lo_sup = k ? std::min(lo_sup, m.sup()) : m.sup();
    hi_inf = k ? std::max(hi_inf, m.inf()) : m.inf();
    hi_sup = k ? std::max(hi_sup, m.sup()) : m.sup();
  }
  lo = FI(lo_inf, lo_sup);
  hi = FI(hi_inf, hi_sup);
}

// is_zero(v) as 1 (certainly zero), 0 (certainly not) or kUndecided.
int zero_state(const FVec2& v) {
  const int sx = certain_sign(v.x), sy = certain_sign(v.y);
  if ((sx != 0 && sx != kUndecided) || (sy != 0 && sy != kUndecided)) return 0;
  return sx == 0 && sy == 0 ? 1 : kUndecided;
}

// The paper cone's unit direction bound (unit_direction_outward,
// wrench_cone.cpp) of the direction enclosed by d: the same grid point,
// found by the same side tests, each certified. u encloses it; k and flip
// name it exactly.
struct GridUnit {
  long k = 0;
  bool flip = false;
  FVec2 u;
};

// u(τ) or −u(τ), τ = k/2^20 (|k| < 2^26: τ², 1 ± τ² and 2τ are exact doubles).
FVec2 grid_point(long k, bool flip) {
  const double t = std::ldexp(static_cast<double>(k), -20);
  const FI n(1 + t * t);
  const FVec2 u{FI(1 - t * t) / n, FI(2 * t) / n};
  return flip ? FVec2{-u.x, -u.y} : u;
}

GridUnit unit_outward(const FVec2& d, bool cw) {
  GridUnit g;
  g.flip = sign_of(d.x) < 0;  // the exact path's d.x < 0
  // Any start gives the same answer; this one is usually it.
  long k = unit_grid_guess((d.x.inf() + d.x.sup()) / 2, (d.y.inf() + d.y.sup()) / 2, g.flip);
  const long outward = cw ? -1 : 1;
  auto on_side = [&](long j, FVec2& u) {
    u = grid_point(j, g.flip);
    return sign_of(cw ? fcross(u, d) : fcross(d, u)) >= 0;
  };
  int steps = 0;
  for (; !on_side(k, g.u); k += outward)
    if (++steps > kUnitGridSteps) throw Undecided{};
  for (FVec2 inner; on_side(k - outward, inner); k -= outward) {
    g.u = inner;
    if (++steps > kUnitGridSteps) throw Undecided{};
  }
  g.k = k;
  return g;
}

// in_cone_filtered(d, a, b) (wrench_cone.cpp) as 1, 0 or kUndecided, given
// ab, the exact sign of a ⊗ b (0 only for a = b here).
int in_arc(const FVec2& d, const FVec2& a, const FVec2& b, int ab) {
  const int c1 = certain_sign(fcross(a, d));
  if (ab == 0) {
    if (c1 == kUndecided) return kUndecided;
    if (c1 != 0) return 0;
    const int along = certain_sign(fdot(a, d));
    return along == kUndecided ? kUndecided : along > 0;
  }
  const int c2 = certain_sign(fcross(d, b));
  if ((c1 != kUndecided && c1 < 0) || (c2 != kUndecided && c2 < 0)) return 0;
  return c1 == kUndecided || c2 == kUndecided ? kUndecided : 1;
}

// Whether control point k is a vertex of the control points' convex hull
// (what convex_hull_2 returns; a repeated point counts once, with the same
// values): 1, 0 or kUndecided. It is iff the nonzero P_j − P_k lie in an
// open half-plane, i.e. are pointed as direction_extremes decides. The
// differences are sums of legs, which keep their precision on short pieces.
int hull_vertex(const LazyPiece::Enclosures& legs, std::size_t k) {
  FVecs v;
  for (std::size_t j = 0; j <= legs.size(); ++j) {
    if (j == k) continue;
    FVec2 diff{FI(0), FI(0)};
    for (std::size_t i = std::min(j, k); i < std::max(j, k); ++i) diff = {diff.x + legs[i].x, diff.y + legs[i].y};
    if (j < k) diff = {-diff.x, -diff.y};
    const int zero = zero_state(diff);
    if (zero == kUndecided) return kUndecided;
    if (zero == 0) v.push_back(diff);
  }
  if (v.empty()) return 1;
  try {
    std::size_t s = 0, e = 0;
    return extremes(v, s, e) ? 1 : 0;
  } catch (const Undecided&) {
    return kUndecided;
  }
}

// The paper cone (paper(), wrench_cone.cpp) of the push directions enclosed
// by ds and de: (û_s, X_min), (û_s, X_max), (û_e, X_min), (û_e, X_max), the
// last two left out when û_e = û_s exactly; false when û_s, û_e span π (the
// exact path splits). X_min and X_max are enclosed without deciding every
// candidate: the moments r ⊗ û over all control points have the hull's
// extremes, and a ⊥-angle bound R ∈ [|r|, |r| + 2^-20] (sqrt_upper) raises
// the lower end of the enclosure only when its point is certainly a hull
// vertex with ⊥ certainly in the arc, the upper end whenever it may be.
// A positive X_min (negative X_max) is shrunk by c ∈ [√h − 2^-20, √h],
// h = (1 + û_s·û_e)/2 (sqrt_lower); its sign must be certain.
bool paper_cone(const FVec2& ds, const FVec2& de, const FVecs& r, const LazyPiece::Enclosures& legs, FGens& gens,
                FVecs& forces) {
  const GridUnit us = unit_outward(ds, true), ue = unit_outward(de, false);
  const bool same = us.flip == ue.flip && us.k == ue.k;
  const int span = same ? 0 : sign_of(fcross(us.u, ue.u));
  if (span < 0 || (span == 0 && !same && sign_of(fdot(us.u, ue.u)) < 0)) return false;
  constexpr double inf = std::numeric_limits<double>::infinity();
  double max_lo = -inf, max_hi = -inf, min_lo = inf, min_hi = inf;
  for (const FVec2& rk : r)
    for (const FVec2* u : {&us.u, &ue.u}) {
      const FI m = fcross(rk, *u);
      max_lo = std::max(max_lo, m.inf());
      max_hi = std::max(max_hi, m.sup());
      min_lo = std::min(min_lo, m.inf());
      min_hi = std::min(min_hi, m.sup());
    }
  const FI step(1.0 / 1048576);
  for (std::size_t k = 0; k < r.size(); ++k) {
    const int zero = zero_state(r[k]);
    if (zero == 1) continue;  // the exact path skips r = 0
    const FI length = CGAL::sqrt(fdot(r[k], r[k]));
    const double R_lo = length.inf(), R_hi = (length + step).sup();
    int hull = 2;  // not asked yet
    for (const bool plus : {true, false}) {
      const FVec2 perp = plus ? frot90(r[k]) : FVec2{-frot90(r[k]).x, -frot90(r[k]).y};
      const int in = in_arc(perp, us.u, ue.u, span);
      if (in == 0) continue;
      if (hull == 2) hull = hull_vertex(legs, k);
      if (hull == 0) continue;
      const bool certain = zero == 0 && in == 1 && hull == 1;
      if (plus) {
        if (certain) max_lo = std::max(max_lo, R_lo);
        max_hi = std::max(max_hi, R_hi);
      } else {
        if (certain) min_hi = std::min(min_hi, -R_lo);
        min_lo = std::min(min_lo, -R_hi);
      }
    }
  }
  FI xmin(min_lo, min_hi), xmax(max_lo, max_hi);
  if (!(min_lo > 0) && !(min_hi <= 0)) throw Undecided{};  // the sign of X_min decides the shrink
  if (!(max_hi < 0) && !(max_lo >= 0)) throw Undecided{};
  if (min_lo > 0 || max_hi < 0) {
    const FI h = (1 + fdot(us.u, ue.u)) / 2;
    const FI root = CGAL::sqrt(FI(std::max(0.0, h.inf()), std::max(0.0, h.sup())));
    const FI c(std::max(0.0, (root - step).inf()), root.sup());
    if (min_lo > 0) xmin = xmin * c;
    if (max_hi < 0) xmax = xmax * c;
  }
  gens.push_back({us.u.x, us.u.y, xmin});
  gens.push_back({us.u.x, us.u.y, xmax});
  forces.push_back(us.u);
  if (same) return true;
  gens.push_back({ue.u.x, ue.u.y, xmin});
  gens.push_back({ue.u.x, ue.u.y, xmax});
  forces.push_back(ue.u);
  return true;
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
Quick decide(const Cones& cones, IntervalTarget& target, bool segment) {
  target.paired_generators = segment;  // a segment's cones: (d, lo), (d, hi) per force part d
  boost::container::small_vector<boost::container::small_vector<int, 8>, 2> hits(cones.size());
  FGens all;
  boost::container::small_vector<int, 16> all_hits;
  for (std::size_t c = 0; c < cones.size(); ++c)
    for (const auto& g : cones[c]) {
      hits[c].push_back(target.interval_ray_hits(g));
      all.push_back(g);
      all_hits.push_back(hits[c].back());
    }
  const int in = target.interval_contains(all.data(), all_hits.data(), all.size());
  if (in == kUndecided) throw Undecided{};
  if (in == 1) return Quick::kIn;
  if (!segment) return Quick::kOut;
  for (std::size_t c = 0; c < cones.size(); ++c) {
    if (!target.out_test_sees_hits()) {
      if (std::find(hits[c].begin(), hits[c].end(), 1) != hits[c].end()) continue;  // does not miss
      // An undecided ray could be a hit, which would spare the LP a certified
      // answer counts (RegionStats::lp_tests): the exact tests decide.
      if (std::find(hits[c].begin(), hits[c].end(), kUndecided) != hits[c].end()) throw Undecided{};
    }
    const int missed = target.certify_out_test(cones[c].data(), cones[c].size());
    if (missed == 1) return Quick::kOut;
    if (missed == kUndecided) throw Undecided{};  // the exact LP decides
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

namespace {

// Enclosures of the control points and of the legs, from exact points.
void enclose_exact(const std::vector<Vec2>& control, LazyPiece::Enclosures& ctrl, LazyPiece::Enclosures& legs) {
  for (std::size_t k = 0; k < control.size(); ++k) {
    ctrl.push_back(to_interval(control[k]));
    if (k > 0) legs.push_back(to_interval(sub(control[k], control[k - 1])));
  }
}

}  // namespace

LazyPiece::LazyPiece(const BezierPiece& root, bool enclose) : root_(&root), u0_(root.u0), u1_(root.u1) {
  if (!enclose) return;
  for (const auto& p : root.control) ctrl_.push_back(to_interval(p));
  // A whole piece is long, so the difference of enclosures is tight enough
  // and spares an exact subtraction per leg (polylines have many pieces).
  // A coordinate whose difference may be zero is subtracted exactly: an
  // exact zero (an axis-parallel leg) is then a point, as the exact path's
  // signs and the paper cone's grid directions need.
  Protect guard;
  for (std::size_t k = 1; k < ctrl_.size(); ++k) {
    FVec2 leg = fsub(ctrl_[k], ctrl_[k - 1]);
    if (leg.x.inf() <= 0 && leg.x.sup() >= 0) leg.x = to_interval(Rational(root.control[k].x - root.control[k - 1].x));
    if (leg.y.inf() <= 0 && leg.y.sup() >= 0) leg.y = to_interval(Rational(root.control[k].y - root.control[k - 1].y));
    legs_.push_back(leg);
  }
}

const BezierPiece& LazyPiece::exact() const {
  asked_ = true;
  if (exact_) return *exact_;
  if (u0_ == root_->u0 && u1_ == root_->u1) return *root_;
  exact_ = root_->restrict_to(u0_, u1_);
  return *exact_;
}

std::pair<LazyPiece, LazyPiece> LazyPiece::halves() const {
  if (asked_) {  // the exact path ran here: halve exactly, as before
    auto h = exact().split(Rational(1, 2));
    std::pair<LazyPiece, LazyPiece> out{LazyPiece(root_, h.first.u0, h.first.u1),
                                        LazyPiece(root_, h.second.u0, h.second.u1)};
    out.first.exact_ = std::move(h.first);
    out.second.exact_ = std::move(h.second);
    for (LazyPiece* c : {&out.first, &out.second})
      if (!ctrl_.empty()) enclose_exact(c->exact_->control, c->ctrl_, c->legs_);
    return out;
  }
  const Rational um = (u0_ + u1_) / 2;
  std::pair<LazyPiece, LazyPiece> out{LazyPiece(root_, u0_, um), LazyPiece(root_, um, u1_)};
  if (ctrl_.empty()) return out;
  // De Casteljau at 1/2 on the enclosures.
  const std::size_t n = ctrl_.size();
  Enclosures pts = ctrl_;
  out.first.ctrl_.resize(n);
  out.second.ctrl_.resize(n);
  Protect guard;
  for (std::size_t level = 0; level < n; ++level) {
    out.first.ctrl_[level] = pts.front();
    out.second.ctrl_[n - 1 - level] = pts[n - 1 - level];
    for (std::size_t i = 0; i + 1 < n - level; ++i)
      pts[i] = {(pts[i].x + pts[i + 1].x) / 2, (pts[i].y + pts[i + 1].y) / 2};
  }
  // The legs by de Casteljau on the legs (the hodograph): with D⁰ the m
  // legs and Dʲ their level-j averages, the left half's leg j is Dʲ_0/2
  // and the right half's is D^{m−1−j}_j/2 (docs/theory.md §8).
  const std::size_t m = legs_.size();
  Enclosures d = legs_;
  out.first.legs_.resize(m);
  out.second.legs_.resize(m);
  for (std::size_t level = 0; level < m; ++level) {
    out.first.legs_[level] = {d.front().x / 2, d.front().y / 2};
    out.second.legs_[m - 1 - level] = {d[m - 1 - level].x / 2, d[m - 1 - level].y / 2};
    for (std::size_t i = 0; i + 1 < m - level; ++i) d[i] = {(d[i].x + d[i + 1].x) / 2, (d[i].y + d[i + 1].y) / 2};
  }
  return out;
}

int paper_cone_enclosure(const FVec2& ds, const FVec2& de, const LazyPiece::Enclosures& control,
                         const LazyPiece::Enclosures& legs, const Vec2& c, std::vector<FGen>& gens) {
  gens.clear();
  try {
    Protect guard;
    const FVec2 fc = to_interval(c);
    FVecs r;
    for (const FVec2& p : control) r.push_back(fsub(p, fc));
    FGens built;
    FVecs forces;
    if (!paper_cone(ds, de, r, legs, built, forces)) return 0;
    gens.assign(built.begin(), built.end());
    return 1;
  } catch (const Undecided&) {
    return kUndecided;
  }
}

Quick quick_segment(const LazyPiece::Enclosures& control, const LazyPiece::Enclosures& leg_enclosures, const Vec2& c,
                    const Rational& mu, const std::vector<EdgeFamily>& families, ConeMethod method,
                    IntervalTarget& target, std::optional<MagnitudeBounds>* bounds) {
  Cones cones;
  FVecs forces;
  try {
    {
      Protect guard;
      const FVec2 fc = to_interval(c);
      const FI fmu = to_interval(mu);
      FVecs P, r, legs;
      if (control.empty()) throw Undecided{};
      for (const auto& p : control) {
        P.push_back(p);
        r.push_back(fsub(P.back(), fc));
      }
      if (leg_enclosures.size() + 1 != control.size()) throw Undecided{};
      for (const FVec2& leg : leg_enclosures)
        if (!is_zero_f(leg)) legs.push_back(leg);
      if (legs.empty()) throw Undecided{};  // the exact path reports the degenerate segment
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
          if (!paper_cone(ds, de, r, leg_enclosures, cones.emplace_back(), forces)) return Quick::kPartial;
          continue;
        }
        forces.push_back(ds);
        if (!same) forces.push_back(de);     // equal vectors: no undecidable cross product below
        FGens& gens = cones.emplace_back();  // filled in place: no small_vector move
        // de = ds exactly (one leg): its two generators would repeat ds's,
        // the same cone, and make cross products no enclosure shows nonzero.
        for (const FVec2& d : {ds, de}) {
          if (same && gens.size() == 2) break;
          FI lo, hi;
          moment_range(r, d, lo, hi);
          gens.push_back({d.x, d.y, lo});
          gens.push_back({d.x, d.y, hi});
        }
      }
    }
    const Quick q = decide(cones, target, true);
    if (q != Quick::kIn || !bounds) return q;
  } catch (const Undecided&) {
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
  } catch (const Undecided&) {
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
    const Quick q = decide(cones, target, false);
    if (q != Quick::kIn || !bounds) return q;
  } catch (const Undecided&) {
    return Quick::kUnknown;
  }
  try {
    in_bounds(cones, first, last, target, bounds);
  } catch (const Undecided&) {
  }
  return Quick::kIn;
}

}  // namespace fixel::internal
